# Shared by the CLI test scripts.

# Runs penumbra with ARGN in `dir` (created empty), prints its output, fails on a non-zero exit;
# its stdout lands in `out_var`, stdout and stderr together in `<out_var>_and_errors`.
function(run_penumbra dir out_var)
  file(REMOVE_RECURSE "${dir}")
  file(MAKE_DIRECTORY "${dir}")
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "penumbra exited with ${rc}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${out_var}_and_errors "${out}${err}" PARENT_SCOPE)  # stdout, then stderr (log lines)
endfunction()

# Fails naming the first of ARGN (paths relative to `dir`) that does not exist.
function(expect_files dir)
  foreach(f IN LISTS ARGN)
    if(NOT EXISTS "${dir}/${f}")
      message(FATAL_ERROR "missing ${dir}/${f}")
    endif()
  endforeach()
endfunction()

# The command that runs penumbra in a window under Xvfb: xvfb-run -a -s "-screen 0 SCREEN" penumbra.
# Under scripts/test.sh --sanitize, LD_PRELOAD (gcc's ASan runtime and Mesa's driver) is meant for
# penumbra alone: xvfb-run's helpers (xauth, Xvfb) are not instrumented and abort under it.
function(penumbra_in_xvfb out_var screen)
  find_program(XVFB_RUN xvfb-run REQUIRED)
  if(NOT "$ENV{LD_PRELOAD}" STREQUAL "")
    set(${out_var} env -u LD_PRELOAD "${XVFB_RUN}" -a -s "-screen 0 ${screen}" env "LD_PRELOAD=$ENV{LD_PRELOAD}" "${PENUMBRA}"
        PARENT_SCOPE)
  else()
    set(${out_var} "${XVFB_RUN}" -a -s "-screen 0 ${screen}" "${PENUMBRA}" PARENT_SCOPE)
  endif()
endfunction()

# A third-party program (chromium, ...) without the sanitizer preload (see penumbra_in_xvfb).
set(WITHOUT_PRELOAD env -u LD_PRELOAD)

# Fails unless the JSON value at path ARGN in `doc` reads `expected` (a count for a LENGTH path:
# give "LENGTH" as the first path element).
function(expect_json doc expected)
  if(ARGV2 STREQUAL "LENGTH")
    list(REMOVE_AT ARGN 0)
    string(JSON value LENGTH "${doc}" ${ARGN})
  else()
    string(JSON value GET "${doc}" ${ARGN})
  endif()
  if(NOT value STREQUAL expected)
    list(JOIN ARGN " " path)
    message(FATAL_ERROR "JSON ${path}: '${value}', expected '${expected}'")
  endif()
endfunction()
