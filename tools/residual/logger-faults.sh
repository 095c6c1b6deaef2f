#!/usr/bin/env bash
# Logger faults injected into one simulated run (issue 27's table in docs/CLOSING-THE-LOOP.md,
# "Data as loggers write it"): the run without its velocity column (so the zero-phase velocity and
# its record edges are in play), then the same with a gap of 0.05 s, 0.3 s and 2 s, 1 % of its rows
# written twice, 5 empty cells, 3 rows whose time goes back, and each sample taken up to 10 % or
# 30 % of a period off its grid time (picked from a 10 kHz simulation; the clean run is its every
# 10th sample, so all variants share one noise), and a rig at its end stop (0.36 s of a still LVDT
# under a ringing, clipped load cell: implausible). Prints, per variant, the effects
# named, the RMS after on the kept samples, and that RMS in the first and last second against the
# rest (from the residual trace --plot writes).
# Usage: tools/residual/logger-faults.sh [BUILD_DIR] [OUT_DIR] [EFFECT]   (default effect gas_spring)
set -euo pipefail
build=${1:-build/release}
out=${2:-out/logger-faults}
effect=${3:-gas_spring}
python=${MRD_PYTHON:-/usr/bin/python3}
mkdir -p "$out"
"$build/tools/simulation/mrd-simulate-run" --profile table4 --damper 1kN --duration 12 --effect "$effect" \
  --rate 10000 --csv "$out/simulated.csv" > /dev/null
"$python" - "$out" <<'PY'
import csv, math, random, sys
out = sys.argv[1]
rows = list(csv.reader(open(f"{out}/simulated.csv")))
header, fine = rows[0], rows[1:]
data = fine[::10]
keep = [i for i, h in enumerate(header) if not h.startswith("velocity")]
header = [header[i] for i in keep]
data = [[r[i] for i in keep] for r in data]
def write(name, rows):
    with open(f"{out}/{name}.csv", "w", newline="") as f:
        w = csv.writer(f); w.writerow(header); w.writerows(rows)
write("clean", data)
n = len(data); rate = round((n - 1) / (float(data[-1][0]) - float(data[0][0])))
for seconds in (0.05, 0.3, 2.0):
    a = n // 2; b = a + int(seconds * rate)
    write(f"gap_{seconds:g}s", data[:a] + data[b:])
rng = random.Random(5)
twice = set(rng.sample(range(n), n // 100))
write("duplicates_1pc", [r for i, r in enumerate(data) for _ in range(2 if i in twice else 1)])
empty = data[:]
for i in rng.sample(range(10, n - 10), 5):
    empty[i] = empty[i][:]; empty[i][1] = ""
write("empty_cells_5", empty)
back = data[:]
for i in rng.sample(range(10, n - 10), 3):
    back[i] = back[i][:]; back[i][0] = repr(float(back[i - 5][0]))
write("time_back_3", back)
keep_fine = [[r[i] for i in keep] for r in fine]
for percent in (10, 30):
    picked, last = [], -1
    for i in range(0, len(fine), 10):
        j = min(max(i + rng.randint(-percent // 10, percent // 10), last + 1), len(fine) - 1)
        picked.append(keep_fine[j]); last = j
    write(f"jitter_{percent}pc", picked)
# A rig at its end stop for 0.36 s from 6 s: the LVDT jitters within 0.5 % of the stroke while
# the load cell rings at 25 Hz through both signs and clips at the run's peak force.
xs = [float(r[1]) for r in data]; fs = [float(r[3]) for r in data]
stroke, peak = max(xs) - min(xs), max(abs(f) for f in fs)
stop = [r[:] for r in data]
first = next(i for i, r in enumerate(data) if float(r[0]) >= 6.0)
for i in range(first, n):
    t = float(data[i][0]) - 6.0
    if t > 0.36: break
    stop[i][1] = repr(xs[first] + 0.005 * stroke * (2.0 * rng.random() - 1.0))
    stop[i][3] = repr(max(-peak, min(peak, 1.2 * peak * math.cos(2.0 * math.pi * 25.0 * t))))
write("end_stop_ringing", stop)
PY
echo "| run | named | rms_after [N] | set aside | first and last 1 s [N] | in between [N] |"
echo "|---|---|---:|---:|---:|---:|"
for variant in clean gap_0.05s gap_0.3s gap_2s duplicates_1pc empty_cells_5 time_back_3 jitter_10pc jitter_30pc end_stop_ringing; do
  "$build/tools/mrd-residual" "$out/$variant.csv" --json "$out/$variant.json" --plot "$out/$variant.plot" \
    > "$out/$variant.txt" 2> "$out/$variant.err" || { echo "| $variant | failed: $(tail -1 "$out/$variant.err") |"; continue; }
  "$python" - "$out" "$variant" <<'PY'
import json, math, sys
out, variant = sys.argv[1], sys.argv[2]
r = json.load(open(f"{out}/{variant}.json"))
named = ", ".join(r.get("effects", [])) or "none"
rows = [list(map(float, l.split())) for l in open(f"{out}/{variant}.plot/residual.dat") if l.strip() and not l.startswith("#")]
t0, t1 = rows[0][0], rows[-1][0]
edge = [x[7] for x in rows if x[8] == 0 and (x[0] - t0 < 1.0 or t1 - x[0] < 1.0)]
mid = [x[7] for x in rows if x[8] == 0 and 1.0 <= x[0] - t0 and t1 - x[0] >= 1.0]
rms = lambda v: math.sqrt(sum(e * e for e in v) / len(v)) if v else float("nan")
aside = r["screening"]["excluded_samples"]
print(f"| {variant} | {named} | {r['rms_after_N']:.4g} | {aside} | {rms(edge):.4g} | {rms(mid):.4g} |")
PY
done
