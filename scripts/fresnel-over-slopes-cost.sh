#!/usr/bin/env bash
# What averaging Fresnel over the slopes a pixel hides costs the lake's frame (the wind's waves):
# scripts/shader-cost.sh with owFresnelOverSlopes replaced by the reflectance of the pixel's normal
# alone. built / override is averaged ÷ the normal's.
#   usage: scripts/fresnel-over-slopes-cost.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
override="$(mktemp -d)"
trap 'rm -rf "$override"' EXIT
mkdir -p "$override/osgWater/shaders"
python3 - shaders/optics.glsl "$override/osgWater/shaders/optics.glsl" <<'PY'
import sys
s = open(sys.argv[1]).read()
i = s.index('float owFresnelOverSlopes(')
j = s.index('\n}\n', i) + 3
s = s[:i] + 'float owFresnelOverSlopes(float cosE, float roughness, float n1, float n2, float q)\n{\n    return owFresnel(cosE, n1, n2, q);\n}\n' + s[j:]
open(sys.argv[2], 'w').write(s)
PY
bash scripts/shader-cost.sh "$override" "${1:-3}"
