#!/usr/bin/env bash
# Dependency audit: every package-config file, library and program that CMake found for a
# configured build must come from a Debian package that packaging/install-deps.sh names, from
# a hard Depends/Pre-Depends (never a Recommends) of one of them, or from an Essential package
# (which every Debian system has, gzip for one). A package that is on this machine
# only because someone installed it by hand fails the audit, so CI cannot pass on a machine
# where a new user's first command would fail (libqt6opengl6-dev was such a package).
#
# Usage: packaging/audit-deps.sh BUILD_DIR      exit 0 clean, 1 undeclared packages, 2 usage
set -euo pipefail

build_dir=${1:?usage: packaging/audit-deps.sh BUILD_DIR}
cache="$build_dir/CMakeCache.txt"
[[ -f "$cache" ]] || { echo "audit-deps: no $cache (configure first)" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/.." && pwd)
build_abs=$(cd "$build_dir" && pwd)

# Found by Qt's or CMake's own modules as optional extras: configure succeeds without them
# and no target of ours links them (Qt6::GuiPrivate alone uses XKB; FindOpenGL looks for GLU
# and EGL whether or not anyone asks). The fresh-root check (fresh-root-check.sh) proves that
# a root without them configures and builds.
optional_entries='^(OPENGL_glu_LIBRARY|OPENGL_egl_LIBRARY|OPENGL_EGL_INCLUDE_DIR|XKB_LIBRARY|XKB_INCLUDE_DIR)$'

# The packages install-deps.sh names: the words of its build `packages=( … )` list.
mapfile -t named < <(sed -n '/^packages=(/,/^)/p' "$here/install-deps.sh" |
  sed -e 's/#.*//' -e 's/packages=(//' -e 's/)//' | tr -s ' \t' '\n' | sed '/^$/d')
[[ ${#named[@]} -gt 0 ]] || { echo "audit-deps: no packages=( … ) list in install-deps.sh" >&2; exit 2; }

# Their closure over hard dependencies, among the installed packages, and the Essential ones. apt-cache prints every
# package it visits unindented; alternatives (|Depends) are visited too, which can only
# make the closure larger than strictly needed, never hide a missing package.
declare -A allowed=()
while read -r p; do allowed[$p]=1; done < <(
  apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts \
    --no-breaks --no-replaces --no-enhances "${named[@]}" | grep -v '^ ' | sed 's/:.*//')
while read -r p essential; do
  [[ "$essential" == yes ]] && allowed[$p]=1
done < <(dpkg-query -W -f='${Package} ${Essential}\n')

# The file a cache entry stands for: a library or header directory's own path, or for a
# package-config directory (<Name>_DIR) its <Name>Config.cmake / <name>-config.cmake.
file_for_entry() {
  local name=$1 path=$2
  if [[ "$name" == *_DIR && -d "$path" ]]; then
    local pkg=${name%_DIR}
    local lower=${pkg,,}
    for f in "$path/${pkg}Config.cmake" "$path/${lower}-config.cmake"; do
      if [[ -f "$f" ]]; then echo "$f"; return 0; fi
    done
    return 0
  fi
  # A header directory such as /usr/include belongs to every -dev package; the library
  # entries beside it name the package.
  if [[ "$name" == *_INCLUDE_DIR && ( "$path" == /usr/include || "$path" == /usr/local/include ) ]]; then
    return 0
  fi
  echo "$path"
}

checked=0
undeclared=()
while IFS= read -r line; do
  name=${line%%:*}
  path=${line#*=}
  [[ "$name" =~ $optional_entries ]] && continue
  [[ "$path" == *-NOTFOUND || -z "$path" ]] && continue
  [[ "$path" == "$build_abs"* || "$path" == "$source_dir"* ]] && continue
  file=$(file_for_entry "$name" "$path")
  [[ -n "$file" ]] || continue
  real=$(readlink -f "$file")
  # Merged /usr: dpkg may list /usr/bin/gzip as /bin/gzip.
  owner=$(dpkg -S "$file" 2>/dev/null || dpkg -S "$real" 2>/dev/null || dpkg -S "${real#/usr}" 2>/dev/null || true)
  owner=${owner%%: *}
  owner=${owner%%:*}
  checked=$((checked + 1))
  if [[ -z "$owner" ]]; then
    undeclared+=("$name=$path (no Debian package owns it: installed by hand?)")
  elif [[ -z "${allowed[$owner]:-}" ]]; then
    undeclared+=("$name=$path comes from $owner, which install-deps.sh neither names nor hard-depends on")
  fi
done < <(grep -E '^[A-Za-z0-9_]+_(DIR|LIBRARY|INCLUDE_DIR|EXECUTABLE):(PATH|FILEPATH)=' "$cache" |
  grep -v '^CMAKE_')

if [[ ${#undeclared[@]} -gt 0 ]]; then
  echo "audit-deps: FAILED: ${#undeclared[@]} of $checked found dependencies are not installed by packaging/install-deps.sh:" >&2
  printf '  %s\n' "${undeclared[@]}" >&2
  echo "Name the package in install-deps.sh (a Recommends does not count: it uses --no-install-recommends)." >&2
  exit 1
fi
echo "audit-deps: all $checked dependencies CMake found come from packages install-deps.sh installs (${#named[@]} named, ${#allowed[@]} with their hard dependencies and the Essential packages)"
