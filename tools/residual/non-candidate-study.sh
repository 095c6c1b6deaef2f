#!/usr/bin/env bash
# Runs that carry an effect that is not a candidate (docs/CLOSING-THE-LOOP.md): a clean simulated
# run with a force added after the fact, then mrd-residual. What must not happen is a candidate
# claimed for it; what should happen is a description of the structure left.
# Usage: tools/residual/non-candidate-study.sh [BUILD_DIR] [OUT_DIR]   (needs python3)
# MRD_RESIDUAL_ARGS: more options for every mrd-residual (e.g. --terms-beside-base).
set -euo pipefail
build=${1:-build/release}
out=${2:-out/non-candidate}
mkdir -p "$out"
simulate="$build/tools/simulation/mrd-simulate-run"
"$simulate" --damper 1kN --profile telegraph --csv "$out/1kN-telegraph.csv" > /dev/null
"$simulate" --damper 50kN --profile table4 --csv "$out/50kN-table4.csv" > /dev/null
"$simulate" --damper 1kN --profile table4 --csv "$out/1kN-table4.csv" > /dev/null
python3 - "$out" <<'PY'
import csv, math, sys
out = sys.argv[1]
def load(name):
    rows = list(csv.reader(open(f"{out}/{name}.csv")))
    return rows[0], [list(map(float, r)) for r in rows[1:]]
def write(name, header, rows):
    w = csv.writer(open(f"{out}/{name}.csv", "w")); w.writerow(header); w.writerows(rows)
def add(source, name, extra_N):
    h, rows = load(source)
    col = {k: h.index(k) for k in h}
    n = len(rows); dt = rows[1][col["time_s"]] - rows[0][col["time_s"]]
    def accel(i):  # m/s^2 from the velocity column
        v = col["velocity_mm_s"]
        return (rows[min(i + 1, n - 1)][v] - rows[max(i - 1, 0)][v]) / 1000.0 / (2 * dt)
    result = []
    for i, r in enumerate(rows):
        r2 = list(r); r2[col["force_N"]] += extra_N(r, col, accel(i)); result.append(r2)
    write(name, h, result)
# Inertia of a moving mass: 50 kg on the 1 kN class, 2 t on the 50 kN class.
add("1kN-telegraph", "inertia-1kN-telegraph", lambda r, c, a: 50.0 * a)
add("50kN-table4", "inertia-50kN-table4", lambda r, c, a: 2000.0 * a)
# Coulomb friction of the seals, 40 N.
add("1kN-telegraph", "friction-1kN-telegraph", lambda r, c, a: 40.0 * math.tanh(r[c["velocity_mm_s"]] / 1.0))
# Mains hum on the load cell, 300 N at 50 Hz.
add("50kN-table4", "hum-50kN-table4", lambda r, c, a: 300.0 * math.sin(2 * math.pi * 50 * r[c["time_s"]]))
# Viscosity rising with the field (Spencer's c0b): +50 % at the class's largest current.
add("50kN-table4", "field-viscosity-50kN-table4",
    lambda r, c, a: 0.5 * 53.0e3 * (r[c["current_A"]] / 1.2) * r[c["velocity_mm_s"]] / 1000.0)
# A cubic bump stop: 100 N at the 20 mm stroke.
add("1kN-table4", "bump-stop-1kN-table4", lambda r, c, a: 100.0 * (r[c["displacement_mm"]] / 20.0) ** 3)
PY
echo "| run | added | named | discovered | RMS before [N] | RMS after [N] | what remains |"
echo "|---|---|---|---|---:|---:|---|"
for name in inertia-1kN-telegraph inertia-50kN-table4 friction-1kN-telegraph hum-50kN-table4 \
            field-viscosity-50kN-table4 bump-stop-1kN-table4; do
  "$build/tools/mrd-residual" "$out/$name.csv" ${MRD_RESIDUAL_ARGS:-} --json "$out/$name.json" > "$out/$name.txt"
  python3 - "$out/$name.json" "$name" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
terms = ', '.join(f"{t['term']} {t['coefficient']:.4g} {t['unit']}" + (" (interference)" if t['kind'] == 'interference' else "")
                  for t in r.get('discovered', [])) or 'none'
alike = '; '.join(' ~ '.join(g) for g in r.get('ambiguous', []))
if alike: terms += f"; ambiguous: {alike}"
print(f"| {sys.argv[2]} | | {', '.join(r['effects']) or 'none'} | {terms} | {r['rms_before_N']:.4g} | {r['rms_after_N']:.4g} | {r['unexplained']} |")
PY
done
