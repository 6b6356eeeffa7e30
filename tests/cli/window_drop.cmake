# Seed 001's launch mode (issue 13) under Xvfb: a file dropped on the window loads. --drop sends
# the file through the window's drop handler on the first frame. A broken scene must leave the
# old scene drawing (the run goes on to its screenshot and exits 0) with the error named; a model
# must load.
find_program(XVFB_RUN xvfb-run REQUIRED)
# Runs the window in `dir` with ARGN, stdout and stderr together in `log`; it must exit 0.
function(view_with dir log)
  file(REMOVE_RECURSE "${dir}")
  file(MAKE_DIRECTORY "${dir}")
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1024x768x24" "${PENUMBRA}" view ${ARGN} --exit-after 2
                  WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the window exited with ${rc}")
  endif()
  set(${log} "${out}" PARENT_SCOPE)
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
