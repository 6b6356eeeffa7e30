# `penumbra bench` end to end on a tiny scene: bench.json has every field with sane values
# (times > 0, memory equal to the texel bytes of the maps, FPS consistent with frame times),
# bench.csv has a row per case, and report.html, opened in headless Chromium, has painted charts,
# decoded images with the case names under them, and no console errors.
include("${CMAKE_CURRENT_LIST_DIR}/helpers.cmake")
run_penumbra("${OUT}" out "${PENUMBRA}" bench "${DATA}/bench_tiny.json" --techniques hard,none,floor-depth
             --shadow-res 256,512 --size 96x64 --frames 4 --warmup-seconds 0 --calibrate --out "${OUT}")
expect_files("${OUT}" bench.json bench.csv report.html)

file(READ "${OUT}/bench.json" doc)
foreach(key format created git_revision device egl_platform malloc clocks settings cases)
  string(JSON value ERROR_VARIABLE missing GET "${doc}" ${key})
  if(missing)
    message(FATAL_ERROR "bench.json lacks '${key}'")
  endif()
endforeach()
string(JSON mode GET "${doc}" malloc mode)
if(NOT mode STREQUAL "tuned")
  message(FATAL_ERROR "bench.json: malloc mode '${mode}', expected the default 'tuned'")
endif()
string(JSON count LENGTH "${doc}" cases)
if(NOT count EQUAL 6)
  message(FATAL_ERROR "bench.json: ${count} cases, expected 3 techniques x 2 resolutions = 6")
endif()

# A decimal as an integer number of thousandths (CMake's maths is integer only).
function(thousandths text out)
  if(NOT text MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "not a plain decimal: ${text}")
  endif()
  set(fraction "${CMAKE_MATCH_3}000")
  string(SUBSTRING "${fraction}" 0 3 fraction)
  math(EXPR value "${CMAKE_MATCH_1} * 1000 + 1${fraction} - 1000")
  set(${out} ${value} PARENT_SCOPE)
endfunction()

# CPU ms per frame (cpu_frame_ms): one sample per counted frame, in the order of the wall intervals.
# A frame's calls return before the next frame starts (or, for the last, before the glFinish that
# ends its interval): each sample is above 0 and at most its frame's wall interval. A CPU clock
# taken over the wrong span (the pacer's wait, or past the next start) or given to the wrong
# frames fails here.
function(check_cpu_samples doc i what)
  string(JSON cpuCount GET "${doc}" cases ${i} cpu_frame_ms count)
  string(JSON cpuSamples LENGTH "${doc}" cases ${i} samples cpu_frame_ms)
  string(JSON wallSamples LENGTH "${doc}" cases ${i} samples frame_ms)
  if(NOT cpuCount EQUAL wallSamples OR NOT cpuSamples EQUAL wallSamples)
    message(FATAL_ERROR "${what}: cpu_frame_ms counts ${cpuCount} and ${cpuSamples} samples against ${wallSamples} frame times")
  endif()
  math(EXPR lastSample "${wallSamples} - 1")
  foreach(k RANGE ${lastSample})
    string(JSON cpu GET "${doc}" cases ${i} samples cpu_frame_ms ${k})
    string(JSON wall GET "${doc}" cases ${i} samples frame_ms ${k})
    thousandths("${cpu}" c)
    thousandths("${wall}" w)
    if(NOT c GREATER 0 OR c GREATER w)
      message(FATAL_ERROR "${what}: frame ${k} took ${cpu} ms of CPU in a ${wall} ms interval; expected 0 < CPU <= interval")
    endif()
  endforeach()
endfunction()

