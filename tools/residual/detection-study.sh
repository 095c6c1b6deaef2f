#!/usr/bin/env bash
# The detection table of docs/CLOSING-THE-LOOP.md: simulated runs that carry one undeclared
# effect (or none), at two sizes, on both damper classes and two profiles, then every pair of
# effects at their nominal size on the 50 kN Table 4 run, each analysed by mrd-residual. Prints
# one markdown row per run (about 5 min on 2 idle cores). PART: all, singles or pairs.
# Usage: tools/residual/detection-study.sh [BUILD_DIR] [OUT_DIR] [SEED] [PART]
# MRD_RESIDUAL_ARGS: more options for every mrd-residual (e.g. --robust-fit).
set -euo pipefail
build=${1:-build/release}
out=${2:-out/detection}
seed=${3:-1}
part=${4:-all}
mkdir -p "$out"
simulate="$build/tools/simulation/mrd-simulate-run"
residual="$build/tools/mrd-residual"
echo "| class | profile | carried | named | RMS before [N] | RMS after [N] | factor | seconds |"
echo "|---|---|---|---|---:|---:|---:|---:|"
effects=(coil_lag preyield_hysteresis gas_spring thermal_drift sensor_delay stroke_end_air)
study() {  # CLASS PROFILE NAME CARRIED...   (CARRIED: NAME:SIZE; none for a clean run)
  local class=$1 profile=$2 name=$3; shift 3
  local args=(--damper "$class" --profile "$profile" --seed "$seed" --csv "$out/$name.csv")
  for carried in "$@"; do args+=(--effect "$carried"); done
  "$simulate" "${args[@]}" > /dev/null
  local start end
  start=$(date +%s.%N)
  # shellcheck disable=SC2086  # the extra options are words
  "$residual" "$out/$name.csv" ${MRD_RESIDUAL_ARGS:-} --json "$out/$name.json" > "$out/$name.txt"
  end=$(date +%s.%N)
  python3 - "$out/$name.json" "$class" "$profile" "$start" "$end" "$@" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
cls, profile, start, end = sys.argv[2:6]
carried = ", ".join(sys.argv[6:]) or "none"
named = ", ".join(r["effects"]) or "none"
alike = "; ".join(" ~ ".join(g) for g in r.get("ambiguous", []))
alike = f" (ambiguous: {alike})" if alike else ""
factor = r["rms_before_N"] / r["rms_after_N"] if r["rms_after_N"] > 0 else float("nan")
print(f"| {cls} | {profile} | {carried} | {named}{alike} | {r['rms_before_N']:.4g} | {r['rms_after_N']:.4g} | {factor:.3g} | {float(end) - float(start):.1f} |")
PY
}
for class in 50kN 1kN; do
  [[ $part == pairs ]] && break
  for profile in table4 telegraph; do
    study "$class" "$profile" "$class-$profile-clean-small"
    for effect in "${effects[@]}"; do
      for size in small large; do
        study "$class" "$profile" "$class-$profile-$effect-$size" "$effect:$size"
      done
    done
  done
done
if [[ $part != singles ]]; then
  class=50kN profile=table4
  for ((i = 0; i < ${#effects[@]}; ++i)); do
    for ((j = i + 1; j < ${#effects[@]}; ++j)); do
      a=${effects[i]} b=${effects[j]}
      study "$class" "$profile" "$class-$profile-$a+$b" "$a:medium" "$b:medium"
    done
  done
fi
