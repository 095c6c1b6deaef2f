#!/usr/bin/env bash
# The detection table of docs/CLOSING-THE-LOOP.md: simulated runs that carry one undeclared
# effect (or none), at two sizes, on both damper classes and two profiles, each analysed by
# mrd-residual. Prints one markdown row per run.
# Usage: tools/residual/detection-study.sh [BUILD_DIR] [OUT_DIR] [SEED]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/detection}
seed=${3:-1}
mkdir -p "$out"
simulate="$build/tools/simulation/mrd-simulate-run"
residual="$build/tools/mrd-residual"
echo "| class | profile | carried | named | RMS before [N] | RMS after [N] | factor | seconds |"
echo "|---|---|---|---|---:|---:|---:|---:|"
for class in 50kN 1kN; do
  for profile in table4 telegraph; do
    for effect in clean coil_lag preyield_hysteresis gas_spring thermal_drift sensor_delay stroke_end_air; do
      for size in small large; do
        [[ $effect == clean && $size == large ]] && continue
        name="$class-$profile-$effect-$size"
        args=(--damper "$class" --profile "$profile" --seed "$seed" --out "$out/$name.csv")
        [[ $effect != clean ]] && args+=(--effect "$effect:$size")
        "$simulate" "${args[@]}" > /dev/null
        start=$(date +%s.%N)
        "$residual" "$out/$name.csv" --json "$out/$name.json" > "$out/$name.txt"
        end=$(date +%s.%N)
        python3 - "$out/$name.json" "$class" "$profile" "$effect" "$size" "$start" "$end" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
cls, profile, effect, size, start, end = sys.argv[2:]
carried = "none" if effect == "clean" else f"{effect}:{size}"
named = ", ".join(r["effects"]) or "none"
factor = r["rms_before_N"] / r["rms_after_N"] if r["rms_after_N"] > 0 else float("nan")
print(f"| {cls} | {profile} | {carried} | {named} | {r['rms_before_N']:.4g} | {r['rms_after_N']:.4g} | {factor:.3g} | {float(end) - float(start):.1f} |")
PY
      done
    done
  done
done
