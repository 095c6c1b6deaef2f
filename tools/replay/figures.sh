#!/usr/bin/env bash
# The figures and tables of docs/CLOSING-THE-LOOP.md: mrd-replay with the default config on
# Dyke's run, on every Quiroz sine test, on Quiroz's validation record at its five currents, and
# on a candump log written from one of the sine tests.
#   tools/replay/figures.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build/release}
out=${2:-$here/docs/figures/closing-the-loop}
replay=$build/tools/mrd-replay
cd "$here"  # relative file names in the reports and plots
data=data/damper
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# "| name | RMS | max | range | NRMSE |" from a summary's force error line.
row() {
  awk -v name="$1" '/^force error \(measured/ {
    gsub(/[,;()]/, " "); for (i = 1; i <= NF; ++i) {
      if ($i == "RMS" && rms == "") rms = $(i + 1); if ($i == "max") max = $(i + 1);
      if ($i == "NRMSE") nrmse = $(i + 1); if ($i == "range") range = $(i + 1) }
    printf "| %s | %s | %s | %s | %s |\n", name, rms, max, range, nrmse }'
}

echo "## Dyke, ranran_50.csv"
"$replay" "$data/dyke-nees-prototype/ranran_50.csv" --columns t=time_s,D=displacement_cm,Y=voltage_V,F=force_N \
  --amps-per-volt 0.5 --plot "$work/dyke" --json "$out/dyke.json" | tee "$work/dyke.txt"
"$replay" "$data/dyke-nees-prototype/ranran_50.csv" --columns t=time_s,D=displacement_cm,Y=voltage_V,V=velocity_cm_s,F=force_N \
  --amps-per-volt 0.5 --recorded-velocity > "$work/dyke_v.txt"
for f in force_displacement residual current; do cp "$work/dyke/replay_$f.png" "$out/dyke_$f.png"; done
echo
echo "| run | RMS [N] | max [N] | measured range [N] | NRMSE |"
echo "| --- | ---: | ---: | ---: | ---: |"
row "ranran_50, velocity filter" < "$work/dyke.txt"
row "ranran_50, recorded velocity V" < "$work/dyke_v.txt"

echo
echo "## Quiroz sine tests, current from the file name"
sine=(--columns 1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N --current-from-name)
"$replay" "$data/quiroz-utfsm/sine/25mm0x25Hz0x5A.txt" "${sine[@]}" --plot "$work/quiroz" \
  --json "$out/quiroz_25mm0x25Hz0x5A.json" | tee "$work/quiroz.txt"
for f in force_displacement residual current; do cp "$work/quiroz/replay_$f.png" "$out/quiroz_$f.png"; done
echo
echo "| file | RMS [N] | max [N] | measured range [N] | NRMSE |"
echo "| --- | ---: | ---: | ---: | ---: |"
for file in "$data"/quiroz-utfsm/sine/*.txt; do
  "$replay" "$file" "${sine[@]}" | row "$(basename "$file" .txt)"
done

echo
echo "## Quiroz validation record, 1 kHz, one replay per current"
echo
echo "| current | RMS [N] | max [N] | measured range [N] | NRMSE |"
echo "| --- | ---: | ---: | ---: | ---: |"
for current in 0p2 0p4 0p6 0p8 1p0; do
  "$replay" "$data/quiroz-utfsm/validation.csv" --columns "x_mm=displacement_mm,F_${current}A_N=force_N" \
    --current "${current/p/.}" --sample-rate 1000 | row "${current/p/.} A"
done

echo
echo "## A candump log written from a sine test, replayed"
"$replay" "$data/quiroz-utfsm/sine/5mm3Hz0x75A.txt" "${sine[@]}" --write-candump "$work/5mm3Hz0x75A.log" > /dev/null
head -4 "$work/5mm3Hz0x75A.log"
"$replay" "$work/5mm3Hz0x75A.log"
echo "figures in $out"
