#!/usr/bin/env bash
# The core functions the designer's views (ui/ outside ui/document/) call, against the list that
# allows them (ui_core_calls.txt): a view draws what the document holds, so a core call a view
# makes must be a drawing or conversion helper, or a call the list marks as still to move into
# ui/document. A call not on the list fails, and so does a listed one no view makes any more
# (strike it off: the list only shrinks as computation moves down).
set -euo pipefail
source_dir=$1
list=$2
cd "$source_dir"
called=$(find ui -name '*.cpp' -o -name '*.h' | grep -v '^ui/document/' | sort |
  xargs grep -hoE '\b(k|kinematics)::[a-z][A-Za-z0-9_]*\(' | sed -E 's/^(k|kinematics):://; s/\($//' | sort -u)
allowed=$(sed -E 's/#.*//; s/[[:space:]]+//g; /^$/d' "$list" | sort -u)
new=$(comm -23 <(echo "$called") <(echo "$allowed"))
gone=$(comm -13 <(echo "$called") <(echo "$allowed"))
status=0
if [[ -n "$new" ]]; then
  echo "views call core functions the list does not allow (run them through ui/document instead):"
  echo "$new" | sed 's/^/  /'
  status=1
fi
if [[ -n "$gone" ]]; then
  echo "listed core functions no view calls any more (strike them off $list):"
  echo "$gone" | sed 's/^/  /'
  status=1
fi
[[ $status -eq 0 ]] && echo "$(echo "$called" | wc -l) core functions called from views, all on the list"
exit $status
