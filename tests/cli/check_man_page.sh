#!/usr/bin/env bash
# A man page help2man built: gzip'd roff with the program's name, its options and the exit codes;
# the sections every page has (EXIT STATUS, FILES, EXAMPLES, SEE ALSO; packaging/man/PROGRAM.h2m);
# and, checked against the program itself, an EXIT STATUS entry for each code its --help states,
# every option its --help lists, and for a program with subcommands (mrd-identify) a subsection
# per subcommand in SUBCOMMANDS with every option that subcommand's --help lists.
# usage: check_man_page.sh PAGE.1.gz PROGRAM [COMMAND...]
#   COMMAND: runs the program (its path; under the emulator in a cross build). Without it only
#   the page itself is checked.
set -euo pipefail
page=$1
program=$2
shift 2
command=("$@")
text=$(gzip -dc "$page")
failed=0
fail() { echo "$page: $*" >&2; failed=1; }

grep -q '^\.TH "\?'"${program^^}" <<<"$text" || fail "no .TH ${program^^}"
grep -qF -- '\-\-version' <<<"$text" || fail "no --version"  # roff escapes the dashes
grep -q 'Exit status: 0 ok' <<<"$text" || fail "no exit codes"

# The body of section NAME (.SH NAME or .SH "NAME"), up to the next .SH.
section() {
  awk -v want="$1" '/^\.SH / { name = substr($0, 5); gsub(/"/, "", name); on = (name == want); next } on' <<<"$text"
}
# The body of subsection NAME of section SECTION, up to the next .SS or .SH.
subsection() {
  section "$1" | awk -v want="$2" '/^\.SS / { name = substr($0, 5); gsub(/"/, "", name); on = (name == want); next } on'
}
for name in "EXIT STATUS" FILES EXAMPLES "SEE ALSO"; do
  [[ -n $(section "$name" | tr -d '[:space:]') ]] || fail "no $name section"
done

# The tags of a section's .TP entries, font escapes removed ('.B 2\fR, \fB3' reads '2, 3').
tags() { awk 'tag { sub(/^\.[BI]R? /, ""); gsub(/\\f[BIRP]/, ""); print; tag = 0 } /^\.TP/ { tag = 1 }'; }
# The long options an --help text lists (the first on each option line), as roff writes them.
options_of() { sed -n 's/^  \(-[A-Za-z0-9],\)\{0,1\}\(--[A-Za-z0-9][A-Za-z0-9-]*\).*/\2/p' | sed 's/-/\\-/g'; }
# The options (arguments) that are not in the text on stdin, dashes unescaped. grep -o takes the
# longest match, so an option found only inside a longer one (--seed in --seeds) is missing.
missing_options() {
  (($#)) || return 0
  comm -23 <(printf '%s\n' "$@" | sort -u) <(grep -oF -f <(printf '%s\n' "$@") | sort -u) | sed 's/\\//g'
}

if ((${#command[@]})); then
  help=$("${command[@]}" --help)
  # Every exit code the --help footer states ('Exit status: 0 ok, 1 ..., 3 I/O error (...). 4: ...').
  codes=$(grep '^Exit status:' <<<"$help" | grep -oE '(: |, |\. )[0-9]+(:| [A-Za-z])' | grep -oE '[0-9]+')
  [[ -n $codes ]] || fail "--help states no exit codes"
  exit_tags=$(section "EXIT STATUS" | tags | tr ',' '\n' | tr -d ' ')
  for code in $codes; do
    grep -qx "$code" <<<"$exit_tags" || fail "EXIT STATUS has no entry for $code"
  done
  mapfile -t options < <(options_of <<<"$help")
  missing=$(missing_options "${options[@]}" <<<"$text")
  [[ -z $missing ]] || fail "options not on the page:" $missing
  subcommands=$(sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\)\( .*\)\{0,1\}$/\1/p' <<<"$help")
  for sub in $subcommands; do
    body=$(subsection SUBCOMMANDS "$sub")
    if [[ -z $body ]]; then
      fail "no subsection '$sub' in SUBCOMMANDS"
      continue
    fi
    mapfile -t options < <("${command[@]}" "$sub" --help | options_of)
    missing=$(missing_options "${options[@]}" <<<"$body")
    [[ -z $missing ]] || fail "subcommand $sub: options not on the page:" $missing
  done
fi
((failed == 0)) || exit 1
echo "$page: ok"
