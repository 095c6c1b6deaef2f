#!/usr/bin/env bash
# The host HIL set (Modbus TCP and RTU) N times in a row beside a busy loop on one core, to show
# that its checks do not depend on an idle machine. Usage: scripts/hil-repeat.sh [BUILD_DIR] [N]
set -uo pipefail
build=${1:-build/release}
count=${2:-20}
( while :; do :; done ) &
busy=$!
trap 'kill $busy' EXIT
passed=0
for i in $(seq 1 "$count"); do
  if ctest --test-dir "$build" -L hil -E '^hil\.vm$' --output-on-failure > "/tmp/hil-repeat-$i.txt" 2>&1; then
    passed=$((passed + 1))
  else
    echo "run $i failed: /tmp/hil-repeat-$i.txt"
  fi
done
echo "host HIL set: $passed of $count passed beside a busy loop"
((passed == count))
