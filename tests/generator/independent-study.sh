#!/usr/bin/env bash
# mrd-residual on runs from the independent truth generator (tests/generator/damper_truth.py),
# whose forms differ from the fitter's model (docs/CLOSING-THE-LOOP.md, "The independent
# generator"). Prints a Markdown table; the runs and the JSON go to OUT_DIR.
# Usage: tests/generator/independent-study.sh [BUILD_DIR] [OUT_DIR]   (needs python3 with numpy)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build/release}
out=${2:-out/independent}
python=${MRD_PYTHON:-/usr/bin/python3}
mkdir -p "$out"
echo "| run | profile | truth | named | discovered | ambiguous | RMS before [N] | RMS after [N] |"
echo "|---|---|---|---|---|---|---:|---:|"
run() {  # NAME PROFILE EFFECT...
  local name=$1 profile=$2; shift 2
  local args=()
  for e in "$@"; do args+=(--effect "$e"); done
  "$python" "$here/damper_truth.py" --profile "$profile" --duration 6 "${args[@]}" --out "$out/$name.csv" \
    --manifest "$out/$name.truth.json"
  "$build/tools/mrd-residual" "$out/$name.csv" --json "$out/$name.json" > "$out/$name.txt"
  "$python" - "$out/$name.json" "$name" "$profile" "$*" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
terms = ", ".join(f"{t['term']} {t['coefficient']:.3g} {t['unit']}" for t in r.get("discovered", [])) or "none"
alike = "; ".join(" ~ ".join(g) for g in r.get("ambiguous", [])) or ""
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4] or 'none'} | {', '.join(r['effects']) or 'none'} | {terms} | "
      f"{alike} | {r['rms_before_N']:.4g} | {r['rms_after_N']:.4g} |")
PY
}
run clean-table4 table4
run clean-telegraph telegraph
effects=(coil_lag gas_spring sensor_delay preyield_hysteresis stroke_end_air thermal_drift)
# The coil lag shows where the current switches: its runs use the telegraph current.
profile_for() { [[ " $* " == *" coil_lag "* ]] && echo telegraph || echo table4; }
for e in "${effects[@]}"; do
  run "$e" "$(profile_for "$e")" "$e:2"
done
run air-beyond beyond stroke_end_air:2
for ((i = 0; i < ${#effects[@]}; ++i)); do
  for ((j = i + 1; j < ${#effects[@]}; ++j)); do
    a=${effects[i]} b=${effects[j]}
    run "$a+$b" "$(profile_for "$a" "$b")" "$a:2" "$b:2"
  done
done
for e in moving_mass coulomb_friction mains_hum field_viscosity bump_stop; do
  run "$e" telegraph "$e:2"
done
