#!/usr/bin/env bash
# Renders the pictures in README.md and docs/DEMO.md with the lake demo, headless (after
# scripts/build.sh): each one's options are in its caption; pairs are joined by side_by_side.py.
# The README's view is also traced by the benchmark's reference (osgwaterbench, a few minutes):
# docs/osgwaterlake-reference.png is its render | reference | CIEDE2000 triplet.
set -euo pipefail
cd "$(dirname "$0")/.."
demo() { bash scripts/with-display.sh ./build/apps/osgwaterlake/osgwaterlake --headless --frames 3 --no-compare "$@" > /dev/null; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pair() { python3 scripts/side_by_side.py "docs/$1" "$tmp/left.png" "$tmp/right.png"; }

demo --screenshot docs/osgwaterlake.png
# the same view, settings (the demo's clear-lake water) and time (10 s) rendered and traced
printf '0 -42 4.5   0 10 -1   0 0 1   10   # the demo view\n' > "$tmp/demo.views"
bash scripts/with-display.sh ./build/apps/osgwaterbench/osgwaterbench --scene data/lake.osgt --views "$tmp/demo.views" \
  --water-type clear-lake --techniques default --size 1024x768 --photons 2000000 --ablation-rounds 0 \
  --out "$tmp/bench" > /dev/null
cp "$tmp/bench/triplets/the-demo-view.png" docs/osgwaterlake-reference.png
demo --no-hud --size 640 480 --eye 0 -38 3 --center 0 -33 -1 --water-type thesis --screenshot "$tmp/left.png"
demo --no-hud --size 640 480 --eye 0 -38 3 --center 0 -33 -1 --water-type thesis --no-caustics --screenshot "$tmp/right.png"
pair osgwaterlake-caustics.png
demo --no-hud --size 512 384 --water-type thesis --underwater --k 0.15 --screenshot "$tmp/left.png"
demo --no-hud --size 512 384 --eye 0 -20 -3 --center 0 -13 2 --k 0.15 --screenshot "$tmp/right.png"
pair osgwaterlake-underwater.png
demo --no-hud --size 512 384 --sun 0 0.97 0.2 --water-type thesis --dome --no-glow --screenshot "$tmp/left.png"
demo --no-hud --size 512 384 --sun 0 0.97 0.2 --water-type thesis --dome --screenshot "$tmp/right.png"
pair osgwaterlake-glow.png
demo --no-hud --size 800 500 --pond --eye 12 18 9 --center 10 44 2.5 --screenshot docs/osgwaterlake-pond.png
echo "pictures: docs/osgwaterlake*.png"
