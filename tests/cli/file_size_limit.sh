#!/bin/bash
# The real executable past a file-size limit (ulimit -f, as a quota or a full disk would stop
# it): a message and exit 1, the old file as it was, no temporary file left. Without SIGXFSZ
# ignored the kernel killed it mid-write and the temporary file stayed.
set -u
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "the old table" > "$dir/table.csv"
( ulimit -f 100; "$cli" analyze --example watt-ii --samples 20000 -o "$dir/table.csv" 2> "$dir/err" )
code=$?
fail() { echo "FAILED: $*"; cat "$dir/err"; exit 1; }
[ "$code" -eq 1 ] || fail "exit $code, expected 1"
grep -q "cannot write .*table.csv: File too large" "$dir/err" || fail "no message naming the file and the reason"
[ "$(cat "$dir/table.csv")" = "the old table" ] || fail "the old file was changed"
[ "$(ls "$dir" | grep -c linkwright-tmp)" -eq 0 ] || fail "a temporary file was left"
echo "passed"
