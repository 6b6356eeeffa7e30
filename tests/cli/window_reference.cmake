# The window's reference mode (issue 13) under Xvfb: --reference traces the frame in the
# background while the window keeps drawing; --exit-after waits for it, so the screenshot shows
# the finished reference. With --heat-map it shows |technique - reference| instead: a different
# picture of the same frame.
include(${CMAKE_CURRENT_LIST_DIR}/helpers.cmake)
penumbra_in_xvfb(in_window 1024x768x24)
foreach(mode reference heat)
  set(flags --reference)
  if(mode STREQUAL "heat")
    list(APPEND flags --heat-map)
  endif()
  run_penumbra("${OUT}/${mode}" out ${in_window} view ${flags} --exit-after 2)
  if(NOT EXISTS "${OUT}/${mode}/screenshot_000.png")
    message(FATAL_ERROR "${mode}: no screenshot of the finished frame")
  endif()
  file(SHA256 "${OUT}/${mode}/screenshot_000.png" hash_${mode})
endforeach()
if(hash_reference STREQUAL hash_heat)
  message(FATAL_ERROR "the heat map looks exactly like the reference")
endif()
