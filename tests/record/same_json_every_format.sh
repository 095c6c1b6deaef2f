#!/usr/bin/env bash
# One run in every format (tests/record/data/formats: comma CSV; semicolons with decimal commas,
# CRLF and a byte-order mark; tabs; MATLAB v5 written byte by byte; v7.3) gives the same
# mrd-residual --json, byte for byte.
# usage: same_json_every_format.sh MRD_RESIDUAL DATA_DIR OUT_DIR [mrd-residual options...]
set -euo pipefail
residual=$1 data=$2 out=$3
shift 3
mkdir -p "$out"
text_columns=t=time_s,x=displacement_mm,F=force_N,I=current_A
mat_columns=t=time_s,data:1=displacement_mm,data:2=force_N,data:3=current_A
run() {  # run FILE COLUMNS [options...]
  local file=$1 columns=$2
  shift 2
  "$residual" "$data/$file" --columns "$columns" --json "$out/$file.json" --quiet "$@" >"$out/$file.txt"
}
run run.csv $text_columns "$@"
status=0
for file in run_semicolon.csv:$text_columns run_tab.tsv:$text_columns run_v5.mat:$mat_columns run_v73.mat:$mat_columns; do
  run "${file%%:*}" "${file#*:}" "$@"
  if cmp -s "$out/run.csv.json" "$out/${file%%:*}.json"; then
    echo "same JSON: ${file%%:*}"
  else
    echo "DIFFERENT JSON: ${file%%:*} (diff $out/run.csv.json $out/${file%%:*}.json)"
    status=1
  fi
done
exit $status
