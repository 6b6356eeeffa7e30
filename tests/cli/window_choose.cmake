# A technique chosen in the window's panel (--choose scripts the click on the first frame) is
# applied one frame later: the frame of the choice carries a notice, because the technique's first
# frame builds and compiles its shaders (3-5 s on llvmpipe with Mesa's shader cache cold), and the
# log then gives that first frame's time.
include(${CMAKE_CURRENT_LIST_DIR}/helpers.cmake)
penumbra_in_xvfb(in_window 1024x768x24)
# One frame of the window with ARGN: it must carry a notice matching `notice` and draw nothing
# timed (the wait it announces comes in the next frame); its log stays in out_and_errors.
function(expect_notice_frame dir notice)
  run_penumbra("${dir}" out ${in_window} view ${ARGN} --exit-after 1)
  if(NOT out_and_errors MATCHES "${notice}")
    message(FATAL_ERROR "${dir}: no notice matching '${notice}'")
  endif()
  if(out_and_errors MATCHES "first frame [0-9]+ ms")
    message(FATAL_ERROR "${dir}: a first frame was drawn and timed in the frame of its notice")
  endif()
  expect_files("${dir}" screenshot_000.png)
  set(out_and_errors "${out_and_errors}" PARENT_SCOPE)
endfunction()
# A new window's first frame compiles its technique's shaders too: the frame before it says so
# over the cleared window, and the log then times that first frame.
expect_notice_frame("${OUT}/opening" "opening [^:\n]+: its first frame compiles its shaders")
run_penumbra("${OUT}/opened" out ${in_window} view --exit-after 2)
string(FIND "${out_and_errors}" "opening " notice_at)
string(REGEX MATCH "[^ \n]+: first frame [0-9]+ ms" timed "${out_and_errors}")
string(FIND "${out_and_errors}" "${timed}" timed_at)
if(notice_at EQUAL -1 OR NOT timed OR timed_at LESS notice_at)
  message(FATAL_ERROR "expected the opening notice, then the first frame's time")
endif()
expect_files("${OUT}/opened" screenshot_000.png)
file(SHA256 "${OUT}/opening/screenshot_000.png" notice_shot)
file(SHA256 "${OUT}/opened/screenshot_000.png" scene_shot)
if(notice_shot STREQUAL scene_shot)
  message(FATAL_ERROR "the scene's first frame looks exactly like its notice")
endif()
# The frame of the choice: the notice, not yet the switch. The choice replaces the opening notice:
# the chosen technique's build is the wait, the scene's own technique is never compiled.
expect_notice_frame("${OUT}/notice" "building pcf-poisson16: its first frame compiles its shaders" --choose pcf-poisson16)
if(out_and_errors MATCHES "opening ")
  message(FATAL_ERROR "a choice on the first frame left the opening notice beside its own")
endif()
# The next frame switches and times itself; the frames after draw on.
run_penumbra("${OUT}/switch" out ${in_window} view --choose pcf-poisson16 --exit-after 3)
string(FIND "${out_and_errors}" "building pcf-poisson16" notice_at)
string(FIND "${out_and_errors}" "pcf-poisson16: first frame " switch_at)
if(notice_at EQUAL -1 OR switch_at EQUAL -1 OR switch_at LESS notice_at)
  message(FATAL_ERROR "expected the notice, then the switch's first-frame time")
endif()
string(REGEX MATCHALL "first frame [0-9]+ ms" timings "${out_and_errors}")
list(LENGTH timings count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "${count} first frames timed, expected the chosen technique's alone")
endif()
string(REGEX MATCHALL "building pcf-poisson16" notices "${out_and_errors}")
list(LENGTH notices count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "the notice was given ${count} times, expected once")
endif()
expect_files("${OUT}/switch" screenshot_000.png)
