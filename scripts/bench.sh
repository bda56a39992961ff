#!/usr/bin/env bash
# Speed against error on the lake (issue 6): installs, builds, runs osgwaterbench at 1280x720 over
# data/lake.views with every technique, writes bench-out/results.{json,csv} and regenerates
# docs/BENCHMARKS.md and docs/benchmark-speed-error.png. About 30 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/with-display.sh build/apps/osgwaterbench/osgwaterbench --scene data/lake.osgt --views data/lake.views \
  --size 1280x720 --out bench-out --docs docs "$@"
