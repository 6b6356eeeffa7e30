# The architecture, checked from the sources rather than by eye: which folder of src/ may
# include which, and that the CPU/GPU contract has one definition. Run by ctest with
# -DSRC=<source root>/src. Each rule names the offending file and line.
set(violations "")

# Reads every #include "..." of the files under `dir` (C++ and GLSL alike) into `out` as
# "file:line:included" entries.
function(collect_includes dir out)
  file(GLOB_RECURSE files "${SRC}/${dir}/*.h" "${SRC}/${dir}/*.cpp" "${SRC}/${dir}/*.glsl" "${SRC}/${dir}/*.frag"
       "${SRC}/${dir}/*.vert" "${SRC}/${dir}/*.geom")
  set(found "")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" lines)
    set(n 0)
    foreach(line IN LISTS lines)
      math(EXPR n "${n} + 1")
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\"")
        file(RELATIVE_PATH rel "${SRC}" "${f}")
        list(APPEND found "src/${rel}:${n}:${CMAKE_MATCH_1}")
      endif()
    endforeach()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# Fails every include of `dir` whose target matches `pattern` unless it matches `allowed`.
function(forbid dir pattern allowed why)
  collect_includes("${dir}" includes)
  foreach(entry IN LISTS includes)
    string(REGEX REPLACE "^.*:[0-9]+:" "" target "${entry}")
    if(target MATCHES "${pattern}" AND (allowed STREQUAL "" OR NOT target MATCHES "${allowed}"))
      string(REGEX REPLACE ":[^:]*$" "" where "${entry}")
      set(violations "${violations}\n  ${where}: includes \"${target}\": ${why}" PARENT_SCOPE)
    endif()
  endforeach()
endfunction()

forbid(shadows "(^|/)render/" "" "shadows/ must not reach into render/ (data flows one way)")
forbid(render "(^|/)shadows/" "^shadows/ShadowTechnique\\.h$" "render/ sees shadows/ only through ShadowTechnique.h")
foreach(core gl gpu platform scene shadows render reference)
  forbid(${core} "(^|/)bench/" "" "the bench measures the core; nothing in the core depends on it")
endforeach()
forbid(scene "(^|/)(gl|shadows|render|reference|app|gpu)/" "" "scene/ knows nothing of GL or shadows")
forbid(gl "(^|/)(scene|shadows|render|reference|app|gpu)/" "" "gl/ is a thin layer over GL objects only")
forbid(gpu "(^|/)(scene|shadows|render|reference|app|gl)/" "" "the shader contract depends on nothing")
foreach(core gl gpu platform scene shadows render reference util)
  forbid(${core} "(^|/)app/" "" "only the front-ends live in app/")
endforeach()

# One definition of every unit and limit: shaders and C++ outside src/gpu/ may use the
# contract's names but not define units, limits or light codes of their own.
file(GLOB_RECURSE sources "${SRC}/*.h" "${SRC}/*.cpp" "${SRC}/*.glsl" "${SRC}/*.frag" "${SRC}/*.vert" "${SRC}/*.geom"
     "${SRC}/../shaders/*.glsl" "${SRC}/../shaders/*.frag" "${SRC}/../shaders/*.vert")
foreach(f IN LISTS sources)
  if(f MATCHES "/src/gpu/")
    continue()
  endif()
  file(STRINGS "${f}" lines REGEX "(kUnit[A-Za-z0-9]+|kMax(Lights|Shadow2D|ShadowCube|Projectors)|kLight(Directional|Spot|Point|Projector))[ \t]*=|#define[ \t]+(UNIT_|MAX_LIGHTS|MAX_SHADOW|MAX_PROJECTORS|LIGHT_)|bindings\\.glsl")
  foreach(line IN LISTS lines)
    set(violations "${violations}\n  ${f}: '${line}': units, limits and light codes are defined in src/gpu/ShaderContract.h only")
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "architecture boundaries broken:${violations}")
endif()
message(STATUS "architecture boundaries hold")
