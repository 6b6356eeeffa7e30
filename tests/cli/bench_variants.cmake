# `penumbra bench --techniques` with a technique's own parameters: two variants of one technique
# are two cases, named with their parameters in bench.json and the round table, each drawn with
# its own values; a malformed variant and a parameter the technique lacks are errors.
include("${CMAKE_CURRENT_LIST_DIR}/helpers.cmake")
run_penumbra("${OUT}" out "${PENUMBRA}" bench "${DATA}/bench_tiny.json" --techniques vsm,vsm:blur_kernel=box:mipmaps=false
             --size 96x64 --frames 3 --warmup-seconds 0 --rounds 2 --no-images --out "${OUT}")
file(READ "${OUT}/bench.json" doc)
string(JSON count LENGTH "${doc}" cases)
if(NOT count EQUAL 4)
  message(FATAL_ERROR "bench.json: ${count} cases, expected 2 variants x 2 rounds = 4")
endif()
string(JSON label0 GET "${doc}" cases 0 label)
string(JSON label1 GET "${doc}" cases 1 label)
string(JSON kernel0 GET "${doc}" cases 0 parameters blur_kernel)
string(JSON kernel1 GET "${doc}" cases 1 parameters blur_kernel)
string(JSON mipmaps1 GET "${doc}" cases 1 parameters mipmaps)
if(NOT label0 STREQUAL "vsm" OR NOT label1 STREQUAL "vsm blur_kernel=box mipmaps=false")
  message(FATAL_ERROR "case labels '${label0}', '${label1}'; expected 'vsm' and 'vsm blur_kernel=box mipmaps=false'")
endif()
if(NOT kernel0 STREQUAL "gaussian" OR NOT kernel1 STREQUAL "box" OR NOT mipmaps1 STREQUAL "false")
  message(FATAL_ERROR "parameters drawn with: ${kernel0} / ${kernel1}, mipmaps ${mipmaps1}; expected gaussian / box, false")
endif()
if(NOT out MATCHES "vsm blur_kernel=box mipmaps=fa[^\n]*x vsm")
  message(FATAL_ERROR "the round table has no ratio of the box variant to vsm:\n${out}")
endif()

foreach(bad "vsm:blur_kernel" "vsm:nope=1")
  execute_process(COMMAND "${PENUMBRA}" bench "${DATA}/bench_tiny.json" --techniques "${bad}" --frames 1 --no-images
                          --out "${OUT}/bad" RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(rc EQUAL 0 OR NOT "${o}${e}" MATCHES "(expected name:parameter=value|has no parameter 'nope')")
    message(FATAL_ERROR "--techniques ${bad}: exit ${rc}, expected an error naming the problem:\n${o}${e}")
  endif()
endforeach()
