#!/usr/bin/env bash
# Dyke's ranran_50 cut in two halves: mrd-residual fits each half, and mrd-replay predicts the
# other half with the fitted config, both on the file's velocity column V.
# The cross-validation table of docs/CLOSING-THE-LOOP.md, "Measured data".
# Usage: tools/residual/dyke-halves.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/dyke-halves}
mkdir -p "$out"
source_file=data/damper/dyke-nees-prototype/ranran_50.csv
columns=t=time_s,D=displacement_cm,Y=voltage_V,F=force_N,V=velocity_cm_s
# The header, then each half of the rows as they are (the second keeps its own times).
rows=$(($(wc -l < "$source_file") - 1))
half=$((rows / 2))
sed -n "1p;2,$((half + 1))p" "$source_file" > "$out/first.csv"
sed -n "1p;$((half + 2)),\$p" "$source_file" > "$out/second.csv"
echo "| fitted on | predicted | RMS in sample [N] | RMS predicted [N] | NRMSE predicted | effects |"
echo "|---|---|---:|---:|---:|---|"
for pair in first:second second:first; do
  fit=${pair%%:*}
  other=${pair##*:}
  "$build/tools/mrd-residual" "$out/$fit.csv" --columns "$columns" --amps-per-volt 0.5 --quiet \
    --json "$out/$fit.json" --write-config "$out/$fit.toml" --accept-unphysical > "$out/$fit.txt"
  "$build/tools/mrd-replay" "$out/$other.csv" --columns "$columns" --amps-per-volt 0.5 \
    --config "$out/$fit.toml" --recorded-velocity > "$out/$fit-predicts-$other.txt"
  python3 - "$out/$fit.json" "$out/$fit-predicts-$other.txt" "$fit" "$other" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))
text = open(sys.argv[2]).read()
m = re.search(r"force error[^\n]*?RMS ([0-9.e+]+) N", text)
n = re.search(r"NRMSE ([0-9.e+-]+)", text)
rms = m.group(1) if m else "?"
nrmse = n.group(1) if n else "?"
print(f"| {sys.argv[3]} half | {sys.argv[4]} half | {r['rms_after_N']:.4g} | {rms} | {nrmse} | {', '.join(r['effects']) or 'none'} |")
PY
done
