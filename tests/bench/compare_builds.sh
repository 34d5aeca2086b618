#!/usr/bin/env bash
# Compares the kinematics benchmark of two builds in one sitting: the base (a commit) and the
# head (this working tree, uncommitted changes included). This machine's speed drifts by up to
# 1.5× between spells, so a figure is only compared with one measured alongside it: each build
# is made in its own folder (Release, linkwright_kinematics_benchmark only), then the two
# programs run alternately, ROUNDS times each, the first to run swapping every round. Prints a
# Markdown table of CPU nanoseconds per item (one sample; 1e9 / items_per_second): the median
# over the rounds of each build, head / base, and each build's min–max.
#
#   tests/bench/compare_builds.sh [-r ROUNDS] [-f FILTER] [BASE] [-- BENCHMARK-ARGS...]
#       ROUNDS   runs of each build (default 5); FILTER is passed as --benchmark_filter
#       BASE     a commit (default: `git merge-base HEAD main`, where this branch left main; HEAD~1
#                on main itself), or a folder that holds the base's source tree
#   tests/bench/compare_builds.sh --export [BASE]
#       only writes BASE's tree (git archive) to build-compare/base-src and prints that path
#
# Everything goes under build-compare/ in this tree (ignored by git). The compiler and the
# libraries are in packaging/fresh-root.sh's root, which has no git: export on the host, then
# compare in the root, where this tree is /src:
#   tests/bench/compare_builds.sh --export
#   packaging/fresh-root.sh run /var/tmp/lw/bookworm 'tests/bench/compare_builds.sh -f FourBar build-compare/base-src'
set -euo pipefail

usage() { sed -n '10,16s/^# \{0,1\}//p' "$0" >&2; exit 2; }
tree=$(cd "$(dirname "$0")/../.." && pwd)
out="$tree/build-compare"
rounds=5
filter=.
export_only=false
base=
while [[ $# -gt 0 ]]; do
  case $1 in
  -r) rounds=${2:?}; shift 2 ;;
  -f) filter=${2:?}; shift 2 ;;
  --export) export_only=true; shift ;;
  --) shift; break ;;
  -*) usage ;;
  *) [[ -z $base ]] || usage; base=$1; shift ;;
  esac
done
[[ $rounds =~ ^[1-9][0-9]*$ ]] || usage

# The base as a source folder: given, or exported from git.
if [[ -n $base && -d $base ]]; then
  base_src=$(cd "$base" && pwd)
else
  command -v git >/dev/null && git -C "$tree" rev-parse --git-dir >/dev/null 2>&1 ||
    { echo "compare_builds: no git here: export the base on the host with --export, then pass build-compare/base-src" >&2; exit 2; }
  if [[ -z $base ]]; then
    base=$(git -C "$tree" merge-base HEAD main 2>/dev/null || true)
    [[ -n $base && $base != $(git -C "$tree" rev-parse HEAD) ]] || base=HEAD~1
  fi
  commit=$(git -C "$tree" rev-parse --verify "$base^{commit}")
  base_src="$out/base-src"
  rm -rf "$base_src"
  mkdir -p "$base_src"
  git -C "$tree" archive "$commit" | tar -x -C "$base_src"
  echo "$commit" >"$base_src/.compare-commit"
fi
if $export_only; then echo "$base_src"; exit 0; fi

# Release, the benchmark only. A build folder made from another source folder is made anew.
build() {
  local src=$1 dir=$2
  if [[ -f $dir/CMakeCache.txt ]] && ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$src" "$dir/CMakeCache.txt"; then
    rm -rf "$dir"
  fi
  cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DLINKWRIGHT_BUILD_GUI=OFF >/dev/null
  cmake --build "$dir" -j2 --target linkwright_kinematics_benchmark >/dev/null
}
echo "compare_builds: building the base ($base_src) and the head ($tree)" >&2
build "$base_src" "$out/base"
build "$tree" "$out/head"

runs="$out/runs"
rm -rf "$runs"
mkdir -p "$runs"
for ((round = 1; round <= rounds; ++round)); do
  order=(base head)
  ((round % 2)) || order=(head base)
  for which in "${order[@]}"; do
    echo "compare_builds: round $round of $rounds: $which" >&2
    "$out/$which/bin/linkwright_kinematics_benchmark" --benchmark_filter="$filter" \
      --benchmark_out="$runs/$which-$round.json" --benchmark_out_format=json "$@" >/dev/null 2>"$runs/$which-$round.log" ||
      { cat "$runs/$which-$round.log" >&2; exit 1; }
  done
done

base_name=$(cat "$base_src/.compare-commit" 2>/dev/null || echo "$base_src")
python3 - "$runs" "$base_name" "$rounds" <<'EOF'
import glob, json, statistics, sys

runs, base_name, rounds = sys.argv[1:]
scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
values = {"base": {}, "head": {}}  # build -> benchmark -> ns per item, one per run
order = []
for which in values:
    for path in sorted(glob.glob(f"{runs}/{which}-*.json")):
        for b in json.load(open(path))["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration":
                continue
            ns = 1e9 / b["items_per_second"] if "items_per_second" in b else b["cpu_time"] * scale[b["time_unit"]]
            values[which].setdefault(b["name"], []).append(ns)
            if b["name"] not in order:
                order.append(b["name"])

def cell(v, f):
    return f(v) if v else "—"

print(f"base {base_name}, head the working tree; {rounds} alternating rounds; CPU ns per item, median (min–max)")
print()
print("| benchmark | base | head | head / base | base min–max | head min–max |")
print("| --- | ---: | ---: | ---: | ---: | ---: |")
for name in order:
    b, h = values["base"].get(name), values["head"].get(name)
    mb = statistics.median(b) if b else None
    mh = statistics.median(h) if h else None
    ratio = f"{mh / mb:.2f}" if mb and mh else "—"
    spread = lambda v: f"{min(v):.0f}–{max(v):.0f}"
    print(f"| {name} | {cell(mb, lambda v: f'{v:.0f}')} | {cell(mh, lambda v: f'{v:.0f}')} | {ratio} "
          f"| {cell(b, spread)} | {cell(h, spread)} |")
EOF
