#!/bin/sh
# Every built-in example opens and renders, normal and in presentation mode, in a window of a
# 1366×768 laptop and a 1024×768 projector (the designer exits 0 having written the picture).
# A layout that never settled (a chart's height and its page's scroll bar in a loop) overflowed
# the stack here.
set -eu
designer=$1 cli=$2 out=$3
mkdir -p "$out"
status=0
for example in $("$cli" examples | grep -v '^ '); do
  for size in 1366x768 1024x768; do
    for mode in "" --presentation; do
      picture="$out/$example$mode-$size.png"
      if ! QT_QPA_PLATFORM=offscreen "$designer" --example "$example" $mode --window-size "$size" \
        --screenshot "$picture" 2>/dev/null || ! test -s "$picture"; then
        echo "the designer failed on $example $mode at $size" >&2
        status=1
      fi
    done
  done
done
exit $status
