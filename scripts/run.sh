#!/usr/bin/env bash
# The README's first command: install, build, run penumbra on the built-in default scene.
# With a display it opens the window; without one it renders headless into ./out and prints
# per-pass GPU timings. Extra arguments go to penumbra (e.g. `scripts/run.sh render --frames 30`).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# Bare `penumbra` on a terminal with a display asks seed 002's menu; this command opens the
# default scene directly (stdin not a terminal: no menu; the window or, with no display, headless).
if [ $# -eq 0 ]; then exec ./build/penumbra </dev/null; fi
exec ./build/penumbra "$@"
