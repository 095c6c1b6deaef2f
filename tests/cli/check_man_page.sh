#!/usr/bin/env bash
# A man page help2man built: gzip'd roff with the program's name, its options and the exit codes.
# usage: check_man_page.sh PAGE.1.gz PROGRAM
set -euo pipefail
page=$1
program=$2
text=$(gzip -dc "$page")
grep -q '^\.TH "\?'"${program^^}" <<<"$text" || { echo "$page: no .TH ${program^^}" >&2; exit 1; }
grep -qF -- '\-\-version' <<<"$text" || { echo "$page: no --version" >&2; exit 1; }  # roff escapes the dashes
grep -q 'Exit status: 0 ok' <<<"$text" || { echo "$page: no exit codes" >&2; exit 1; }
echo "$page: ok"
