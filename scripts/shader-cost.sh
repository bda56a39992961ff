#!/usr/bin/env bash
# What a shader's choice costs the lake's frame: the demo, headless, at four of the benchmark's views
# with the water in view, timed as built ("built") and with the shader files of OVERRIDE_DIR in front
# of the embedded ones ("override": OVERRIDE_DIR/osgWater/shaders/*.glsl on OSG_FILE_PATH, the kit's
# data path). The two run alternately, view by view, for ROUNDS rounds (default 3); printed: each
# pair's frame times, and the median of built ÷ override over the pairs with a bootstrap 95%
# interval. The machine is noisy (±10% a run), so only the paired median is a figure. About 4
# minutes a round on 2 cores.
#   usage: scripts/shader-cost.sh OVERRIDE_DIR [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
override="$(cd "$1" && pwd)"
rounds="${2:-3}"
[ -d "$override/osgWater/shaders" ] || { echo "shader-cost: no osgWater/shaders under $override" >&2; exit 2; }
bash scripts/build.sh > /dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# eye and centre of: high overview, near the shore, into the sun, across the whole lake (data/lake.views)
views=("0 -72 48:0 -5 -3" "6 -36 2:2 -24 -1.5" "-24 -32 4:0 0 -1" "-24 -24 2.5:40 40 0")
log="$work/times"
for round in $(seq 1 "$rounds"); do
  for view in "${views[@]}"; do
    for mode in built override; do
      if [ "$mode" = override ]; then export OSG_FILE_PATH="$override"; else unset OSG_FILE_PATH; fi
      ms=$(bash scripts/with-display.sh ./build/apps/osgwaterlake/osgwaterlake --headless --no-hud --no-compare \
             --frames 40 --eye ${view%%:*} --center ${view##*:} --screenshot "$work/shot.png" 2>&1 |
           sed -n 's/^ *water  *\([0-9.]*\) ms.*/\1/p')
      echo "$round|${view%%:*}|$mode|$ms" | tee -a "$log"
    done
  done
done
python3 - "$log" <<'PY'
import math, random, statistics, sys
pairs = {}
for line in open(sys.argv[1]):
    r, view, mode, ms = line.strip().split('|')
    pairs.setdefault((r, view), {})[mode] = float(ms)
ratios = [p['built'] / p['override'] for p in pairs.values() if len(p) == 2]
random.seed(1)
boot = sorted(statistics.median(random.choices(ratios, k=len(ratios))) for _ in range(5000))
print('built / override over %d pairs: median %.3f (95%% interval %.3f .. %.3f), geometric mean %.3f'
      % (len(ratios), statistics.median(ratios), boot[125], boot[-126],
         math.exp(sum(map(math.log, ratios)) / len(ratios))))
PY
