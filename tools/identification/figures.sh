#!/usr/bin/env bash
# The figures of docs/IDENTIFICATION.md:
#  - Figure 7/8 analogues on the paper's Table 1 set (40 A/m loop, search +-100% around the
#    truth): fitted-over-measured B-H of pso and improved-pso, and both convergence curves;
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

truth=1.3e6,25.3,8.43e-5,66.6,0.2
"$identify" synthetic "$work/table1.csv" --truth "$truth" --H-max 40 --points 1000
for algo in pso improved-pso; do
  "$identify" fit "$work/table1.csv" --start "$truth" --algo "$algo" --seed 1 --plot "$work/$algo" \
    > "$work/$algo.txt"
  cat "$work/$algo.txt"
done
# Two tools' runs on one figure, so drawn here, in the house style of tools/plot (noenhanced
# text, the key below the data, the generated curve on top).
gnuplot <<GP
set terminal pngcairo size 900,600 noenhanced font ',10'
set key outside below; set grid; set format y '%g'
set output '$out/table1_convergence.png'
set title 'Paper Table 1 set, 40 A/m loop, +-100% box: best fitness against evaluations (Figure 8)'
set xlabel 'evaluations'; set ylabel 'RMSE of B [T] (Eq. 15)'; set logscale y
plot '$work/pso/identify_convergence.dat' using 1:2 with steps lw 2 title 'classical PSO', \
     '$work/improved-pso/identify_convergence.dat' using 1:2 with steps lw 2 title 'improved PSO'
set output '$out/table1_bh.png'
unset logscale y
set title 'Paper Table 1 set, 40 A/m loop: generated curve and the two fits (Figure 7)'
set xlabel 'H [A/m]'; set ylabel 'B [T]'
plot '$work/pso/identify_bh.dat' using 1:3 with lines lw 2 title 'classical PSO', \
     '$work/improved-pso/identify_bh.dat' using 1:3 with lines lw 2 dt 2 title 'improved PSO', \
     '$work/improved-pso/identify_bh.dat' using 1:2 with points pt 7 ps 0.3 lc rgb 'black' title 'generated'
GP

"$identify" fit "$here/data/bh-loops/szewczyk-jamodel/MnZn_ferrite_loops.csv" --polish --seed 1 \
  --plot "$work/ferrite"
cp "$work/ferrite/identify_bh.png" "$out/ferrite_bh.png"
cp "$work/ferrite/identify_convergence.png" "$out/ferrite_convergence.png"
echo "figures in $out"
