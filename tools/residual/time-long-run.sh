#!/usr/bin/env bash
# The timing case for mrd-residual: a 10-minute telegraph run at 1 kHz (600,000
# samples, 1 kN class) carrying an undeclared thermal drift, analysed on 2 threads. Prints the
# summary's last lines and /usr/bin/time's wall, CPU and resident memory.
# Usage: tools/residual/time-long-run.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/long-run}
mkdir -p "$out"
[[ -f "$out/long.csv" ]] ||
  "$build/tools/simulation/mrd-simulate-run" --profile telegraph --damper 1kN --duration 600 \
    --effect thermal_drift --csv "$out/long.csv" > /dev/null
/usr/bin/time -f "wall %e s, CPU %U s user + %S s system, %M KB resident" \
  "$build/tools/mrd-residual" "$out/long.csv" --threads 2 > "$out/summary.txt" 2> "$out/time.txt"
tail -n 4 "$out/summary.txt"
cat "$out/time.txt"
