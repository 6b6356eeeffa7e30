# The window under Xvfb takes a storm (issue 12): every frame it is minimised, restored, resized
# to 1x1, to 8192x8192 and back to 800x600, and the technique changes; after 7 drawn frames (each
# step once, one of them at 8192x8192) it
# must exit cleanly and leave its last frame as a screenshot.
include(${CMAKE_CURRENT_LIST_DIR}/helpers.cmake)
penumbra_in_xvfb(in_window 1280x1024x24)
run_penumbra("${OUT}" out ${in_window} view --storm --exit-after 7)
file(GLOB shots "${OUT}/*.png")
if(NOT shots)
  message(FATAL_ERROR "the storm left no screenshot of its last frame")
endif()
