#!/usr/bin/env bash
# What a study's --plot wrote (mrd-identify compare, reproduce-paper): per STEM, the figures
# STEM_convergence.png and STEM_bh.png, each a PNG gnuplot drew, and their data with one curve per
# algorithm, in the order given: STEM_convergence.dat names ALGO_evaluations ALGO_best_fitness_T
# for each, STEM_bh.dat H_A_per_m B_T and then ALGO_B_T for each, and every row has those fields.
# usage: check_study_plots.sh DIR ALGO,ALGO... STEM...
set -euo pipefail
dir=$1
IFS=, read -ra algos <<<"$2"
shift 2
failed=0
fail() { echo "check_study_plots: $*" >&2; failed=1; }

# The data file's column line must be `expected`, and every row have as many fields.
check_data() {
  local file=$1 expected=$2
  [[ -s $file ]] || { fail "$file: missing or empty"; return; }
  local header
  header=$(head -n 1 "$file")
  [[ $header == "$expected" ]] || fail "$file: column line '$header', expected '$expected'"
  local fields=$(($(wc -w <<<"$expected") - 1))
  # The first row that differs is enough to say so.
  awk -v n="$fields" -v f="$file" 'NR > 1 && NF != n { printf "%s:%d: %d fields, expected %d\n", f, NR, NF, n; exit 1 }' \
    "$file" >&2 || failed=1
}

for stem in "$@"; do
  for figure in convergence bh; do
    png=$dir/${stem}_$figure.png
    if [[ $(head -c 4 "$png" 2>/dev/null | od -An -c | tr -d ' ') != '211PNG' ]]; then
      fail "$png: not a PNG"
    elif (($(stat -c %s "$png") < 1000)); then
      fail "$png: under 1000 bytes"
    fi
  done
  convergence="#" bh="# H_A_per_m B_T"
  for algo in "${algos[@]}"; do
    convergence+=" ${algo}_evaluations ${algo}_best_fitness_T"
    bh+=" ${algo}_B_T"
  done
  check_data "$dir/${stem}_convergence.dat" "$convergence"
  check_data "$dir/${stem}_bh.dat" "$bh"
done
((failed == 0)) || exit 1
echo "check_study_plots: $dir: ${#algos[@]} algorithm(s) in each figure of $*"
