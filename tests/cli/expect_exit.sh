#!/usr/bin/env bash
# Runs a program and checks its exit status and what it printed (stdout and stderr together).
# usage: expect_exit.sh STATUS REGEX PROGRAM [ARGS...]   (the output must match the extended REGEX)
set -uo pipefail
expected=$1
pattern=$2
shift 2
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [[ $status -ne $expected ]]; then
  echo "expect_exit: '$*' exited $status, expected $expected" >&2
  exit 1
fi
if ! grep -Eq -- "$pattern" <<<"$output"; then
  echo "expect_exit: '$*' printed nothing matching '$pattern'" >&2
  exit 1
fi
