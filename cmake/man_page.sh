#!/usr/bin/env bash
# Writes a program's man page with help2man from its --help and --version (mrd_install_command,
# at build time), with the sections of its include file (packaging/man/PROGRAM.h2m: EXIT STATUS,
# FILES, EXAMPLES, SEE ALSO, ...). A program with subcommands (mrd-identify) gets a SUBCOMMANDS
# section made here from each subcommand's own --help, so that every subcommand's options are on
# the page, as the program states them: nothing is copied by hand, nothing can go stale. Writes
# PAGE and PAGE.gz (gzip -9n).
# usage: man_page.sh HELP2MAN PROGRAM SUMMARY SOURCE INCLUDE PAGE
#   PROGRAM: the program, or a wrapper that runs it (under the emulator in a cross build)
set -euo pipefail
help2man=$1 program=$2 summary=$3 source=$4 include=$5 page=$6
name=$(basename "$page" .1)
work=$(mktemp -d "$page.XXXXXX")
trap 'rm -rf "$work"' EXIT

# Subcommand names: the first word of each line of --help's "Subcommands:" list.
subcommands=$("$program" --help | sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\)\( .*\)\{0,1\}$/\1/p')
includes=()
if [[ -n $subcommands ]]; then
  generated=$work/subcommands.h2m
  {
    echo '[SUBCOMMANDS]'
    echo "Each subcommand takes its own options, after its name (\\fB$name \\fR\\fISUBCOMMAND\\fR \\fB\\-\\-help\\fR prints them):"
  } >"$generated"
  for sub in $subcommands; do
    wrapper=$work/$name-$sub
    printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$program" "$sub" >"$wrapper"
    chmod +x "$wrapper"
    "$help2man" --no-info --no-discard-stderr --version-string="$source" --name="$sub" \
      --output="$work/$sub.1" "$wrapper"
    # The sub-page's body from its SYNOPSIS on, as a subsection: its sections become paragraphs
    # with CLI11's own headings; the exit-status footer is the main page's. A line help2man would
    # read as an include file's [section] or /pattern/ is escaped.
    awk -v sub_name="$sub" '
      function out(line) { lines[++n] = line }
      /^\.SH SYNOPSIS/ { body = 1; out(".SS \"" sub_name "\""); next }
      !body { next }
      /^\.SH DESCRIPTION/ { out(".PP"); next }
      /^\.SH OPTIONS/ { out(".PP"); out("Options:"); next }
      /^\.S[HS] / { heading = substr($0, 5); gsub(/"/, "", heading); sub(/:$/, "", heading)
                    out(".PP"); out(heading ":"); next }
      /^Exit status:/ { if (lines[n] == ".PP") n--; skip = 1; next }
      skip && /^\./ { skip = 0 }
      skip { next }
      /^\[.*\][[:space:]]*$/ || /^\/.*\/[ims]*[[:space:]]*$/ { out("\\&" $0); next }
      { out($0) }
      END { for (i = 1; i <= n; ++i) print lines[i] }
    ' "$work/$sub.1" >>"$generated"
  done
  includes+=(--include "$generated")
fi

"$help2man" --no-info --no-discard-stderr --section 1 --name "$summary" --source "$source" \
  "${includes[@]}" --include "$include" --output "$work/page" "$program"
mv "$work/page" "$page"
gzip -9nf --keep "$page"
