#!/usr/bin/env bash
# What summing light in linear units costs the lake's frame: the demo, headless, at four of the
# benchmark's views with the water in view, timed as built ("linear") and with every sum made on
# display values as before ("display": the kit's sRGB decode and encode replaced by the identity
# through a shader override, srgb.glsl on OSG_FILE_PATH). The two run alternately, view by view,
# for ROUNDS rounds (default 3); printed: each pair's frame times, and the median of linear ÷
# display over the pairs with a bootstrap 95% interval. The machine is noisy (±10% a run), so only
# the paired median is a figure. About 4 minutes a round on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
rounds="${1:-3}"
bash scripts/build.sh > /dev/null
override="$(mktemp -d)"
trap 'rm -rf "$override"' EXIT
mkdir -p "$override/osgWater/shaders"
cat > "$override/osgWater/shaders/srgb.glsl" <<'EOF'
uniform float osgWater_Exposure;
vec3 owDecodeSrgb(vec3 c) { return c; }
vec3 owEncodeSrgb(vec3 c) { return c; }
vec3 owDisplay(vec3 linear) { return owEncodeSrgb(osgWater_Exposure * linear); }
EOF
# eye and centre of: high overview, near the shore, into the sun, across the whole lake (data/lake.views)
views=("0 -72 48:0 -5 -3" "6 -36 2:2 -24 -1.5" "-24 -32 4:0 0 -1" "-24 -24 2.5:40 40 0")
log="$(mktemp)"
for round in $(seq 1 "$rounds"); do
  for view in "${views[@]}"; do
    for mode in linear display; do
      if [ "$mode" = display ]; then export OSG_FILE_PATH="$override"; else unset OSG_FILE_PATH; fi
      ms=$(bash scripts/with-display.sh ./build/apps/osgwaterlake/osgwaterlake --headless --no-hud --no-compare \
             --frames 40 --eye ${view%%:*} --center ${view##*:} --screenshot "$override/shot.png" 2>&1 |
           sed -n 's/^ *water  *\([0-9.]*\) ms.*/\1/p')
      echo "$round|${view%%:*}|$mode|$ms" | tee -a "$log"
    done
  done
done
python3 - "$log" <<'EOF'
import math, random, statistics, sys
pairs = {}
for line in open(sys.argv[1]):
    r, view, mode, ms = line.strip().split('|')
    pairs.setdefault((r, view), {})[mode] = float(ms)
ratios = [p['linear'] / p['display'] for p in pairs.values() if len(p) == 2]
random.seed(1)
boot = sorted(statistics.median(random.choices(ratios, k=len(ratios))) for _ in range(5000))
print('linear / display over %d pairs: median %.3f (95%% interval %.3f .. %.3f), geometric mean %.3f'
      % (len(ratios), statistics.median(ratios), boot[125], boot[-126],
         math.exp(sum(map(math.log, ratios)) / len(ratios))))
EOF