math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON technique GET "${doc}" cases ${i} technique)
  string(JSON res GET "${doc}" cases ${i} shadow_resolution)
  string(JSON frames GET "${doc}" cases ${i} frame_ms count)
  string(JSON frameMean GET "${doc}" cases ${i} frame_ms mean)
  string(JSON fpsMean GET "${doc}" cases ${i} fps mean)
  string(JSON gpu GET "${doc}" cases ${i} gpu_frame_ms median)
  string(JSON memory GET "${doc}" cases ${i} shadow_memory_bytes)
  string(JSON errors GET "${doc}" cases ${i} gl_errors)
  string(JSON samples LENGTH "${doc}" cases ${i} samples frame_ms)
  string(JSON shadowSamples LENGTH "${doc}" cases ${i} samples pass_gpu_ms shadow)
  string(JSON query GET "${doc}" cases ${i} calibration shadow query_ms)
  string(JSON wall GET "${doc}" cases ${i} calibration shadow wall_ms)
  string(JSON flagged GET "${doc}" cases ${i} calibration shadow flagged)
  string(JSON image GET "${doc}" cases ${i} image)
  set(what "case ${i} (${technique} ${res})")
  if(NOT frames EQUAL 4 OR NOT samples EQUAL 4 OR NOT shadowSamples EQUAL 4)
    message(FATAL_ERROR "${what}: ${frames} frame times, ${samples} frame samples, ${shadowSamples} shadow samples; expected 4 each")
  endif()
  check_cpu_samples("${doc}" ${i} "${what}")
  if(NOT frameMean GREATER 0 OR NOT gpu GREATER 0)
    message(FATAL_ERROR "${what}: frame ${frameMean} ms, GPU ${gpu} ms: both must be > 0")
  endif()
  # FPS mean x mean frame ms = 1000 (within 1 %, the rounding to thousandths included).
  thousandths("${fpsMean}" f)
  thousandths("${frameMean}" m)
  math(EXPR product "${f} * ${m}")
  if(product LESS 990000000 OR product GREATER 1010000000)
    message(FATAL_ERROR "${what}: FPS ${fpsMean} does not match the mean frame time ${frameMean} ms")
  endif()
  # Memory: the texel bytes of the maps. hard: one spot light, DEPTH32F + RGBA16F tint + RG32F
  # drawn alpha at res^2 (the scene has a translucent caster); none: nothing; floor-depth: one
  # DEPTH32F map.
  if(technique STREQUAL "hard")
    math(EXPR expected "${res} * ${res} * (4 + 8 + 8)")
  elseif(technique STREQUAL "none")
    set(expected 0)
  else()
    math(EXPR expected "${res} * ${res} * 4")
  endif()
  if(NOT memory EQUAL expected)
    message(FATAL_ERROR "${what}: shadow_memory_bytes ${memory}, expected the texel bytes ${expected}")
  endif()
  if(NOT errors EQUAL 0)
    message(FATAL_ERROR "${what}: ${errors} GL errors")
  endif()
  # With calibration, the passes' parts by path (render/SubPassClock.h): the renderer's.
  if(technique STREQUAL "hard")
    foreach(path "shadow maps" "shadow maps/shadow map: spot" "opaque")
      string(JSON t ERROR_VARIABLE missing GET "${doc}" cases ${i} sub_pass_wall_ms "${path}")
      if(missing)
        message(FATAL_ERROR "${what}: sub_pass_wall_ms lacks '${path}'")
      endif()
    endforeach()
  endif()
  if(NOT EXISTS "${OUT}/${image}")
    message(FATAL_ERROR "${what}: image ${image} missing")
  endif()
endforeach()

file(STRINGS "${OUT}/bench.csv" rows)
list(LENGTH rows rowCount)
if(NOT rowCount EQUAL 7)
  message(FATAL_ERROR "bench.csv: ${rowCount} lines, expected a header and 6 rows")
endif()

