#!/usr/bin/env bash
# The example fit reports of docs/IDENTIFICATION.md and docs/CLOSING-THE-LOOP.md, "Fit report":
# mrd-identify on a measured ferrite (kept whole in docs/figures/report/identify, small enough
# to commit) and mrd-residual on one of Quiroz's sine tests (a screenshot of its report in
# headless Chromium; the report itself is written to OUT_DIR).
# Usage: tools/report/example.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/report}
figures=docs/figures/report
mkdir -p "$out" "$figures"

rm -rf "$figures/identify"
mkdir -p "$figures/identify"
"$build/tools/mrd-identify" fit data/bh-loops/szewczyk-jamodel/MnZn_ferrite_loops.csv --evaluations 3000 --polish \
  --seed 1 --json "$figures/identify/identify.json" --report "$figures/identify" \
  --write-config "$out/identified.toml"

"$build/tools/mrd-residual" data/damper/quiroz-utfsm/sine/5mm3Hz0x75A.txt \
  --columns 1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N --current-from-name --threads 2 \
  --json "$out/residual.json" --report "$out/residual"

# The plots are inline in report.html; each NAME.gp redraws its NAME.svg.
rm -f "$figures/identify/"*.svg

# Debian's chromium-headless-shell (what scripts/install-deps.sh installs), or a full chromium.
browser=$(command -v chromium-headless-shell || command -v chromium || true)
if [[ -n $browser ]]; then
  for pair in "$figures/identify/report.html:$figures/identify-report.png:1100,1500" \
              "$out/residual/report.html:$figures/residual-report.png:1100,2200"; do
    IFS=: read -r page png size <<<"$pair"
    "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$size" \
      --screenshot="$png" "file://$(realpath "$page")" 2>/dev/null
  done
fi
