#!/usr/bin/env python3
"""One independent-generator case for ctest: generate a run, analyse it with mrd-residual, assert.
  expect.py MRD_RESIDUAL OUT_DIR NAME PROFILE --effect E:S ... --named a,b --term NAME:VALUE:TOL
            --ambiguous a,b
--named lists the effects mrd-residual must name (empty: none); --term a discovered term whose
coefficient must lie within TOL (relative) of VALUE; without --term no term may be discovered on
a telegraph run; --ambiguous a group the JSON's "ambiguous" must hold (led by the one kept); --seed N draws a random
damper (damper_truth.py --damper random) for a run of --duration s; --no-terms asserts that no
damper term is discovered, whatever the profile."""
import argparse, json, os, subprocess, sys

here = os.path.dirname(os.path.abspath(__file__))
p = argparse.ArgumentParser()
p.add_argument("residual"); p.add_argument("out"); p.add_argument("name"); p.add_argument("profile")
p.add_argument("--effect", action="append", default=[])
p.add_argument("--named", default="")
p.add_argument("--term", action="append", default=[])
p.add_argument("--ambiguous", action="append", default=[])
p.add_argument("--seed", type=int)
p.add_argument("--duration", default="6")
p.add_argument("--no-terms", action="store_true")
a = p.parse_args()
os.makedirs(a.out, exist_ok=True)
csv, js = os.path.join(a.out, a.name + ".csv"), os.path.join(a.out, a.name + ".json")
gen = [sys.executable, os.path.join(here, "damper_truth.py"), "--profile", a.profile, "--duration", a.duration, "--out", csv]
if a.seed is not None: gen += ["--damper", "random", "--seed", str(a.seed)]
for e in a.effect: gen += ["--effect", e]
subprocess.run(gen, check=True)
subprocess.run([a.residual, csv, "--json", js], check=True, stdout=subprocess.DEVNULL)
r = json.load(open(js))
named = sorted(r["effects"]); want = sorted(n for n in a.named.split(",") if n)
ok = named == want
if not ok: print(f"named {named}, expected {want}")
terms = {t["term"]: t["coefficient"] for t in r["discovered"] if t["kind"] == "damper" or t["term"].startswith("line_")}
wanted_terms = {}
for spec in a.term:
    name, value, tol = spec.split(":"); wanted_terms[name] = (float(value), float(tol))
for name, (value, tol) in wanted_terms.items():
    got = terms.get(name)
    if got is None or abs(got - value) > tol * abs(value):
        print(f"term {name}: got {got}, expected {value} within {tol:.0%}"); ok = False
if not a.term and (a.profile == "telegraph" or a.no_terms) and terms:
    print(f"discovered {terms} on a run that carries no term"); ok = False
for group in a.ambiguous:
    if group.split(",") not in r["ambiguous"]:
        print(f"ambiguous {group} not reported (got {r['ambiguous']})"); ok = False
print(f"{a.name}: named {named}, discovered {terms}, RMS {r['rms_before_N']:.4g} -> {r['rms_after_N']:.4g} N")
sys.exit(0 if ok else 1)
