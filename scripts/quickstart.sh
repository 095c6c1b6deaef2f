#!/usr/bin/env bash
# Quick start, step 1: install the dependencies, build (Release), run the main job.
# The main job is a simulated Table 4 run at 0.5 Hz, +-40 mm through the observer and the
# hysteresis compensator; it prints force and B error figures and writes out/*.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
./build/release/tools/mrd-table4-run --out out "$@"
