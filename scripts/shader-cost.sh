#!/usr/bin/env bash
# What a shader's choice costs the lake's frame: scripts/paired-cost.sh with the kit as built (A)
# against the shader files of OVERRIDE_DIR in front of the embedded ones (B:
# OVERRIDE_DIR/osgWater/shaders/*.glsl on OSG_FILE_PATH). A / B is built ÷ override.
#   usage: scripts/shader-cost.sh OVERRIDE_DIR [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
override="$(cd "$1" && pwd)"
[ -d "$override/osgWater/shaders" ] || { echo "shader-cost: no osgWater/shaders under $override" >&2; exit 2; }
bash scripts/paired-cost.sh "${2:-3}" "" "--shaders $override"
