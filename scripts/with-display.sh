#!/usr/bin/env bash
# Runs a command with an X display for OpenGL: the real one when DISPLAY is set, else a private
# Xvfb (Mesa llvmpipe renders into pbuffers there).
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
