#!/bin/bash
# The real executable sent SIGINT (Ctrl+C), SIGTERM or SIGHUP in the middle of a streamed -o
# write: it ends of that signal (exit status 128 + its number), the old file as it was, no
# temporary file left. Before the writer removed its temporary file on these signals, a
# OUT.linkwright-tmp.PID.N of hundreds of MB stayed behind.
set -u
set -m  # job control: a background job then keeps SIGINT rather than ignoring it
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; cat "$dir/err" 2> /dev/null; exit 1; }
for signal in INT TERM HUP; do
  echo "the old table" > "$dir/table.csv"
  "$cli" analyze --example watt-ii --samples 10000000 -o "$dir/table.csv" 2> "$dir/err" &
  pid=$!
  # Until the temporary file holds some of the table (the run takes far longer than that).
  for ((tries = 0; tries < 6000; ++tries)); do
    temp=$(find "$dir" -name 'table.csv.linkwright-tmp.*' -size +0 | head -1)
    [ -n "$temp" ] && break
    kill -0 "$pid" 2> /dev/null || fail "SIG$signal: the run ended before it wrote anything"
    sleep 0.05
  done
  [ -n "$temp" ] || { kill -KILL "$pid"; fail "SIG$signal: no temporary file appeared"; }
  kill -"$signal" "$pid"
  wait "$pid"
  code=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$code" -eq "$expected" ] || fail "SIG$signal: exit $code, expected $expected (ended of the signal)"
  [ "$(cat "$dir/table.csv")" = "the old table" ] || fail "SIG$signal: the old file was changed"
  left=$(ls "$dir" | grep linkwright-tmp)
  [ -z "$left" ] || fail "SIG$signal: a temporary file was left: $left"
done
echo "passed"
