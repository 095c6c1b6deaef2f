#!/usr/bin/env bash
# Quick start, step 1: install the dependencies, build (Release), run the main jobs.
# 1. The simulated Table 4 run at 0.5 Hz, +-40 mm through the observer and the hysteresis
#    compensator: force and B error figures, out/table4_run.csv and out/*.png.
# 2. Hardware-in-the-loop on this host: mrd-plant (the simulated rig, etc/mrd/plant.toml) and
#    mrd-controller (etc/mrd/hil-modbus.toml) as two processes over Modbus TCP on 127.0.0.1,
#    the Table 4 sine at 0.5 Hz for 6 s. It prints the controller's loop statistics and
#    supervisor transitions, then mrd-hil-report joins the controller's telemetry with the
#    plant's log: the observer's force error against the plant's true force, and
#    out/hil/force_displacement.png (the paper's Fig. 14). docs/HIL.md explains it all.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
B=build/release
./$B/tools/mrd-table4-run --out out "$@"
echo
mkdir -p out
./$B/sim/plant/mrd-plant --config etc/mrd/plant.toml --log out/hil_plant.csv > out/hil_plant.out 2>&1 &
plant=$!
trap 'kill $plant 2>/dev/null || true' EXIT
# The plant says when it serves; wait for that line (bounded), not for a fixed time.
for _ in $(seq 100); do
  grep -q "mrd-plant: ready" out/hil_plant.out && break
  kill -0 $plant 2>/dev/null || { cat out/hil_plant.out; exit 1; }
  sleep 0.1
done
cat out/hil_plant.out
./$B/firmware/mrd-controller --config etc/mrd/hil-modbus.toml --duration 6 \
  --telemetry out/hil_telemetry.csv | tee out/hil_controller.out
kill -TERM $plant
wait $plant || true
trap - EXIT
tail -n +4 out/hil_plant.out
echo
./$B/tools/hil/mrd-hil-report --telemetry out/hil_telemetry.csv --plant out/hil_plant.csv --plot out/hil
