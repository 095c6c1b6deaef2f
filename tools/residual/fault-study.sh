#!/usr/bin/env bash
# Sensor faults injected into clean and measured runs (docs/CLOSING-THE-LOOP.md, "Screening"):
# each run is analysed unfaulted, faulted with screening (the default) and faulted with
# --no-screening. With screening the fit should match the unfaulted run's within a few per cent.
# Usage: tools/residual/fault-study.sh [BUILD_DIR] [OUT_DIR]   (needs python3 with numpy; about
# 7 min, Dyke's run is 4 of them)
set -euo pipefail
build=${1:-build/release}
out=${2:-out/fault-study}
mkdir -p "$out"
"$build/tools/simulation/mrd-simulate-run" --damper 1kN --profile table4 --duration 10 --csv "$out/sim-1kN-table4.csv" > /dev/null
# The independent generator's run (its own forms, numpy) with a field lag to find through the faults.
"${MRD_PYTHON:-/usr/bin/python3}" tests/generator/damper_truth.py --profile telegraph --duration 6 --effect coil_lag:2 \
  --out "$out/indep-coil_lag.csv"
python3 - "$out" data/damper/quiroz-utfsm/sine <<'PY'
import csv, math, random, sys
out, quiroz = sys.argv[1], sys.argv[2]
def own(name, rows, header):
    with open(f"{out}/{name}.csv", "w", newline="") as f:
        w = csv.writer(f); w.writerow(header); w.writerows(rows)
# Quiroz's constant-current tests into the project's format (the current from the file name).
for stem, amps in (("5mm3Hz0x75A", 0.75), ("25mm0x25Hz1A", 1.0)):
    rows = [[float(v) for v in line.split()[:4]] + [amps] for line in open(f"{quiroz}/{stem}.txt") if line.strip()]
    own(f"quiroz-{stem}", rows, ["time_s", "displacement_mm", "velocity_mm_s", "force_N", "current_A"])
def load(name):
    rows = list(csv.reader(open(f"{out}/{name}.csv")))
    return rows[0], [list(map(float, r)) for r in rows[1:]]
rng = random.Random(7)
for name in ("sim-1kN-table4", "quiroz-5mm3Hz0x75A", "quiroz-25mm0x25Hz1A", "indep-coil_lag"):
    h, rows = load(name)
    t, x, F = h.index("time_s"), h.index("displacement_mm"), h.index("force_N")
    end = rows[-1][t]
    # The last 0.5 s: the load cell saturates at 80 % of the force it saw there, the LVDT sticks.
    tail = [r for r in rows if r[t] >= end - 0.5]
    scale = 0.8 * max(abs(r[F]) for r in tail)
    faulted = [list(r) for r in rows]
    stuck = None
    for r in faulted:
        if r[t] >= end - 0.5:
            stuck = r[x] if stuck is None else stuck
            r[F] = max(-scale, min(scale, r[F])); r[x] = stuck
    own(f"{name}-clip-stuck", faulted, h)
    # Spikes: five on the force (half its range), three on the LVDT (a fifth of its range).
    faulted = [list(r) for r in rows]
    Fr = max(r[F] for r in rows) - min(r[F] for r in rows)
    xr = max(r[x] for r in rows) - min(r[x] for r in rows)
    for i in rng.sample(range(10, len(rows) - 10), 5): faulted[i][F] += 0.5 * Fr
    for i in rng.sample(range(10, len(rows) - 10), 3): faulted[i][x] -= 0.2 * xr
    own(f"{name}-spikes", faulted, h)
    # A gap: 50 samples lost in the middle.
    mid = len(rows) // 2
    own(f"{name}-gap", rows[:mid] + rows[mid + 50:], h)
PY
# Dyke's run keeps its own format (quoted header, fs on row 1 only, a trailing comma): its lines
# are copied as text and only D (displacement, cm) and F (force, N) are changed.
python3 - "$out" data/damper/dyke-nees-prototype/ranran_50.csv <<'PY'
import random, sys
out, source = sys.argv[1], sys.argv[2]
lines = open(source).read().splitlines()
header, body = lines[0], [l.split(",") for l in lines[1:] if l.strip()]
names = [h.strip('"') for h in header.split(",")]
t, x, F = names.index("t"), names.index("D"), names.index("F")
def write(name, rows):
    with open(f"{out}/{name}.csv", "w") as f:
        f.write(header + "\n" + "\n".join(",".join(r) for r in rows) + "\n")
write("dyke-ranran_50", body)
end = float(body[-1][t])
rows = [list(r) for r in body]
tail = [r for r in rows if float(r[t]) >= end - 0.5]
scale = 0.8 * max(abs(float(r[F])) for r in tail)
stuck = None
for r in rows:
    if float(r[t]) >= end - 0.5:
        stuck = r[x] if stuck is None else stuck
        r[F] = repr(max(-scale, min(scale, float(r[F])))); r[x] = stuck
write("dyke-ranran_50-clip-stuck", rows)
rng = random.Random(7)
rows = [list(r) for r in body]
Fs, xs = [float(r[F]) for r in body], [float(r[x]) for r in body]
for i in rng.sample(range(10, len(rows) - 10), 5): rows[i][F] = repr(float(rows[i][F]) + 0.5 * (max(Fs) - min(Fs)))
for i in rng.sample(range(10, len(rows) - 10), 3): rows[i][x] = repr(float(rows[i][x]) - 0.2 * (max(xs) - min(xs)))
write("dyke-ranran_50-spikes", rows)
mid = len(body) // 2
write("dyke-ranran_50-gap", body[:mid] + body[mid + 50:])
PY
echo "| run | fault | screening | set aside | named | RMS before [N] | RMS after [N] |"
echo "|---|---|---|---:|---|---:|---:|"
dyke_columns=(--columns t=time_s,D=displacement_cm,Y=voltage_V,F=force_N,V=velocity_cm_s --amps-per-volt 0.5)
for base in sim-1kN-table4 indep-coil_lag quiroz-5mm3Hz0x75A quiroz-25mm0x25Hz1A dyke-ranran_50; do
  format=(); [[ $base == dyke-* ]] && format=("${dyke_columns[@]}")
  for fault in "" -clip-stuck -spikes -gap; do
    for mode in on off; do
      [[ -z $fault && $mode == off ]] && continue
      flag=(); [[ $mode == off ]] && flag=(--no-screening)
      name="$base$fault-$mode"
      "$build/tools/mrd-residual" "$out/$base$fault.csv" "${format[@]}" "${flag[@]}" --json "$out/$name.json" \
        > "$out/$name.txt"
      python3 - "$out/$name.json" "$base" "${fault#-}" "$mode" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"| {sys.argv[2]} | {sys.argv[3] or 'none'} | {sys.argv[4]} | {r['screening']['excluded_samples']} | "
      f"{', '.join(r['effects']) or 'none'} | {r['rms_before_N']:.4g} | {r['rms_after_N']:.4g} |")
PY
    done
  done
done
