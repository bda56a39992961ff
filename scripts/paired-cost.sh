#!/usr/bin/env bash
# What a choice costs the lake's frame: the demo, headless, at four of the benchmark's views with the
# water in view, timed with options A and with options B, alternately, view by view, for ROUNDS
# rounds. Each is a string of the demo's options; `--shaders DIR` in it (not a demo option) puts DIR
# on OSG_FILE_PATH, the kit's data path, so DIR/osgWater/shaders/*.glsl stand in front of the
# embedded shaders. Printed: each run's frame time, and the median of A ÷ B over the pairs with a
# bootstrap 95% interval. The machine is noisy (±10% a run), so only the paired median is a
# figure. About 4 minutes a round on 2 cores.
#   usage: scripts/paired-cost.sh ROUNDS "A OPTIONS" "B OPTIONS"
set -euo pipefail
cd "$(dirname "$0")/.."
rounds="$1"
modes=("$2" "$3")
bash scripts/build.sh > /dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# eye and centre of: high overview, near the shore, into the sun, across the whole lake (data/lake.views)
views=("0 -72 48:0 -5 -3" "6 -36 2:2 -24 -1.5" "-24 -32 4:0 0 -1" "-24 -24 2.5:40 40 0")
log="$work/times"
for round in $(seq 1 "$rounds"); do
  for view in "${views[@]}"; do
    for m in 0 1; do
      read -r -a options <<< "${modes[$m]}"
      args=()
      unset OSG_FILE_PATH
      for ((i = 0; i < ${#options[@]}; ++i)); do
        if [ "${options[$i]}" = --shaders ]; then
          i=$((i + 1))
          export OSG_FILE_PATH="$(cd "${options[$i]}" && pwd)"
        else
          args+=("${options[$i]}")
        fi
      done
      ms=$(bash scripts/with-display.sh ./build/apps/osgwaterlake/osgwaterlake --headless --no-hud --no-compare \
             --frames 40 --eye ${view%%:*} --center ${view##*:} --screenshot "$work/shot.png" ${args[@]+"${args[@]}"} 2>&1 |
           sed -n 's/^ *water  *\([0-9.]*\) ms.*/\1/p')
      label=$([ "$m" = 0 ] && echo A || echo B)
      echo "$round|${view%%:*}|$label|$ms" | tee -a "$log"
    done
  done
done
python3 - "$log" <<'PY'
import math, random, statistics, sys
pairs = {}
for line in open(sys.argv[1]):
    r, view, mode, ms = line.strip().split('|')
    pairs.setdefault((r, view), {})[mode] = float(ms)
ratios = [p['A'] / p['B'] for p in pairs.values() if len(p) == 2]
random.seed(1)
boot = sorted(statistics.median(random.choices(ratios, k=len(ratios))) for _ in range(5000))
print('A / B over %d pairs: median %.3f (95%% interval %.3f .. %.3f), geometric mean %.3f'
      % (len(ratios), statistics.median(ratios), boot[125], boot[-126],
         math.exp(sum(map(math.log, ratios)) / len(ratios))))
PY
