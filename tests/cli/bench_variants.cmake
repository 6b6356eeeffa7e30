# `penumbra bench --techniques` with a technique's own parameters: two variants of one technique
# are two cases, named with their parameters in bench.json and the round table, each drawn with
# its own values; a malformed variant and a parameter the technique lacks are errors.
include("${CMAKE_CURRENT_LIST_DIR}/helpers.cmake")
run_penumbra("${OUT}" out "${PENUMBRA}" bench "${DATA}/bench_tiny.json" --techniques vsm,vsm:blur_kernel=box:mipmaps=false
             --size 96x64 --frames 3 --warmup-seconds 0 --rounds 2 --no-images --out "${OUT}")
file(READ "${OUT}/bench.json" doc)
expect_json("${doc}" 4 LENGTH cases)  # 2 variants x 2 rounds
expect_json("${doc}" "vsm" cases 0 label)
expect_json("${doc}" "vsm blur_kernel=box mipmaps=false" cases 1 label)
expect_json("${doc}" "auto" cases 0 parameters blur_kernel)
expect_json("${doc}" "box" cases 1 parameters blur_kernel)
expect_json("${doc}" "false" cases 1 parameters mipmaps)
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
