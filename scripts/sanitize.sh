#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (LeakSanitizer included),
# built into ./build-sanitize. Any report fails the test that caused it. Leaks inside Mesa, X11 and
# LLVM (the software GL driver, not ours) are suppressed in scripts/lsan.supp, and one known OSG
# cycle; nothing of osgWater's. GL objects live in the driver's memory, so their leaks are counted by
# osgwater_leaks instead. ~10 min to build and ~6 min to test on 2 cores. Extra arguments go to ctest
# (e.g. -R Serialization).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOSGWATER_SANITIZE=ON
cmake --build build-sanitize -j"$(nproc)"
# Mesa unloads its driver (swrast_dri.so, with LLVM) when the last GL context goes, before
# LeakSanitizer reports at exit; the driver's own allocations would then show as "<unknown module>"
# that no suppression can name. Preloading the driver keeps it mapped, so lsan.supp names it. Nothing
# preloaded defines malloc, so ASan's interceptors still come first (hence verify_asan_link_order=0).
DRI=$(ls /usr/lib/*/dri/swrast_dri.so 2>/dev/null | head -1 || true)
if [ -n "$DRI" ]; then export LD_PRELOAD="$DRI"; fi
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:verify_asan_link_order=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
bash scripts/with-display.sh ctest --test-dir build-sanitize --output-on-failure "$@"
