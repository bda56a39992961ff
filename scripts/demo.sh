#!/usr/bin/env bash
# Installs dependencies, builds, and runs the lake demo: in a window when a display exists,
# otherwise headless (off-screen), writing a screenshot and printing the median frame time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
if [ -n "${DISPLAY:-}" ]; then
  ./build/apps/osgwaterlake/osgwaterlake --screenshot osgwaterlake.png "$@"
else
  bash scripts/with-display.sh ./build/apps/osgwaterlake/osgwaterlake --headless --screenshot osgwaterlake.png "$@"
fi
