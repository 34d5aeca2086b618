#!/usr/bin/env bash
# Installs Linkwright's build and test dependencies from Debian 12 packages.
# Does nothing when everything is present; uses sudo when not run as root.
set -euo pipefail

packages=(
  g++ cmake make             # toolchain (C++20, CMake >= 3.25)
  libeigen3-dev              # linear algebra for the kinematics core
  catch2                     # Catch2 2.13 test framework
  qt6-base-dev qt6-charts-dev qt6-svg-dev  # the GUI (Widgets, Charts, SVG export)
  libgl-dev                  # OpenGL headers that Qt6Gui's CMake package requires
  libbenchmark-dev           # Google Benchmark: the core's speed benchmarks (docs/benchmarks.md)
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
