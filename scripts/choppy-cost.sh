#!/usr/bin/env bash
# What choppy waves cost the lake's frame: scripts/paired-cost.sh with the wind's waves at
# choppiness 1 (A) against none (B). A / B is choppy ÷ not.
#   usage: scripts/choppy-cost.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/paired-cost.sh "${1:-3}" "--choppy 1" "--choppy 0"
