#!/usr/bin/env bash
# An install a user can run: the README's install block, run as written from a scratch folder with a
# clean environment (no library or OSG paths), then the same prefix moved elsewhere and used again.
#   $1 the build folder, $2 the README, $3 the consumer project (tests/consumer), $4 osgconv,
#   $5 compiler flags a consumer must share with the library (the sanitizer build's)
set -euo pipefail
build="$1"; readme="$2"; consumer="$3"; osgconv="$4"; flags="${5:-}"
work="$build/_install_run"
rm -rf "$work"; mkdir -p "$work/scratch"
# the block under the README's "<!-- install" marker, as written
awk '/^<!-- install/ { marked = 1; next }
     marked && /^```bash/ { inside = 1; marked = 0; next }
     inside && /^```/ { exit }
     inside { print }' "$readme" > "$work/block.sh"
grep -q 'CMAKE_PREFIX_PATH' "$work/block.sh" && grep -q 'OSG_LIBRARY_PATH' "$work/block.sh" \
  || { echo "the README's install block lost its CMAKE_PREFIX_PATH or OSG_LIBRARY_PATH line"; exit 1; }
# what a user's shell has, nothing the build set (and the sanitizer build's runtime settings)
clean=(env -i PATH=/usr/bin:/bin HOME="$work" DISPLAY="${DISPLAY:-}" XAUTHORITY="${XAUTHORITY:-}")
for v in LD_PRELOAD ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS; do
  if [ -n "${!v:-}" ]; then clean+=("$v=${!v}"); fi
done
# the block's "build" and "my-app": this build and a project that finds the kit
ln -s "$(cd "$build" && pwd)" "$work/scratch/build"
cp -r "$consumer" "$work/scratch/my-app"
(cd "$work/scratch" && "${clean[@]}" PREFIX="$work/prefix" bash -euo pipefail "$work/block.sh") > "$work/block.log" 2>&1 \
  || { cat "$work/block.log"; echo "the README's install block failed"; exit 1; }
grep -q 'frame time, median' "$work/block.log" || { cat "$work/block.log"; echo "the installed demo printed no frame times"; exit 1; }
[ -s "$work/scratch/osgwaterlake.png" ] || { echo "the installed demo wrote no screenshot"; exit 1; }
grep -q -a 'osgWater::WaterNode' "$work/scratch/lake.osgb" 2> /dev/null \
  || { echo "osgconv through OSG_LIBRARY_PATH did not write the lake's water"; exit 1; }

# the exported targets name no path of this machine (only paths under the prefix): it can move
if grep -hE '^\s*(INTERFACE|IMPORTED)_[A-Z_]+ ' "$work/prefix/lib/cmake/osgWater/"osgWaterTargets*.cmake \
   | sed 's|\${_IMPORT_PREFIX}/[^;"]*||g' | grep -E '["; ]/'; then
  echo "the exported targets hold absolute paths"; exit 1
fi
mv "$work/prefix" "$work/moved"
mkdir -p "$work/elsewhere"
(cd "$work/elsewhere" && "${clean[@]}" "$work/moved/bin/osgwaterlake" --headless --frames 2 --size 64 48 --no-compare) \
  > "$work/moved.log" 2>&1 || { cat "$work/moved.log"; echo "the moved prefix's demo failed"; exit 1; }
[ -s "$work/elsewhere/osgwaterlake.png" ] || { echo "the moved prefix's demo wrote no screenshot"; exit 1; }
# its scene is the prefix's own, not the source tree's (which this machine also has)
grep -q "^scene: $work/moved/share/osgWater/data/lake.osgt" "$work/moved.log" \
  || { cat "$work/moved.log"; echo "the moved prefix's demo did not load its own scene"; exit 1; }
# a runtime-only install (no libosgWater.so development link): osgDB finds the serializer plugin
rm "$work/moved/lib/libosgWater.so"
(cd "$work/elsewhere" && "${clean[@]}" OSG_LIBRARY_PATH="$work/moved/lib" "$osgconv" \
   "$work/moved/share/osgWater/data/lake.osgt" plugin.osgt) > "$work/plugin.log" 2>&1 || true
grep -q 'osgWater::WaterNode' "$work/elsewhere/plugin.osgt" 2> /dev/null \
  || { cat "$work/plugin.log"; echo "osgconv did not read the lake through the serializer plugin"; exit 1; }
ln -s libosgWater.so.0 "$work/moved/lib/libosgWater.so"
# a project configured and built against the moved prefix links and runs
"${clean[@]}" cmake -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/moved" \
  ${flags:+"-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags"} > /dev/null
"${clean[@]}" cmake --build "$work/consumer" > /dev/null
"${clean[@]}" "$work/consumer/consumer" > /dev/null
echo "installed, moved, and run"
