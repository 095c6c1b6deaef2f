#!/usr/bin/env bash
# check_man_page.sh refuses the gaps issue 29 found in the pages: each mutant of a good page, one
# of EXIT STATUS, FILES, EXAMPLES and SEE ALSO left out, the entry of exit code CODE left out,
# and (for a program with subcommands) one option of its last subcommand left out of
# SUBCOMMANDS, must fail the check.
# usage: man_page_mutants.sh PAGE.1.gz PROGRAM CODE COMMAND...
set -euo pipefail
here=$(dirname "$0")
page=$1
program=$2
code=$3
shift 3
command=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
text=$(gzip -dc "$page")
bash "$here/check_man_page.sh" "$page" "$program" "${command[@]}" >/dev/null ||
  { echo "FAIL: the page itself fails the check"; exit 1; }
failed=0

mutant() {  # mutant WHAT AWK-ARGS...: the page through awk must change and fail the check
  local what=$1
  shift
  awk "$@" <<<"$text" >"$work/m.1"
  if cmp -s "$work/m.1" <(cat <<<"$text"); then
    echo "FAIL: the mutant without $what is the page itself"
    failed=1
    return
  fi
  gzip -9nf "$work/m.1"
  if bash "$here/check_man_page.sh" "$work/m.1.gz" "$program" "${command[@]}" >/dev/null 2>&1; then
    echo "FAIL: a page without $what passes"
    failed=1
  else
    echo "ok: a page without $what fails"
  fi
}

for name in "EXIT STATUS" FILES EXAMPLES "SEE ALSO"; do
  mutant "$name" -v want="$name" '/^\.SH / { name = substr($0, 5); gsub(/"/, "", name); on = (name == want) } !on'
done
mutant "exit code $code" -v code="$code" \
  '/^\.SH / { name = substr($0, 5); gsub(/"/, "", name); on = (name == "EXIT STATUS") } on && $0 == ".B " code { $0 = ".B 99" } 1'
last=$("${command[@]}" --help | sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\)\( .*\)\{0,1\}$/\1/p' | tail -1)
if [[ -n $last ]]; then
  option=$("${command[@]}" "$last" --help | sed -n 's/^  \(-[A-Za-z0-9],\)\{0,1\}\(--[A-Za-z0-9][A-Za-z0-9-]*\).*/\2/p' | tail -1)
  # The option as roff writes it (\-\-name), through the environment: awk -v would read the
  # backslashes as escapes.
  export MRD_OPTION=${option//-/\\-}
  mutant "$last's option $option" -v subcommand="$last" '
    /^\.SH / { name = substr($0, 5); gsub(/"/, "", name); in_section = (name == "SUBCOMMANDS"); on = 0 }
    /^\.SS / && in_section { name = substr($0, 5); gsub(/"/, "", name); on = (name == subcommand) }
    on && index($0, ENVIRON["MRD_OPTION"]) { next } 1'
fi
((failed == 0))
