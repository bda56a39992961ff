#!/usr/bin/env bash
# Installs the build into a private prefix and builds + runs a consumer with find_package(osgWater).
set -euo pipefail
bin="$1"; src="$2"
# $3: compiler flags the library was built with that a consumer must share (the sanitizer build's:
# an uninstrumented program cannot load an ASan library)
flags="${3:-}"
rm -rf "$bin/_install" "$bin/_consumer"
cmake --install "$bin" --prefix "$bin/_install" > /dev/null
cmake -S "$src" -B "$bin/_consumer" -DCMAKE_PREFIX_PATH="$bin/_install" \
  ${flags:+"-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags"} > /dev/null
cmake --build "$bin/_consumer" > /dev/null
LD_LIBRARY_PATH="$bin/_install/lib:$bin/_install/lib/x86_64-linux-gnu:${LD_LIBRARY_PATH:-}" "$bin/_consumer/consumer"
