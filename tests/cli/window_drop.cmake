# Seed 001's launch mode (issue 13) under Xvfb: a file dropped on the window loads. --drop sends
# the file through the window's drop handler on the first frame. A broken scene must leave the
# old scene drawing (the run goes on to its screenshot and exits 0) with the error named; a model
# must load.
include(${CMAKE_CURRENT_LIST_DIR}/helpers.cmake)
penumbra_in_xvfb(in_window 1024x768x24)
# Runs the window in `dir` with ARGN; `log` gets stdout and stderr together.
function(view_with dir log)
  run_penumbra("${dir}" out ${in_window} view ${ARGN} --exit-after 2)
  set(${log} "${out_and_errors}" PARENT_SCOPE)
endfunction()
view_with("${OUT}/broken" out --drop "${DATA}/malformed.json")
if(NOT out MATCHES "malformed.json:[0-9]+")
  message(FATAL_ERROR "the dropped broken scene's error does not name its file and line")
endif()
if(out MATCHES "loaded ")
  message(FATAL_ERROR "a broken scene was reported as loaded")
endif()
if(NOT EXISTS "${OUT}/broken/screenshot_000.png")
  message(FATAL_ERROR "the window did not go on drawing after a broken drop")
endif()
view_with("${OUT}/model" out --drop "${DATA}/materials.obj")
if(NOT out MATCHES "loaded [^\n]*materials.obj")
  message(FATAL_ERROR "the dropped model did not load")
endif()