# A report page in headless Chromium: a harness page loads it in a frame and reports what it
# finds (JSON: canvases, painted, images, decoded, tables, captions, headings).
find_program(CHROMIUM NAMES chromium chromium-browser REQUIRED)
function(check_report page out_var)
  execute_process(
    COMMAND ${WITHOUT_PRELOAD} timeout 120 "${CHROMIUM}" --headless --no-sandbox --disable-gpu --allow-file-access-from-files
            --enable-logging=stderr --v=0 --virtual-time-budget=20000 --dump-dom
            "file://${CMAKE_CURRENT_LIST_DIR}/report_check.html?report=file://${page}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE dom ERROR_VARIABLE log)
  if(NOT rc EQUAL 0 OR NOT dom MATCHES "RESULT ({[^<]*})")
    message(FATAL_ERROR "headless Chromium did not report on ${page} (exit ${rc}):\n${dom}\n${log}")
  endif()
  set(result "${CMAKE_MATCH_1}")
  string(REPLACE "&quot;" "\"" result "${result}")
  message("${page} in Chromium: ${result}")
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()
check_report("${OUT}/report.html" result)
string(JSON canvases GET "${result}" canvases)
string(JSON painted GET "${result}" painted)
string(JSON images GET "${result}" images)
string(JSON decoded GET "${result}" decoded)
string(JSON tables GET "${result}" tables)
if(NOT canvases EQUAL 4 OR NOT painted EQUAL 4)
  message(FATAL_ERROR "report.html: ${painted} of ${canvases} charts painted, expected 4 of 4")
endif()
if(NOT images EQUAL 6 OR NOT decoded EQUAL 6)
  message(FATAL_ERROR "report.html: ${decoded} of ${images} images decoded, expected 6 of 6")
endif()
if(tables LESS 1)
  message(FATAL_ERROR "report.html has no table")
endif()
foreach(name "hard 256" "none 512" "floor-depth 512")
  string(FIND "${result}" "\"${name}\"" at)
  if(at LESS 0)
    message(FATAL_ERROR "report.html: no image captioned '${name}'")
  endif()
endforeach()
# Console errors (uncaught exceptions, console.error) of the report page, as Chromium logs them.
string(REGEX MATCHALL "CONSOLE[^\n]*report\\.html[^\n]*" consoleErrors "${log}")
if(consoleErrors)
  message(FATAL_ERROR "report.html logged to the console:\n${consoleErrors}")
endif()
# A screenshot to look at (not asserted on).
execute_process(COMMAND ${WITHOUT_PRELOAD} timeout 120 "${CHROMIUM}" --headless --no-sandbox --disable-gpu --window-size=1400,2200
                        "--screenshot=${OUT}/report_screenshot.png" "file://${OUT}/report.html"
                OUTPUT_QUIET ERROR_QUIET)

# Across scenes: the same technique on three generated grids gets a least-squares line of shadow
# pass against triangles drawn, in bench.json and on stdout; `none` and the unshadowed floor draw
# no map and get none.
run_penumbra("${OUT}/scaling" scaling "${PENUMBRA}" bench --grid-scene 1000 --grid-scene 20000 --grid-scene 60000
             --techniques hard,none,floor-unshadowed --redraw-shadow-maps --size 64x48 --frames 3 --warmup-seconds 0 --no-images
             --out "${OUT}/scaling")
file(READ "${OUT}/scaling/bench.json" doc)
string(JSON fits LENGTH "${doc}" shadow_pass_scaling)
string(JSON label GET "${doc}" shadow_pass_scaling 0 label)
string(JSON points LENGTH "${doc}" shadow_pass_scaling 0 points)
if(NOT fits EQUAL 1 OR NOT label STREQUAL "hard" OR NOT points EQUAL 3)
  message(FATAL_ERROR "bench.json: ${fits} scaling fit(s), the first '${label}' over ${points} scenes; expected one, hard's, over 3")
endif()
foreach(i 0 1 2)
  math(EXPR caseIndex "3 * ${i}")  # hard, none, floor-unshadowed per scene
  string(JSON drawn GET "${doc}" cases ${caseIndex} shadow_triangles_per_frame)
  string(JSON fitted GET "${doc}" shadow_pass_scaling 0 points ${i} triangles)
  if(NOT drawn EQUAL fitted OR drawn LESS 1000)
    message(FATAL_ERROR "scaling point ${i}: ${fitted} triangles, the case drew ${drawn}")
  endif()
  # The unshadowed floor: a camera pass only, no map, no triangles into one.
  math(EXPR caseIndex "3 * ${i} + 2")
  string(JSON technique GET "${doc}" cases ${caseIndex} technique)
  string(JSON memory GET "${doc}" cases ${caseIndex} shadow_memory_bytes)
  string(JSON drawn GET "${doc}" cases ${caseIndex} shadow_triangles_per_frame)
  string(JSON opaque GET "${doc}" cases ${caseIndex} pass_gpu_ms opaque median)
  if(NOT technique STREQUAL "floor-unshadowed" OR NOT memory EQUAL 0 OR NOT drawn EQUAL 0 OR NOT opaque GREATER 0)
    message(FATAL_ERROR "case ${caseIndex} (${technique}): ${memory} map bytes, ${drawn} triangles into maps, camera pass ${opaque} ms; "
                        "expected floor-unshadowed with 0, 0 and > 0")
  endif()
endforeach()
string(JSON r2 GET "${doc}" shadow_pass_scaling 0 r2)
if(r2 LESS 0 OR r2 GREATER 1)
  message(FATAL_ERROR "scaling fit: R² ${r2} outside [0, 1]")
endif()
# The floor beside them: none's frame against floor-unshadowed's on each scene.
# (hard had no floor-lambert or floor-depth beside it: no row.)
string(JSON ratios LENGTH "${doc}" floor_ratios)
if(NOT ratios EQUAL 3)
  message(FATAL_ERROR "bench.json: ${ratios} floor ratios, expected one per scene, for none")
endif()
string(JSON floorLabel GET "${doc}" floor_ratios 0 label)
string(JSON floorName GET "${doc}" floor_ratios 0 frame_floor)
string(JSON floorRatio GET "${doc}" floor_ratios 0 frame_ratio)
if(NOT floorLabel STREQUAL "none" OR NOT floorName STREQUAL "floor-unshadowed" OR NOT floorRatio GREATER 0)
  message(FATAL_ERROR "floor ratio 0: ${floorLabel} against '${floorName}' = ${floorRatio}; expected none against floor-unshadowed, > 0")
endif()
if(NOT scaling MATCHES "shadow pass against triangles drawn[^\n]*\n +hard +[0-9.-]+ ms \\+ +[0-9.-]+ ms per million triangles +R² ")
  message(FATAL_ERROR "stdout lacks hard's scaling line")
endif()

# --rounds: the case list measured three times in turn; each case's median frame against its
# scene's first case, per round, with the median over the rounds (bench::roundRatios). Only the
# first round draws pictures.
run_penumbra("${OUT}/rounds" rounds "${PENUMBRA}" bench "${DATA}/bench_tiny.json" --techniques none,hard --rounds 3
             --size 96x64 --frames 3 --warmup-seconds 0 --out "${OUT}/rounds")
file(READ "${OUT}/rounds/bench.json" doc)
string(JSON count LENGTH "${doc}" cases)
string(JSON lastRound GET "${doc}" cases 5 round)
string(JSON lastTechnique GET "${doc}" cases 5 technique)
string(JSON lastImage GET "${doc}" cases 5 image)
if(NOT count EQUAL 6 OR NOT lastRound EQUAL 2 OR NOT lastTechnique STREQUAL "hard" OR NOT lastImage MATCHES "^(null)?$")
  message(FATAL_ERROR "--rounds 3: ${count} cases, the last of round ${lastRound} (${lastTechnique}, image ${lastImage}); "
                      "expected 6, round 2, hard, no image")
endif()
string(JSON rows LENGTH "${doc}" rounds)
string(JSON base GET "${doc}" rounds 1 base)
string(JSON perRound LENGTH "${doc}" rounds 1 ratio_to_base_per_round)
string(JSON noneRatio GET "${doc}" rounds 0 ratio_to_base_median)
thousandths("${noneRatio}" noneThousandths)
if(NOT rows EQUAL 2 OR NOT base STREQUAL "none" OR NOT perRound EQUAL 3 OR NOT noneThousandths EQUAL 1000)
  message(FATAL_ERROR "--rounds 3: ${rows} rows, hard's base '${base}' with ${perRound} ratios, none's own ratio ${noneRatio}; "
                      "expected 2 rows, none, 3, 1")
endif()
# hard's median ratio is the middle one of its three rounds' (and each is its frame ÷ none's).
set(ratios "")
foreach(k 0 1 2)
  string(JSON ratio GET "${doc}" rounds 1 ratio_to_base_per_round ${k})
  thousandths("${ratio}" t)
  list(APPEND ratios ${t})
endforeach()
list(SORT ratios COMPARE NATURAL)
list(GET ratios 1 middle)
string(JSON medianRatio GET "${doc}" rounds 1 ratio_to_base_median)
thousandths("${medianRatio}" m)
if(NOT m EQUAL middle OR m LESS 1)
  message(FATAL_ERROR "--rounds 3: hard's median ratio ${medianRatio}, rounds' ${ratios} (thousandths); expected the middle one, > 0")
endif()
# Three rounds are too few to bound the median at 95 % (bench::medianInterval): no interval.
string(JSON intervalType TYPE "${doc}" rounds 1 ratio_to_base_median_interval)
if(NOT intervalType STREQUAL "NULL")
  message(FATAL_ERROR "--rounds 3: hard's median interval is ${intervalType}, expected null (too few rounds)")
endif()
if(NOT rounds MATCHES "in rounds [^\n]*\n +none +@bench_tiny +[0-9.]+ ms +1\\.000x none +\\[1\\.000 1\\.000 1\\.000\\]\n +hard ")
  message(FATAL_ERROR "stdout lacks the rounds' table")
endif()
check_report("${OUT}/rounds/report.html" result)
string(JSON images GET "${result}" images)
string(FIND "${result}" "\"In rounds" at)
if(NOT images EQUAL 2 OR at LESS 0)
  message(FATAL_ERROR "rounds' report.html: ${images} images, expected 2 (round 1's); a table headed 'In rounds' expected")
endif()

# Scene time starts from 0 at each case's first measured frame (--scene-step seconds per frame), so
# every case measures the same frames whatever its warm-up took. A sphere in the spot's view until
# t = 0.9 s, far off after 1 s; two warm-up frames (--warmup-seconds 0) at 0.5 s a frame: measured
# at t = 0 and 0.5, the sphere is drawn into the map every frame (measured after the warm-up's
# scene time, at 1 and 1.5 s, never).
file(MAKE_DIRECTORY "${OUT}")
file(WRITE "${OUT}/leaving.json" [=[{
  "camera": { "position": [0, 4, 6], "target": [0, 0, 0], "fov_deg": 50 },
  "lights": [ { "type": "spot", "position": [1, 6, 1], "direction": [-0.15, -1, -0.15], "angle_deg": 70,
                "shadow": { "resolution": 256 } } ],
  "objects": [ { "shape": "plane", "size": [10, 10] },
               { "name": "sphere", "shape": "sphere", "radius": 0.5,
                 "animation": [[0, 0, 1, 0], [0.9, 0, 1, 0], [1, 60, 1, 0], [3, 60, 1, 0]] } ] }]=])
foreach(step 0.5 0.0001)
  run_penumbra("${OUT}/scene-time-${step}" out "${PENUMBRA}" bench "${OUT}/leaving.json" --techniques hard --size 96x64
               --frames 2 --warmup-seconds 0 --scene-step ${step} --no-images --out "${OUT}/scene-time-${step}")
  file(READ "${OUT}/scene-time-${step}/bench.json" doc)
  string(JSON recorded GET "${doc}" settings scene_step_seconds)
  string(JSON triangles GET "${doc}" cases 0 shadow_triangles_per_frame)
  set(triangles_${step} ${triangles})
  if(step STREQUAL "0.5" AND NOT recorded STREQUAL "0.5")
    message(FATAL_ERROR "--scene-step 0.5: bench.json's settings record ${recorded}")
  endif()
endforeach()
# Nearly still (0.1 ms a frame) the sphere is drawn in every frame too: the same triangles.
if(NOT triangles_0.5 EQUAL triangles_0.0001 OR NOT triangles_0.5 GREATER 100)
  message(FATAL_ERROR "--scene-step 0.5: ${triangles_0.5} triangles per frame into the map, nearly still: ${triangles_0.0001}; "
                      "expected the same, with the sphere's (> 100)")
endif()

# A measured frame that links a program pays for its compile (hundreds of ms on llvmpipe with a
# cold shader cache), so the bench measures again over the same frames. The default scene orbited
# at 1 s a frame reaches views whose lighting builds (the lights each pixel needs, render/
# LightingProgram.h) its two warm-up frames at t = 0 and 1 s did not need: the first try links
# some, the kept one none, and the table says so. The same case without repeats would have kept
# those compiles in its frame times.
run_penumbra("${OUT}/repeat" repeat "${PENUMBRA}" bench --techniques hard --size 160x90 --frames 20 --warmup-seconds 0
             --scene-step 1 --no-images --out "${OUT}/repeat")
file(READ "${OUT}/repeat/bench.json" doc)
string(JSON repeated GET "${doc}" cases 0 measurement repeated)
string(JSON linked GET "${doc}" cases 0 measurement programs_linked)
string(JSON measuredFrames GET "${doc}" cases 0 frame_ms count)
if(repeated LESS 1 OR NOT linked EQUAL 0 OR NOT measuredFrames EQUAL 20)
  message(FATAL_ERROR "orbit at 1 s a frame: measured again ${repeated} time(s), the kept try linked ${linked} program(s) over "
                      "${measuredFrames} frames; expected at least 1 repeat, 0 programs, 20 frames")
endif()
if(NOT repeat MATCHES "measured [23] times: the earlier tries compiled shaders")
  message(FATAL_ERROR "stdout does not say the case was measured again:\n${repeat}")
endif()

# --interleave N: the cases of a scene measured together, in turns of N frames each, so that a
# machine whose speed swings slows them alike. A turn's first two frames share the pipeline (two
# frames in flight) with the case before and its last frame's interval ends at the next case's
# start: neither is counted. On the leaving sphere's scene at 0.5 s a frame, turns of 5 count each
# case's scene frames 2 and 3 (t = 1 and 1.5 s: the sphere is gone): no sphere in the map in a
# counted frame, where counting a turn's first frames (t = 0, 0.5 s) would draw it.
# Each case keeps its own scene time (both measure the same frames), and every counted frame has
# its wall interval and its GPU times.
run_penumbra("${OUT}/interleave" interleave "${PENUMBRA}" bench "${OUT}/leaving.json" --techniques hard,pcf-poisson16
             --interleave 5 --rounds 2 --size 96x64 --frames 2 --warmup-seconds 0 --scene-step 0.5 --no-images
             --out "${OUT}/interleave")
file(READ "${OUT}/interleave/bench.json" doc)
string(JSON recorded GET "${doc}" settings interleave_frames)
string(JSON count LENGTH "${doc}" cases)
if(NOT recorded EQUAL 5 OR NOT count EQUAL 4)
  message(FATAL_ERROR "--interleave 5 --rounds 2: settings record ${recorded}, ${count} cases; expected 5 and 4")
endif()
foreach(i 0 1 2 3)
  string(JSON technique GET "${doc}" cases ${i} technique)
  string(JSON turn GET "${doc}" cases ${i} measurement interleave_frames)
  string(JSON frames GET "${doc}" cases ${i} frame_ms count)
  string(JSON shadowSamples LENGTH "${doc}" cases ${i} samples pass_gpu_ms shadow)
  string(JSON opaqueSamples LENGTH "${doc}" cases ${i} samples pass_gpu_ms opaque)
  string(JSON triangles GET "${doc}" cases ${i} shadow_triangles_per_frame)
  string(JSON errors GET "${doc}" cases ${i} gl_errors)
  if(NOT turn EQUAL 5 OR NOT frames EQUAL 2 OR NOT shadowSamples EQUAL 2 OR NOT opaqueSamples EQUAL 2 OR NOT errors EQUAL 0)
    message(FATAL_ERROR "--interleave 5, case ${i} (${technique}): turns of ${turn}, ${frames} frame times, ${shadowSamples} shadow and "
                        "${opaqueSamples} opaque GPU samples, ${errors} GL errors; expected 5, 2, 2, 2, 0")
  endif()
  check_cpu_samples("${doc}" ${i} "--interleave 5, case ${i} (${technique})")
  # The plane alone in the map: 2 triangles (the sphere's hundreds would show in the mean).
  if(triangles GREATER 10)
    message(FATAL_ERROR "--interleave 5, case ${i} (${technique}): ${triangles} triangles per frame into the map; the sphere was "
                        "drawn in a counted frame (a turn's first frames counted, or scene time shared between cases)")
  endif()
endforeach()
string(JSON rows LENGTH "${doc}" rounds)
if(NOT rows EQUAL 2)
  message(FATAL_ERROR "--interleave 5 --rounds 2: ${rows} rows of round ratios, expected 2")
endif()
if(NOT interleave MATCHES "each scene's cases measured together, in turns of 5 frames each")
  message(FATAL_ERROR "stdout does not say the cases were interleaved:\n${interleave}")
endif()
