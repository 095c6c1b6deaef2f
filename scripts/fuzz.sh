#!/usr/bin/env bash
# Runs every libFuzzer target (fuzz/) for a while: scripts/fuzz.sh [seconds-per-target] [target...]
# Builds the `fuzz` preset (clang) first. Each target starts from its seed corpus in
# fuzz/corpus/<target> (left untouched) and grows a working copy in build/fuzz/corpus/<target>;
# crashes, leaks and timeouts land in build/fuzz/artifacts/<target>/ and fail the script.
# FUZZ_JOBS=2 runs two targets at a time (each fuzzer is one process on one core).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-30}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(run_csv run_mat candump config can_codec register_codec bh_curve)
jobs=${FUZZ_JOBS:-1}

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j2

out=build/fuzz
run_one() {
  local t=$1 corpus=$out/corpus/$1 artifacts=$out/artifacts/$1/
  mkdir -p "$corpus" "$artifacts" "$out/logs"
  local dict=()
  [[ -f fuzz/dict/$t.dict ]] && dict=(-dict="fuzz/dict/$t.dict")
  # Leak checking is on (ASan's default under libFuzzer); an input slower than 10 s is a hang.
  "$out/fuzz/fuzz_$t" "$corpus" "fuzz/corpus/$t" "${dict[@]}" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts" \
    >"$out/logs/$t.log" 2>&1
}

summary() {
  local t=$1 status=$2 log=$out/logs/$1.log
  local execs cov ft corpus
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2 || true)
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | cut -d' ' -f2 || true)
  corpus=$(find "$out/corpus/$t" -type f | wc -l)
  printf '%-15s %6ss %12s execs  cov %-6s ft %-6s corpus %-6s %s\n' "$t" "$seconds" "${execs:-?}" \
    "${cov:-?}" "${ft:-?}" "$corpus" "$([[ $status == 0 ]] && echo ok || echo "FAILED (see $log)")"
}

declare -A pid_of
failed=0
for t in "${targets[@]}"; do
  [[ -x $out/fuzz/fuzz_$t ]] || { echo "fuzz.sh: no target '$t'" >&2; exit 2; }
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  run_one "$t" &
  pid_of[$t]=$!
done
for t in "${targets[@]}"; do
  status=0
  wait "${pid_of[$t]}" || status=$?
  summary "$t" "$status"
  ((status == 0)) || failed=1
done
if ((failed)); then
  echo "fuzz.sh: a target failed; its input is in $out/artifacts/<target>/ (make it a regression test)" >&2
  exit 1
fi
