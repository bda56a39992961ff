#!/usr/bin/env bash
# Fuzzes the .osgt/.osgb reading of WaterNode, WaterSettings and WaterSurface with libFuzzer (clang,
# AddressSanitizer + UndefinedBehaviorSanitizer), seeded from tests/fuzz/seeds (made from data/ and
# the test files). Usage: bash scripts/fuzz.sh [runs] (default 1,000,000 executions).
# Crashes are written to fuzz-out/crash-*: copy each into tests/fuzz/regressions/ (replayed by
# the ordinary test suite), then fix it.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-1000000}"
bash scripts/install-deps.sh fuzz
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOSGWATER_FUZZ=ON
cmake --build build-fuzz -j"$(nproc)" --target osgwater_fuzz
mkdir -p fuzz-out/corpus
# leaks are LeakSanitizer's part in sanitize.sh; OSG's osg2 reader leaks ~1.5 kB per read (an Options
# reference cycle, see lsan.supp), so memory grows ~1.5 GB over a million inputs: hence 4 GB
# no 0xbe fill of every allocation and a small quarantine: 5x the executions a second, same checks
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:max_malloc_fill_size=0:quarantine_size_mb=16"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
build-fuzz/tests/osgwater_fuzz -runs="$RUNS" -max_len=4096 -timeout=10 -rss_limit_mb=4096 \
  -artifact_prefix=fuzz-out/ -print_final_stats=1 fuzz-out/corpus tests/fuzz/seeds tests/fuzz/regressions
