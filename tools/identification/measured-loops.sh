#!/usr/bin/env bash
# Fits every measured loop set in data/bh-loops with every algorithm over several seeds and
# writes the measured-loop table of docs/IDENTIFICATION.md, with the author's published
# Mn-Zn ferrite fit evaluated by the same objective.
#   tools/identification/measured-loops.sh [BUILD_DIR] [SEEDS] > table.md
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build/release}
seeds=${2:-5}
identify=$build/tools/mrd-identify
data=$here/data/bh-loops/szewczyk-jamodel

for material in MnZn_ferrite MnZn_HP_ferrite M130_27s amorf; do
  file=$data/${material}_loops.csv
  echo "### ${material}"
  echo
  n=$seeds
  # k of about 1 A/m over an 800 A/m loop: one evaluation costs 20x the others.
  if [[ $material == amorf && $n -gt 3 ]]; then n=3; fi
  "$identify" compare --seeds "$n" "$file"
  echo
done

author=$(tail -n 1 "$data/MnZn_ferrite_JA_params_author.csv" | awk -F, '{print $4","$1","$5","$2","$3}')
echo "### The author's Mn-Zn ferrite fit, evaluated by our model and objective"
echo
echo '```'
"$identify" evaluate "$data/MnZn_ferrite_loops.csv" "$author" 2>&1
echo '```'
