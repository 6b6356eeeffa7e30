# Installable: `cmake --install` into a temporary prefix, then the installed binary renders the
# default scene from another directory, with no environment variable, finding its data relative
# to itself (<prefix>/share/penumbra) rather than in the source tree.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/elsewhere")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${OUT}/prefix" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif()
foreach(f bin/penumbra share/penumbra/shaders/passes/lighting.frag share/penumbra/src/gpu/ShaderContract.h
          share/penumbra/src/shadows/cssm/lookup.glsl share/penumbra/src/shadows/pcf/PcfKernel.h share/penumbra/scenes/default.json)
  if(NOT EXISTS "${OUT}/prefix/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
# Every shader stage of the source tree, whatever its extension (a compute shader's .comp was
# left out of the install's patterns until 2026-12-03).
file(GLOB_RECURSE shaders RELATIVE "${SOURCE}" "${SOURCE}/src/*" "${SOURCE}/shaders/*")
list(FILTER shaders INCLUDE REGEX "\\.(glsl|vert|frag|geom|comp|tesc|tese)$")
list(LENGTH shaders count)
if(count LESS 50)
  message(FATAL_ERROR "found only ${count} shader files under ${SOURCE}")
endif()
foreach(f IN LISTS shaders)
  if(NOT EXISTS "${OUT}/prefix/share/penumbra/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY --unset=PENUMBRA_SHADER_DIR --unset=PENUMBRA_SCENE_DIR
          "${OUT}/prefix/bin/penumbra" render --frames 1 --size 96x64 --technique cssm2 --out run
  WORKING_DIRECTORY "${OUT}/elsewhere" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed penumbra failed (${rc}): ${out}${err}")
endif()
file(READ "${OUT}/elsewhere/run/stats.json" stats)
string(JSON dataDir GET "${stats}" data_dir)
file(REAL_PATH "${OUT}/prefix/share/penumbra" expected)
file(REAL_PATH "${dataDir}" got)
if(NOT got STREQUAL expected)
  message(FATAL_ERROR "the installed binary read its data from ${dataDir}, not ${expected}")
endif()
if(NOT EXISTS "${OUT}/elsewhere/run/frame_0000.png")
  message(FATAL_ERROR "no frame written")
endif()
