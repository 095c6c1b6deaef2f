#!/usr/bin/env bash
# The measured-data tables of docs/CLOSING-THE-LOOP.md, "mrd-residual": Dyke's prototype damper
# (with Spencer 1997's published model as the reference) and Quiroz's sine tests at all
# currents fitted together, then their validation record predicted per current.
# Usage: tools/residual/measured-runs.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/residual}
mkdir -p "$out/dyke" "$out/quiroz"
residual="$build/tools/mrd-residual"
replay="$build/tools/mrd-replay"

echo "== Dyke, ranran_50.csv"
"$residual" data/damper/dyke-nees-prototype/ranran_50.csv \
  --columns t=time_s,D=displacement_cm,Y=voltage_V,F=force_N,V=velocity_cm_s --amps-per-volt 0.5 \
  --reference-spencer-dyke --json "$out/dyke/residual.json" --write-config "$out/dyke/fitted.toml" --accept-unphysical \
  --plot "$out/dyke" | tee "$out/dyke/summary.txt"

echo "== Quiroz, the 20 sine tests together"
"$residual" data/damper/quiroz-utfsm/sine/*.txt \
  --columns 1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N --current-from-name \
  --json "$out/quiroz/residual.json" --write-config "$out/quiroz/fitted.toml" --accept-unphysical \
  --plot "$out/quiroz" | tee "$out/quiroz/summary.txt"

echo "== Quiroz, validation.csv predicted with the fitted config, per current"
for pair in 0p2:0.2 0p4:0.4 0p6:0.6 0p8:0.8 1p0:1.0; do
  column=${pair%%:*}
  amps=${pair##*:}
  for config in etc/mrd/mrd.toml "$out/quiroz/fitted.toml"; do
    printf '%s A, %s: ' "$amps" "$(basename "$config")"
    "$replay" data/damper/quiroz-utfsm/validation.csv --columns "x_mm=displacement_mm,F_${column}A_N=force_N" \
      --current "$amps" --sample-rate 1000 --zero-phase-velocity 0 --config "$config" | grep "force error"
  done
done
"$replay" data/damper/quiroz-utfsm/validation.csv --columns x_mm=displacement_mm,F_0p6A_N=force_N --current 0.6 \
  --sample-rate 1000 --zero-phase-velocity 0 --config "$out/quiroz/fitted.toml" --plot "$out/quiroz/validation" > /dev/null

echo "== Quiroz, each sine test with the config fitted to all 20, per current (0 A included)"
for amps in 0 0x25 0x5 0x75 1; do
  python3 - "$replay" "$out/quiroz/fitted.toml" "$amps" data/damper/quiroz-utfsm/sine/*"Hz${amps}A.txt" <<'PY'
import re, subprocess, sys
replay, config, amps, files = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
sum_sq, count, ranges = 0.0, 0, []
for f in files:
    text = subprocess.run([replay, f, "--columns", "1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N",
                           "--current-from-name", "--recorded-velocity", "--config", config],
                          capture_output=True, text=True, check=True).stdout
    samples = int(re.search(r"(\d+) samples", text).group(1))
    rms = float(re.search(r"force error[^\n]*?RMS ([0-9.e+]+) N", text).group(1))
    ranges.append(float(re.search(r"measured range ([0-9.e+]+) N", text).group(1)))
    sum_sq += rms * rms * samples
    count += samples
rms = (sum_sq / count) ** 0.5
print(f"{amps.replace('x', '.')} A: {len(files)} tests, RMS {rms:.4g} N, NRMSE {rms / max(ranges):.4g} (of the largest range, {max(ranges):.4g} N)")
PY
done
