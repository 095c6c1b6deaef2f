#!/usr/bin/env bash
# A report opened in headless Chromium: its time charts draw, zoom together when one is dragged
# over, come back whole on a double-click (the page's #selftest, tools/report/web/time_chart.js),
# and the console stays free of errors.
# Usage: report_in_chromium.sh CHARTS REPORT_DIR PROGRAM ARGS...
#   PROGRAM writes REPORT_DIR/report.html, which must hold CHARTS time charts.
set -euo pipefail
charts=$1
dir=$2
shift 2
browser=$(command -v chromium-headless-shell || command -v chromium || true)
if [[ -z $browser ]]; then
  # Skipped (ctest SKIP_RETURN_CODE), not passed: CI installs the browser, so there it always runs.
  echo "report_in_chromium: no chromium-headless-shell or chromium (scripts/install-deps.sh installs it)" >&2
  exit 77
fi
rm -rf "$dir"
"$@" > /dev/null
[[ -s $dir/report.html ]] || { echo "report_in_chromium: $* wrote no $dir/report.html" >&2; exit 1; }
# --no-sandbox: CI runs as root, where Chromium's sandbox will not start.
"$browser" --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 --window-size=1200,900 \
  --virtual-time-budget=10000 --dump-dom "file://$(realpath "$dir")/report.html#selftest" \
  > "$dir/dom.html" 2> "$dir/console.txt" || true
result=$(grep -o '<pre id="mrd-selftest">[^<]*' "$dir/dom.html" | sed 's/.*>//' || true)
echo "${result:-no selftest result in the page}"
# Chromium logs the page's console as CONSOLE lines; an uncaught exception reads "Uncaught".
errors=$(grep -E 'CONSOLE' "$dir/console.txt" | grep -iE 'error|uncaught' || true)
if [[ -n $errors ]]; then
  echo "console errors:"
  echo "$errors"
  exit 1
fi
[[ $result == "selftest: ok $charts charts zoomed"* ]]
