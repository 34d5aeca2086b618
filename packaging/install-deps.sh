#!/usr/bin/env bash
# Installs Linkwright's build and test dependencies from Debian packages: the same names on
# Debian 12 (bookworm) and Debian 13 (trixie).
# Does nothing when everything is present; uses sudo when not run as root.
#
#   packaging/install-deps.sh            what building, testing and packaging need
#   packaging/install-deps.sh --checks   also the tools CI runs on its host: fresh roots, the
#                                        code style, and the package checks
#   packaging/install-deps.sh --package-checks   only the tools that check a built package
#                                        (packaging/check-package.sh, in the package's root)
#   packaging/install-deps.sh --fuzz     also clang and libFuzzer (tests/fuzz, sanitizer builds)
#
# Packages are installed with --no-install-recommends, so every package the build reads must
# be named here or be a hard dependency of one named here; packaging/audit-deps.sh checks it.
set -euo pipefail

packages=(
  g++ cmake make             # toolchain (C++20, CMake >= 3.25)
  libeigen3-dev              # linear algebra for the kinematics core
  nlohmann-json3-dev         # the document reader's JSON parser
  libnlopt-dev               # NLopt: Nelder–Mead with bounds optimises a linkage
                             # (kinematics/tune/optimise_linkage.h)
  libdxflib-dev              # dxflib (QCAD's DXF library): the DXF drawings of the links
  python3-ezdxf              # reads those drawings back in a test (tests/cli/dxf_readback.py)
  libgif-dev                 # giflib: File ▸ Export ▸ Animation's GIF encoder and colour
                             # quantizer (ui/export/gif_writer.h); the tests read GIFs back with it
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
                             # FFmpeg (5.1 on Debian 12, 7.1 on Debian 13): the animation's MP4
                             # (H.264 by libx264) and WebM (VP9 by libvpx-vp9) videos, both built
                             # into Debian's libavcodec (ui/export/video_writer.h); the tests
                             # decode them back with it
  libcairo2-dev pkgconf      # cairo draws the lab-report PDF (kinematics/report/); pkg-config finds it
  fonts-dejavu-core          # the report's font (DejaVu Sans: Greek letters, °, ²)
  poppler-utils              # pdftotext and pdfinfo read the report back in tests/cli/report_cli_test.cpp
  catch2                     # the test framework: Catch2 2.13 on Debian 12, 3.7 on Debian 13
                             # (tests/support/catch.h takes either)
  qt6-base-dev qt6-charts-dev qt6-svg-dev  # the GUI (Widgets, Concurrent, Charts, SVG export)
  libgl-dev                  # OpenGL headers that Qt6Gui's CMake package requires
  libqt6opengl6-dev          # Qt6OpenGL: Qt6Charts' CMake package requires it, yet it is only a
                             # Recommends of qt6-base-dev, which --no-install-recommends skips
  libbenchmark-dev           # Google Benchmark: the core's speed benchmarks (docs/benchmarks.md)
  help2man                   # the manual pages, made from each program's --help
  dpkg-dev file              # cpack -G DEB: dpkg-shlibdeps finds the package's dependencies
  pybind11-dev python3-dev   # the Python module (python/, docs/python.md): pybind11 2.10 on
                             # Debian 12, 2.13 on Debian 13, and the Python headers it builds on
  python3-numpy              # the module returns a sweep's columns as NumPy arrays
  python3-pytest             # the module's tests (python/tests), run by CTest
  python3-distributed        # linkwright.batch runs on Dask; its tests start a LocalCluster
)

package_check_packages=(
  lintian                    # Debian's package checker
  appstream desktop-file-utils  # validate the AppStream data and the desktop entry
)

check_packages=(
  "${package_check_packages[@]}"
  mmdebstrap                 # fresh Debian 12 and 13 roots (packaging/fresh-root.sh)
  clang-format               # the code style (.clang-format), checked by CI
)

fuzz_packages=(
  clang                      # libFuzzer's compiler (clang 14 on Debian 12, 19 on Debian 13)
  libclang-rt-dev            # the libFuzzer and sanitizer runtimes of that clang, only a
                             # Recommends of it
)

case "${1:-}" in
  "") ;;
  --checks) packages+=("${check_packages[@]}") ;;
  --package-checks) packages=("${package_check_packages[@]}") ;;
  --fuzz) packages+=("${fuzz_packages[@]}") ;;
  *) echo "usage: packaging/install-deps.sh [--checks | --package-checks | --fuzz]" >&2; exit 2 ;;
esac

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
