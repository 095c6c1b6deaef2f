#!/usr/bin/env bash
# The figures of docs/IDENTIFICATION.md:
#  - Figure 7/8 analogues on the paper's Table 1 set (40 A/m loop, search +-100% around the
#    truth): the B-H fits of pso and improved-pso over the generated curve, and both convergence
#    curves (mrd-identify reproduce-paper --plot);
#  - the measured Mn-Zn ferrite loops fitted from the file alone, with the LM polish.
#   tools/identification/figures.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build/release}
out=${2:-$here/docs/figures/identification}
identify=$build/tools/mrd-identify
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# Both swarms' seed-1 runs of the Section 4.1 protocol, drawn by the tool itself (tools/plot); of
# its figures for the two known sets, the Table 1 set's are the docs'.
"$identify" reproduce-paper --seeds 1 --algos pso,improved-pso --table1-amplitude 40 --quiet \
  --plot "$work/paper"
cp "$work/paper/table1_convergence.png" "$out/table1_convergence.png"
cp "$work/paper/table1_bh.png" "$out/table1_bh.png"

"$identify" fit "$here/data/bh-loops/szewczyk-jamodel/MnZn_ferrite_loops.csv" --polish --seed 1 \
  --plot "$work/ferrite"
cp "$work/ferrite/identify_bh.png" "$out/ferrite_bh.png"
cp "$work/ferrite/identify_convergence.png" "$out/ferrite_convergence.png"
echo "figures in $out"
