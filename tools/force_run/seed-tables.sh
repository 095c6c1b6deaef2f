#!/usr/bin/env bash
# The seed tables of docs/FORCE-CONTROL.md ("The seeds", "Drift on the simulated plant"), from
# mrd-force-run's JSON. Usage: tools/force_run/seed-tables.sh [MRD_FORCE_RUN] [OUT_DIR]
# About 3 minutes on two cores.
set -euo pipefail
tool=${1:-build/release/tools/mrd-force-run}
out=${2:-$(mktemp -d)}
mkdir -p "$out"

run() {  # run NAME ARGS...: one mrd-force-run, its JSON kept as OUT/NAME.json
  local name=$1; shift
  "$tool" "$@" --json "$out/$name.json" > /dev/null
}
rms() {  # rms FILE STRATEGY: that strategy's RMS error [N], rounded
  python3 -c 'import json,sys
d = json.load(open(sys.argv[1]))
print(round(next(s["rms_error_N"] for s in d["strategies"] if s["name"] == sys.argv[2])))' "$1" "$2"
}
ratio() { python3 -c 'import sys; print(f"{float(sys.argv[1]) / float(sys.argv[2]):.2f}")' "$1" "$2"; }

echo "| profile | seed | inverse_ja [N] | / inverse_bingham | / clipped_on_off | inverse_ja_lag, 30 ms lag [N] | / inverse_ja |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
for profile in random structure; do
  for seed in 1 2 3 4 5; do
    run "$profile-$seed" --profile "$profile" --seed "$seed"
    run "$profile-$seed-lag" --profile "$profile" --seed "$seed" --coil-lag-ms 30
    ja=$(rms "$out/$profile-$seed.json" inverse_ja)
    bingham=$(rms "$out/$profile-$seed.json" inverse_bingham)
    onoff=$(rms "$out/$profile-$seed.json" clipped_on_off)
    lag_ja=$(rms "$out/$profile-$seed-lag.json" inverse_ja)
    lag=$(rms "$out/$profile-$seed-lag.json" inverse_ja_lag)
    echo "| $profile | $seed | $ja | $(ratio "$ja" "$bingham") | $(ratio "$ja" "$onoff") | $lag | $(ratio "$lag" "$lag_ja") |"
  done
done

echo
echo "| run | inverse_ja [N RMS] | inverse_ja_load_cell [N RMS] | ratio |"
echo "| --- | ---: | ---: | ---: |"
drift_row() {  # drift_row LABEL NAME ARGS...
  local label=$1 name=$2; shift 2
  run "$name" --load-cell "$@"
  local ja lc
  ja=$(rms "$out/$name.json" inverse_ja)
  lc=$(rms "$out/$name.json" inverse_ja_load_cell)
  echo "| $label | $ja | $lc | $(ratio "$lc" "$ja") |"
}
for seed in 1 2 3 4 5; do
  drift_row "20 % drift, 60 s, seed $seed" "drift-60-$seed" --drift 20 --duration 60 --seed "$seed"
done
for tau in 5 2 1; do
  drift_row "20 % drift, 20 s, time_constant $tau s" "drift-20-tau$tau" --drift 20 --duration 20 --load-cell-tau "$tau"
done
drift_row "20 % drift, 120 s, seed 1" drift-120 --drift 20 --duration 120
for seed in 1 2 3 4 5; do
  drift_row "no drift, 60 s, seed $seed" "still-60-$seed" --duration 60 --seed "$seed"
done
drift_row "no drift, 20 s, seed 1" still-20 --duration 20
echo
echo "JSON: $out"
