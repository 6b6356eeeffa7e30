#!/usr/bin/env bash
# The README's second command (and what .ci/run calls): install, build, run every test.
#   scripts/test.sh              the suite on the normal build (./build)
#   scripts/test.sh --sanitize   the same suite built with AddressSanitizer + UBSan (./build-sanitize)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  scripts/setup.sh --sanitize
  # Leak checking stays on, with no suppressions. EGL dlopens Mesa's driver and unloads it at
  # exit, before LeakSanitizer looks: the driver's still-referenced globals then read as leaks
  # with no module name. Preloading the driver (after the ASan runtime, which must come first)
  # keeps it mapped to the end, and nothing leaks. Any UBSan report aborts its test.
  driver=$(find /usr/lib -name swrast_dri.so -print -quit 2>/dev/null || true)
  export LD_PRELOAD="$(gcc -print-file-name=libasan.so)${driver:+ $driver}"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  # Tests that start third-party programs (xvfb-run, chromium) or clang-built fuzzers keep the
  # preload away from them (tests/cli/helpers.cmake); the soak skips its memory bounds.
  export PENUMBRA_SANITIZED=1
  cd build-sanitize
  ctest --output-on-failure -j 2 --timeout 1200
  exit 0
fi
scripts/setup.sh
cd build
ctest --output-on-failure -j 2 --timeout 600
