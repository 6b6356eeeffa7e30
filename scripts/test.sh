#!/usr/bin/env bash
# The README's second command (and what .ci/run calls): install, build, run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cd build
ctest --output-on-failure -j 2 --timeout 600
