# The README's first command in its headless form: `penumbra` with no arguments and no display
# renders the built-in default scene into ./out and prints per-pass timings.
include("${CMAKE_CURRENT_LIST_DIR}/helpers.cmake")
run_penumbra("${OUT}" out ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY "${PENUMBRA}")
expect_files("${OUT}/out" frame_0000.png frame_0002.png stats.json)
file(READ "${OUT}/out/stats.json" stats)
string(JSON total GET "${stats}" mean_ms total)
string(JSON shadow GET "${stats}" mean_ms shadow)
string(JSON errors GET "${stats}" gl_errors)
string(JSON memory GET "${stats}" shadow_memory_bytes)
if(NOT total GREATER 0 OR NOT shadow GREATER 0 OR NOT memory GREATER 0)
  message(FATAL_ERROR "stats.json lacks timings or memory: total=${total} shadow=${shadow} memory=${memory}")
endif()
if(NOT errors EQUAL 0)
  message(FATAL_ERROR "GL errors during the default-scene run: ${errors}")
endif()
# glibc's malloc is tuned for llvmpipe by default (app/MallocTuning.h), and the run records it.
string(JSON mallocMode GET "${stats}" malloc mode)
string(JSON mmapThreshold GET "${stats}" malloc mallopt M_MMAP_THRESHOLD)
if(NOT mallocMode STREQUAL "tuned" OR NOT mmapThreshold EQUAL 33554432)
  message(FATAL_ERROR "stats.json: malloc mode '${mallocMode}', M_MMAP_THRESHOLD ${mmapThreshold}; expected the default 'tuned', 32 MiB")
endif()
# The green pane's coloured shadow falls on part of the ground: the ground is split, the far
# objects take the program without tint (render/TintReach.h).
string(JSON untinted GET "${stats}" frames 0 tint_shading untinted_draws)
string(JSON split GET "${stats}" frames 0 tint_shading split_draws)
string(JSON splitMs GET "${stats}" frames 0 tint_shading cpu_ms)
if(NOT untinted GREATER 0 OR NOT split GREATER 0 OR NOT splitMs GREATER 0)
  message(FATAL_ERROR "the default scene's opaque draws should be partly untinted and split, in measured CPU time: "
                      "untinted=${untinted} split=${split} cpu_ms=${splitMs}")
endif()
if(NOT out MATCHES "shadow [0-9.]+ \\| opaque")
  message(FATAL_ERROR "per-pass timings were not printed")
endif()

# Split view from the command line: the right side's technique and parameters reach a renderer of
# their own (the pixels themselves are SplitViewTest's), and a bad side is named.
# (Also glibc's malloc as configured, which the run records.)
run_penumbra("${OUT}" split "${PENUMBRA}" render --size 64x48 --frames 1 --split "cssm2:filter=box64" --split-at 0.25
             --malloc default --out "${OUT}/split")
file(READ "${OUT}/split/stats.json" stats)
string(JSON mallocMode GET "${stats}" malloc mode)
string(JSON tunedBy ERROR_VARIABLE notTuned GET "${stats}" malloc mallopt)
if(NOT mallocMode STREQUAL "default" OR NOT notTuned)
  message(FATAL_ERROR "--malloc default: stats.json's malloc mode '${mallocMode}', mallopt '${tunedBy}'; expected 'default', none")
endif()
string(JSON left GET "${stats}" split left)
string(JSON right GET "${stats}" split right)
string(JSON column GET "${stats}" split divider_column)
if(NOT left STREQUAL "hard" OR NOT right STREQUAL "cssm2" OR NOT column EQUAL 16)
  message(FATAL_ERROR "split view: left=${left} right=${right} divider=${column}, expected hard, cssm2, 16")
endif()
execute_process(COMMAND "${PENUMBRA}" render --size 64x48 --frames 1 --split nope --out "${OUT}/split_bad"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "--split: unknown shadow technique 'nope'; known: hard")
  message(FATAL_ERROR "a bad --split side must fail with a message naming it: rc=${rc} ${err}")
endif()
