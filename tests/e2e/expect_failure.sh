#!/usr/bin/env bash
# expect_failure.sh CODE REGEX OUTDIR -- COMMAND...
# Runs COMMAND and checks the bad-input contract: it exits with CODE, prints exactly one line
# on stderr matching REGEX (extended grep), nothing on stdout, and leaves no OUTDIR behind.
set -u
code=$1 regex=$2 outdir=$3
shift 4
rm -rf "$outdir"
stdout=$(mktemp) stderr=$(mktemp)
"$@" >"$stdout" 2>"$stderr"
actual=$?
fail=0
say() { echo "FAIL: $*"; fail=1; }
[ "$actual" -eq "$code" ] || say "exit code $actual, expected $code"
lines=$(wc -l <"$stderr")
[ "$lines" -eq 1 ] || say "stderr has $lines lines, expected exactly 1"
grep -Eq -- "$regex" "$stderr" || say "stderr does not match /$regex/"
[ ! -s "$stdout" ] || say "stdout is not empty"
[ ! -e "$outdir" ] || say "output folder $outdir was created"
echo "--- stderr:"; cat "$stderr"
echo "--- stdout:"; cat "$stdout"
rm -f "$stdout" "$stderr"
exit $fail
