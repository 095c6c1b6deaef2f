#!/usr/bin/env bash
# Logger faults injected into clean runs (issue 27's tables in docs/CLOSING-THE-LOOP.md, "Data as
# loggers write it"), by tools/residual/inject_logger_faults.py: the unfaulted run, a gap of
# 0.05 s, 0.3 s and 2 s, 1 % of its rows written twice, 5 empty cells, 3 rows whose time goes
# back, each sample taken up to 10 % or 30 % of a period off its grid time, and a rig at its end
# stop (0.36 s of a still LVDT under a ringing, clipped load cell: implausible). Sources:
#   simulated    mrd-simulate-run, 1 kN, Table 4 for 12 s with EFFECT (default gas_spring), at
#                10 kHz written at 1 kHz without its velocity column; jitter picks 10 kHz samples
#   independent  tests/generator/damper_truth.py, telegraph current, 8 s with a field lag
#                (coil_lag:2); jitter by interpolation, the current held at its level
#   independent-fine  the same at 10 kHz written at 1 kHz: jitter picks 10 kHz samples, and
#                the telegraph's switches fall between the written rows, as a real command's do
#                (not in "all")
#   measured     Quiroz's sine test 5mm3Hz0x75A.txt (data/damper/quiroz-utfsm), its own format
#                and velocity column, 0.75 A; jitter by interpolation
# Prints, per source and variant, the effects named, the RMS after on the kept samples and its
# ratio to the unfaulted run's (**bold** over 1.05, "differs" where the effects are not the
# unfaulted run's), that ratio again against the unfaulted run's error on the same samples (the
# ones the variant kept: a gap that removes a hard stretch lowers the error on what is left),
# and the RMS in the first and last second against the rest (from the residual trace --plot
# writes).
# Usage: tools/residual/logger-faults.sh [BUILD_DIR] [OUT_DIR] [SOURCE...] (default: simulated;
#        all: the three). EFFECT=... sets the simulated run's effect.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-build/release}
out=${2:-out/logger-faults}
shift $(($# > 2 ? 2 : $#))
sources=("${@:-simulated}")
[[ ${sources[0]} == all ]] && sources=(simulated independent measured)
python=${MRD_PYTHON:-/usr/bin/python3}
inject="$python $here/inject_logger_faults.py"

for source in "${sources[@]}"; do
  dir="$out/$source"
  mkdir -p "$dir"
  extension=.csv
  residual_args=()
  case $source in
    simulated)
      "$build/tools/simulation/mrd-simulate-run" --profile table4 --damper 1kN --duration 12 \
        --effect "${EFFECT:-gas_spring}" --rate 10000 --csv "$dir/source.csv" > /dev/null
      # Columns: time_s, displacement_mm, current_A, force_N after the velocity is dropped.
      $inject "$dir/source.csv" "$dir" --drop-columns velocity --fine-every 10 --force-column 3 > "$dir/variants"
      ;;
    independent | independent-fine)
      fine=()
      [[ $source == independent-fine ]] && fine=(--rate 10000)
      "$python" "$root/tests/generator/damper_truth.py" --profile telegraph --duration 8 --effect coil_lag:2 \
        "${fine[@]}" --out "$dir/source.csv"
      header=$(head -1 "$dir/source.csv")
      force=$("$python" -c "import sys; print(sys.argv[1].split(',').index('force_N'))" "$header")
      current=$("$python" -c "import sys; print(sys.argv[1].split(',').index('current_A'))" "$header")
      fine=(--held-columns "$current")
      [[ $source == independent-fine ]] && fine=(--fine-every 10)
      $inject "$dir/source.csv" "$dir" "${fine[@]}" --force-column "$force" > "$dir/variants"
      ;;
    measured)
      extension=.txt
      residual_args=(--columns 1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N --current 0.75)
      $inject "$root/data/damper/quiroz-utfsm/sine/5mm3Hz0x75A.txt" "$dir" --force-column 3 > "$dir/variants"
      ;;
    *) echo "unknown source '$source': simulated, independent, independent-fine, measured or all" >&2; exit 1 ;;
  esac
  echo
  echo "$source:"
  echo
  echo "| variant | named | rms_after [N] | / unfaulted | / unfaulted, same samples | set aside | first and last 1 s [N] | in between [N] |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|"
  while read -r variant; do
    "$build/tools/mrd-residual" "$dir/$variant$extension" "${residual_args[@]}" --json "$dir/$variant.json" \
      --plot "$dir/$variant.plot" > "$dir/$variant.summary" 2> "$dir/$variant.err" ||
      { echo "| $variant | failed: $(tail -1 "$dir/$variant.err") |"; continue; }
    "$python" - "$dir" "$variant" <<'PY'
import bisect, json, math, sys
out, variant = sys.argv[1], sys.argv[2]
def load(name):
    return json.load(open(f"{out}/{name}.json"))
r, clean = load(variant), load("clean")
named = ", ".join(r.get("effects", [])) or "none"
if sorted(r.get("effects", [])) != sorted(clean.get("effects", [])):
    named += " (differs)"
ratio = r["rms_after_N"] / clean["rms_after_N"]
ratio_text = f"**{ratio:.3f}**" if ratio > 1.05 else f"{ratio:.3f}"
def residual_rows(name):
    return [list(map(float, l.split())) for l in open(f"{out}/{name}.plot/residual.dat") if l.strip() and not l.startswith("#")]
rows, clean_rows = residual_rows(variant), residual_rows("clean")
t0, t1 = rows[0][0], rows[-1][0]
# The unfaulted run's error on the samples this variant kept (nearest time): a gap that removes
# the run's hardest stretch lowers the error on what is left without the fit being any better.
clean_times = [x[0] for x in clean_rows]
def unfaulted_at(t):
    k = bisect.bisect_left(clean_times, t)
    near = min((j for j in (k - 1, k) if 0 <= j < len(clean_rows)), key=lambda j: abs(clean_times[j] - t))
    return clean_rows[near][7]
same = [unfaulted_at(x[0]) for x in rows if x[8] == 0]
kept = [x[7] for x in rows if x[8] == 0]
edge = [x[7] for x in rows if x[8] == 0 and (x[0] - t0 < 1.0 or t1 - x[0] < 1.0)]
mid = [x[7] for x in rows if x[8] == 0 and 1.0 <= x[0] - t0 and t1 - x[0] >= 1.0]
rms = lambda v: math.sqrt(sum(e * e for e in v) / len(v)) if v else float("nan")
aside = r["screening"]["excluded_samples"]
same_ratio = rms(kept) / rms(same)
same_text = f"**{same_ratio:.3f}**" if same_ratio > 1.05 else f"{same_ratio:.3f}"
print(f"| {variant} | {named} | {r['rms_after_N']:.4g} | {ratio_text} | {same_text} | {aside} | {rms(edge):.4g} | {rms(mid):.4g} |")
PY
  done < "$dir/variants"
done
