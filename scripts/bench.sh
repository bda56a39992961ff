#!/usr/bin/env bash
# Speed against error on the lake: installs, builds, runs osgwaterbench at 1280x720 over
# data/lake.views, writes bench-out/results.{json,csv} and regenerates docs/BENCHMARKS.md and
# docs/benchmark-speed-error.png, then the Fresnel fit's docs/FRESNEL.md and the virtual vertices'
# docs/VIRTUAL_VERTICES.md. The published techniques take about two hours on 2 cores
# (llvmpipe); run again after a cut, it measures only what is left. `bash scripts/bench.sh
# --techniques all` runs every one.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
# A run cut short goes on where it stopped: osgwaterbench keeps each finished technique under
# bench-out/resume, keyed by the git trees of everything that changes a figure. Uncommitted changes
# there (or no git) measure everything afresh.
resume=()
measured="osgWater shaders apps data CMakeLists.txt"
if git rev-parse --git-dir > /dev/null 2>&1 && git diff --quiet HEAD -- $measured &&
   [ -z "$(git ls-files --others --exclude-standard -- $measured)" ]; then
  resume=(--resume "$(for p in $measured; do git rev-parse "HEAD:$p"; done | sha1sum | cut -c1-16)")
else
  echo "bench.sh: uncommitted changes to the measured sources: every technique is measured afresh" >&2
fi
bash scripts/with-display.sh build/apps/osgwaterbench/osgwaterbench --scene data/lake.osgt --views data/lake.views \
  --held-out data/lake-hard.views \
  --size 1280x720 --out bench-out --docs docs --photons 2000000 "${resume[@]}" \
  --techniques default,one-step,refraction-plane,refraction-bracketed,refraction-virtual-vertices,reflection-offset,reflection-plane,mesh-grid,waves-sum,waves-wind,iterative-1,iterative-2,iterative-8,budget-0.0625,budget-0.25,budget-1,budget-4,no-rotation,rotation-thesis,texture-256,texture-1024,view-targets-0.5,view-targets-1,fresnel-schlick,fresnel-power,fresnel-reciprocal,caustics-off,caustics-unfocused,caustics-cpu,caustics-points-texture,caustics-photons-halved,caustics-mesh,caustics-mesh-supersampled,caustics-procedural,caustics-procedural-screen,caustics-tiled,caustics-reflective,environment-map,glow-off,quality-fast,quality-exact \
  "$@"
# the reciprocal-power Fresnel fit: docs/FRESNEL.md and docs/fresnel-approximations.png
build/apps/osgwaterbench/osgwaterbench --fresnel-figure docs
# the virtual vertices' error volume (the geometric-refraction thesis's Tables 4.1, 4.2): docs/VIRTUAL_VERTICES.md
build/apps/osgwatervirtualvertices/osgwatervirtualvertices --scene data/lake.osgt --docs docs > /dev/null
