#!/usr/bin/env bash
# Loop latency bench: mrd-controller --bench (mock HAL, simulated rig) at 1 kHz and 10 kHz, and
# cyclictest (Debian rt-tests) with the same period and SCHED_FIFO priority, side by side.
#   bash scripts/bench-loop.sh [SECONDS] [PRIORITY]      (defaults: 60 s, priority 80)
# The issue's figure is 60 s per run; a shared machine may ask for less (say so when quoting).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
priority=${2:-80}
controller=build/release/firmware/mrd-controller
[[ -x $controller ]] || { echo "bench-loop: build first (cmake --workflow --preset release)" >&2; exit 1; }
if ! command -v cyclictest >/dev/null; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "bench-loop: cyclictest missing; as root: apt-get install rt-tests" >&2
    exit 1
  fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends rt-tests >/dev/null
fi

# p50/p99/p99.9/max of a cyclictest histogram (one line per microsecond: "us count").
cyclictest_percentiles() {
  awk '/^[0-9]+[ \t]+[0-9]+/ { n[$1 + 0] = $2 + 0; total += $2 }
       /# Max Latencies/ { max = $4 + 0 }
       /# Histogram Overflows/ { over = $4 + 0 }
       END {
         split("0.5 0.99 0.999", q, " "); seen = 0; k = 1
         for (us = 0; us <= 100000 && k <= 3; ++us) {
           seen += n[us]
           while (k <= 3 && seen >= q[k] * (total + over)) { p[k] = us; ++k }
         }
         for (; k <= 3; ++k) p[k] = ">" us
         printf "p50 %8s  p99 %8s  p99.9 %8s  max %8s  (n = %d, overflows %d)\n", p[1], p[2], p[3], max, total + over, over
       }'
}

for rate in 1000 10000; do
  period_us=$((1000000 / rate))
  echo "=== ${rate} Hz (period ${period_us} us), SCHED_FIFO ${priority}, ${seconds} s each ==="
  config=$(mktemp --suffix=.toml)
  # The embedded config with this priority (everything else as shipped).
  "$controller" --print-default-config | sed "s/^priority = [0-9]*/priority = ${priority}/" >"$config"
  "$controller" --config "$config" --bench --rate "$rate" --duration "$seconds" | tee /tmp/mrd-bench-$rate.txt |
    grep -E "^(real-time|cycles|wake-up latency|execution time)|histogram|^ +[0-9>]" || true
  rm -f "$config"
  echo "--- cyclictest -m -p ${priority} -i ${period_us} -D ${seconds}s -h 10000 -q"
  cyclictest -m -p "$priority" -i "$period_us" -D "${seconds}s" -h 10000 -q >/tmp/cyclictest-$rate.txt 2>&1 || true
  printf "%-22s " "cyclictest [us]"
  cyclictest_percentiles </tmp/cyclictest-$rate.txt
  printf "%-22s " "mrd-controller [us]"
  grep "wake-up latency \\[us\\]" /tmp/mrd-bench-$rate.txt | sed 's/wake-up latency \[us\] *//'
  echo
done
