# A technique chosen in the window's panel (--choose scripts the click on the first frame) is
# applied one frame later: the frame of the choice carries a notice, because the technique's first
# frame builds and compiles its shaders (3-5 s on llvmpipe with Mesa's shader cache cold), and the
# log then gives that first frame's time.
include(${CMAKE_CURRENT_LIST_DIR}/helpers.cmake)
penumbra_in_xvfb(in_window 1024x768x24)
# The frame of the choice: the notice, not yet the switch.
run_penumbra("${OUT}/notice" out ${in_window} view --choose pcf-poisson16 --exit-after 1)
if(NOT out_and_errors MATCHES "building pcf-poisson16: its first frame compiles its shaders")
  message(FATAL_ERROR "the frame of the choice did not announce the build")
endif()
if(out_and_errors MATCHES "first frame [0-9]+ ms")
  message(FATAL_ERROR "the technique was switched in the frame of the choice, before its notice was shown")
endif()
expect_files("${OUT}/notice" screenshot_000.png)
# The next frame switches and times itself; the frames after draw on.
run_penumbra("${OUT}/switch" out ${in_window} view --choose pcf-poisson16 --exit-after 3)
string(FIND "${out_and_errors}" "building pcf-poisson16" notice_at)
string(FIND "${out_and_errors}" "pcf-poisson16: first frame " switch_at)
if(notice_at EQUAL -1 OR switch_at EQUAL -1 OR switch_at LESS notice_at)
  message(FATAL_ERROR "expected the notice, then the switch's first-frame time")
endif()
string(REGEX MATCHALL "building pcf-poisson16" notices "${out_and_errors}")
list(LENGTH notices count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "the notice was given ${count} times, expected once")
endif()
expect_files("${OUT}/switch" screenshot_000.png)
