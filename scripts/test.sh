#!/usr/bin/env bash
# Installs dependencies, builds, and runs every test (unit + headless rendering) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/with-display.sh ctest --test-dir build --output-on-failure
