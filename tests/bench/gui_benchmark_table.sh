#!/usr/bin/env bash
# The drag-to-redraw table of docs/benchmarks.md: linkwright_gui_benchmark for the four-bar,
# slider-crank, shaper, a dyad six-bar and a Newton six-bar at each sampling quality, with
# kinematics only and with forces. Prints a Markdown table (ms per move: median / p95 / max):
# the handling, the drag to redraw, and the longest single event of the GUI thread (how long
# it cannot answer the user).
#
#   tests/bench/gui_benchmark_table.sh [build-dir] [moves]     (default build, 200)
set -euo pipefail
build=${1:-build}
moves=${2:-200}
bench="$build/bin/linkwright_gui_benchmark"
echo "| linkwright_gui_benchmark | quality | shows | handling median / p95 / max | drag to redraw median / p95 / max | longest event median / p95 / max |"
echo "| --- | --- | --- | --- | --- | --- |"
for example in thesis-crank-rocker ls3-engine shaper watt-ii stephenson-ii; do
  for quality in draft normal precise; do
    for shows in kinematics forces; do
      flag=()
      [[ $shows == forces ]] && flag=(--forces)
      line=$(QT_QPA_PLATFORM=offscreen "$bench" --moves "$moves" --example "$example" --quality "$quality" \
        "${flag[@]}" 2>/dev/null | grep '^RESULT')
      read -r _ _ _ _ _ hm hp hx _ rm rp rx _ _ _ _ _ em ep ex <<<"$line"
      echo "| $example | $quality | $shows | $hm / $hp / $hx | $rm / $rp / $rx | $em / $ep / $ex |"
    done
  done
done
