#!/usr/bin/env bash
# Runs both libFuzzer targets side by side for SECONDS each (default 60), from the seed
# corpus and the stored regressions; any finding fails. New interesting inputs are kept in
# BUILD_DIR/fuzz/, findings in BUILD_DIR/fuzz/findings/: copy a finding into
# tests/fuzz/regressions/<documents|arguments>/ once it is fixed, so the test suite keeps it.
#
# Usage: tests/fuzz/run-fuzzers.sh BUILD_DIR [SECONDS] [EXTRA LIBFUZZER FLAGS…]
# BUILD_DIR is configured with CXX=clang++ -DLINKWRIGHT_BUILD_FUZZERS=ON (and usually
# -DLINKWRIGHT_SANITIZE=ON); packaging/install-deps.sh --fuzz installs clang and libFuzzer.
set -euo pipefail

build=$(realpath "${1:?usage: tests/fuzz/run-fuzzers.sh BUILD_DIR [SECONDS] [FLAGS…]}")
seconds=${2:-60}
shift $(( $# >= 2 ? 2 : 1 ))
here=$(cd "$(dirname "$0")" && pwd)
work="$build/fuzz"
mkdir -p "$work/findings"

declare -A folder=([document]=documents [arguments]=arguments)
pids=()
for input in document arguments; do
  fuzzer="$build/bin/linkwright_${input}_fuzzer"
  [[ -x "$fuzzer" ]] || { echo "run-fuzzers: $fuzzer not built (LINKWRIGHT_BUILD_FUZZERS=ON)" >&2; exit 2; }
  mkdir -p "$work/$input-corpus"
  # The first corpus folder receives new inputs; the source's seed and regression folders
  # are only read.
  "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$work/findings/$input-" "$@" \
    "$work/$input-corpus" "$here/corpus/${folder[$input]}" "$here/regressions/${folder[$input]}" \
    > "$work/$input.log" 2>&1 &
  pids+=($!)
done

status=0
for i in 0 1; do
  input=$([[ $i -eq 0 ]] && echo document || echo arguments)
  if wait "${pids[$i]}"; then
    runs=$(grep -m1 -o 'stat::number_of_executed_units: [0-9]*' "$work/$input.log" | grep -o '[0-9]*$' || echo '?')
    echo "run-fuzzers: $input: no finding in $seconds s ($runs inputs run)"
  else
    status=1
    echo "run-fuzzers: $input: FINDING (log: $work/$input.log)" >&2
    grep -E 'linkwright .* fuzzer:|ERROR: |SUMMARY: |Test unit written to' "$work/$input.log" >&2 || tail -20 "$work/$input.log" >&2
    echo >&2
  fi
done
exit $status
