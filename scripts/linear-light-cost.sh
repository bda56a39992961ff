#!/usr/bin/env bash
# What summing light in linear units costs the lake's frame: scripts/shader-cost.sh with every sum
# made on display values as before (the kit's sRGB decode and encode replaced by the identity in
# srgb.glsl). built / override is linear ÷ display.
#   usage: scripts/linear-light-cost.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
override="$(mktemp -d)"
trap 'rm -rf "$override"' EXIT
mkdir -p "$override/osgWater/shaders"
cat > "$override/osgWater/shaders/srgb.glsl" <<'GLSL'
uniform float osgWater_Exposure;
vec3 owDecodeSrgb(vec3 c) { return c; }
vec3 owEncodeSrgb(vec3 c) { return c; }
vec3 owDisplay(vec3 linear) { return owEncodeSrgb(osgWater_Exposure * linear); }
GLSL
bash scripts/shader-cost.sh "$override" "${1:-3}"
