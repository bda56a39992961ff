#!/usr/bin/env bash
# Installs what osgWater needs on Debian 12 (bookworm), from Debian's own packages.
# `install-deps.sh fuzz` adds clang and its libFuzzer runtime (scripts/fuzz.sh).
set -euo pipefail
PACKAGES=(
  cmake g++ make pkg-config
  libopenscenegraph-dev openscenegraph   # OSG 3.6.5: library, osgDB plugins (obj, png), osgviewer
  libglm-dev                             # CPU mirror of the shader maths
  libfftw3-dev                           # the wave spectrum's FFT cascades
  libgtest-dev                           # tests
  libembree-dev nlohmann-json3-dev gnuplot-nox  # benchmark: exact reference, results.json, plot
  xvfb xauth libgl1-mesa-dri             # headless rendering: Xvfb + Mesa llvmpipe
)
if [ "${1:-}" = "fuzz" ]; then PACKAGES+=(clang libclang-rt-14-dev); fi
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
