#!/usr/bin/env bash
# mrd-residual on RANDOM dampers of the independent truth generator (damper_truth.py --damper
# random: core, coil, yield law, sign shape, fluid and size drawn per seed, 1-100 kN): how far
# above the load cell's noise the fitted model's error stays on a damper it was not built for,
# and whether it names what is not there or misses what is. Prints a Markdown table and a summary;
# the runs, manifests (*.truth.json), JSON and residual traces (*.plot/residual.dat) go to OUT_DIR.
#   clean runs   seeds 1..N_CLEAN, profiles table4, random, mixed in turn;
#   single runs  seeds 101.., one effect of size 2 each, cycling coil_lag gas_spring sensor_delay
#                preyield_hysteresis stroke_end_air thermal_drift; coil_lag on the random profile
#                (its current steps), the others on table4, then mixed on the next pass;
#   pairs        seeds 201.., N_PAIRS pairs of those effects (random profile when coil_lag is one).
# The floor ratio is rms_after_N / the truth's noise sigma (1 is a perfect fit); "interior" is the
# same away from the run's first and last 0.5 s (from the residual trace --plot writes).
# 8 s at 1 kHz per run. Needs python3 with numpy.
# Usage: tests/generator/random-damper-study.sh [BUILD_DIR] [OUT_DIR] [N_CLEAN] [N_SINGLE] [N_PAIRS]
#   defaults: build/release out/random-damper 12 12 0; MRD_THREADS sets mrd-residual --threads,
#   MRD_RESIDUAL_ARGS adds options (e.g. "--robust-fit").
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build/release}
out=${2:-out/random-damper}
n_clean=${3:-12}
n_single=${4:-12}
n_pairs=${5:-0}
python=${MRD_PYTHON:-/usr/bin/python3}
residual="$build/tools/mrd-residual"
threads=()
[[ -n ${MRD_THREADS:-} ]] && threads=(--threads "$MRD_THREADS")
read -r -a extra <<< "${MRD_RESIDUAL_ARGS:-}"
if [[ ! -x $residual ]]; then
  echo "random-damper-study: no $residual (build mrd-residual first)" >&2
  exit 2
fi
mkdir -p "$out"
rows="$out/rows.jsonl"
: > "$rows"
echo "| run | seed | profile | damper | truth | named | rms_after [N] | noise [N] | floor ratio | interior |"
echo "|---|---:|---|---|---|---|---:|---:|---:|---:|"
run() {  # KIND NAME SEED PROFILE EFFECT...   (KIND: clean, single or pair)
  local kind=$1 name=$2 seed=$3 profile=$4; shift 4
  local args=() status=0
  for e in "$@"; do args+=(--effect "$e"); done
  rm -rf "$out/$name.json" "$out/$name.plot"
  if ! "$python" "$here/damper_truth.py" --damper random --seed "$seed" --profile "$profile" --duration 8 \
      "${args[@]}" --out "$out/$name.csv" --manifest "$out/$name.truth.json" 2> "$out/$name.gen.err"; then
    status=gen
  else
    "$residual" "$out/$name.csv" --quiet "${threads[@]}" "${extra[@]}" --json "$out/$name.json" --plot "$out/$name.plot" \
      > "$out/$name.txt" 2> "$out/$name.err" || status=$?
  fi
  "$python" - "$out" "$name" "$kind" "$seed" "$profile" "$status" "$rows" "$@" <<'PY'
import json, math, os, sys
out, name, kind, seed, profile, status, rows = sys.argv[1:8]
truth = sys.argv[8:]
row = dict(run=name, kind=kind, truth=[e.split(":")[0] for e in truth])
cells = [name, seed, profile]
try:
    m = json.load(open(os.path.join(out, name + ".truth.json")))
    d = m["damper"]
    law = f"power p={d['p']:.2f}" if d["yield_law"] == "power" else "tanh"
    cells.append(f"{d['material'].split('_')[0]}, {law}, {d['sign']} {1e3 * d['v0_m_s']:.1f} mm/s, "
                 f"n={d['n']:.2f}, {d['F_max_N'] / 1e3:.3g} kN")
    noise = m["force_noise_N"]
except (OSError, ValueError, KeyError):
    cells.append("?"); noise = float("nan")
cells.append(" ".join(truth) or "none")
r = None
if status == "0":
    try:
        r = json.load(open(os.path.join(out, name + ".json")))
        after = float(r["rms_after_N"])
    except (OSError, ValueError, KeyError, TypeError):
        status, r = "0, no readable JSON", None
if r is None:
    why = "generator failed" if status == "gen" else f"failed (exit {status})"
    print("| " + " | ".join(cells + [why, "", f"{noise:.4g}", "", ""]) + " |")
    row["failed"] = True
else:
    # Residual after the fit away from the run's edges: residual.dat's t (col 1), residual after
    # (col 8) and excluded flag (col 9); absent when the plot step wrote nothing.
    interior = float("nan")
    try:
        sq, count, t_end = 0.0, 0, 0.0
        data = [line.split() for line in open(os.path.join(out, name + ".plot", "residual.dat"))]
        t_end = float(data[-1][0])
        for c in data:
            if 0.5 <= float(c[0]) <= t_end - 0.5 and c[8] == "0":
                sq += float(c[7]) ** 2; count += 1
        interior = math.sqrt(sq / count) / noise if count else float("nan")
    except (OSError, IndexError, ValueError):
        pass
    named = r["effects"]
    terms = [t["term"] for t in r.get("discovered", []) if t.get("kind") == "damper"]
    shown = ", ".join(named) or "none"
    if terms:
        shown += " (terms: " + ", ".join(terms) + ")"
    print("| " + " | ".join(cells + [shown, f"{after:.4g}", f"{noise:.4g}", f"{after / noise:.3g}",
                                     f"{interior:.3g}"]) + " |")
    row.update(named=named, terms=terms, floor=after / noise, interior=interior)
with open(rows, "a") as f:
    f.write(json.dumps(row) + "\n")
PY
}
profiles=(table4 random mixed)
for ((i = 1; i <= n_clean; ++i)); do
  p=${profiles[(i - 1) % 3]}
  run clean "clean-$i-$p" "$i" "$p"
