#!/usr/bin/env bash
# Quick start, step 1: install the dependencies, build (Release), run the main jobs.
# 1. The simulated Table 4 run at 0.5 Hz, +-40 mm through the observer and the hysteresis
#    compensator: force and B error figures, out/table4_run.csv and out/*.png.
# 2. mrd-controller, the firmware, for 5 s on its embedded default config: the real-time loop
#    against the simulated rig on the mock HAL. It prints the loop statistics and the supervisor's
#    transitions, and writes its telemetry to out/controller_telemetry.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
./build/release/tools/mrd-table4-run --out out "$@"
echo
./build/release/firmware/mrd-controller --duration 5 --telemetry out/controller_telemetry.csv
