#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each (default 60), from the seed corpus and the stored
# regressions, as many side by side as there are cores (two at a time on CI's two cores: four
# targets take two minutes); any finding fails. New interesting inputs are kept in
# BUILD_DIR/fuzz/, findings in BUILD_DIR/fuzz/findings/: copy a finding into
# tests/fuzz/regressions/<folder>/ once it is fixed, so the test suite keeps it.
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

# Each target and the folder of its inputs under corpus/ and regressions/.
inputs=(document arguments compare_table law_table)
declare -A folder=([document]=documents [arguments]=arguments [compare_table]=compare-tables [law_table]=law-tables)
for input in "${inputs[@]}"; do
  fuzzer="$build/bin/linkwright_${input}_fuzzer"
  [[ -x "$fuzzer" ]] || { echo "run-fuzzers: $fuzzer not built (LINKWRIGHT_BUILD_FUZZERS=ON)" >&2; exit 2; }
done

# One core each: a fuzzer sharing a core runs half as many inputs in its minute.
batch=$(nproc 2> /dev/null || echo 2)
status=0
for ((first = 0; first < ${#inputs[@]}; first += batch)); do
  running=("${inputs[@]:first:batch}")
  pids=()
  for input in "${running[@]}"; do
    mkdir -p "$work/$input-corpus"
    # The first corpus folder receives new inputs; the source's seed and regression folders
    # are only read (a target without a finding yet has no regression folder).
    corpora=("$work/$input-corpus")
    for stored in corpus regressions; do
      [[ -d "$here/$stored/${folder[$input]}" ]] && corpora+=("$here/$stored/${folder[$input]}")
    done
    "$build/bin/linkwright_${input}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$work/findings/$input-" "$@" "${corpora[@]}" \
      > "$work/$input.log" 2>&1 &
    pids+=($!)
  done
  for i in "${!running[@]}"; do
    input=${running[$i]}
    if wait "${pids[$i]}"; then
      runs=$(grep -m1 -o 'stat::number_of_executed_units: [0-9]*' "$work/$input.log" | grep -o '[0-9]*$' || echo '?')
      echo "run-fuzzers: $input: no finding in $seconds s ($runs inputs run)"
    else
      status=1
      echo "run-fuzzers: $input: FINDING (log: $work/$input.log)" >&2
      grep -E 'linkwright .* fuzzer:|ERROR: |SUMMARY: |Test unit written to' "$work/$input.log" >&2 ||
        tail -20 "$work/$input.log" >&2
      echo >&2
    fi
  done
done
exit $status