done
effects=(coil_lag gas_spring sensor_delay preyield_hysteresis stroke_end_air thermal_drift)
for ((j = 0; j < n_single; ++j)); do
  e=${effects[j % ${#effects[@]}]}
  p=table4
  (( (j / ${#effects[@]}) % 2 == 1 )) && p=mixed
  [[ $e == coil_lag ]] && p=random
  run single "$e-$((101 + j))" "$((101 + j))" "$p" "$e:2"
done
pairs=()
for ((i = 0; i < ${#effects[@]}; ++i)); do
  for ((j = i + 1; j < ${#effects[@]}; ++j)); do pairs+=("${effects[i]} ${effects[j]}"); done
done
for ((j = 0; j < n_pairs; ++j)); do
  read -r a b <<< "${pairs[j % ${#pairs[@]}]}"
  p=table4
  [[ $a == coil_lag || $b == coil_lag ]] && p=random
  run pair "$a+$b-$((201 + j))" "$((201 + j))" "$p" "$a:2" "$b:2"
done
"$python" - "$rows" <<'PY'
import json, math, statistics, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
def of(kind): return [r for r in rows if r["kind"] == kind]
def figures(values):
    values = [v for v in values if not math.isnan(v)]
    return f"median {statistics.median(values):.3g}, max {max(values):.3g}" if values else "none"
clean, single, pair = of("clean"), of("single"), of("pair")
ok = lambda rs: [r for r in rs if not r.get("failed")]  # noqa: E731
failed = sum(1 for r in rows if r.get("failed"))
print()
print(f"clean: {len(clean)} runs, floor ratio {figures([r['floor'] for r in ok(clean)])} "
      f"(interior {figures([r['interior'] for r in ok(clean)])}); "
      f"{sum(1 for r in ok(clean) if r['named'])} named an effect, "
      f"{sum(1 for r in ok(clean) if r['terms'])} discovered a damper term.")
for label, rs in (("single", single), ("pair", pair)):
    if not rs:
        continue
    hit = sum(1 for r in ok(rs) if set(r["truth"]) <= set(r["named"]))
    wrong = sum(1 for r in ok(rs) if set(r["named"]) - set(r["truth"]))
    print(f"{label}: {len(rs)} runs, all truth named in {hit}, a wrong name in {wrong}; "
          f"floor ratio {figures([r['floor'] for r in ok(rs)])}.")
print(f"failed runs: {failed}.")
PY
