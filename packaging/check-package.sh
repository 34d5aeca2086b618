#!/usr/bin/env bash
# Checks a built Debian package as a distribution and a new user would, on a fresh root of the
# Debian release it was built for (its version ends +deb12 or +deb13), with that release's tools:
#   1. `apt-get install ./linkwright_*.deb` pulls in no -dev package, linkwright-cli classifies
#      the thesis crank-rocker and the designer renders a window offscreen; the picture is
#      copied to SCREENSHOT; `import linkwright` sweeps the crank-rocker, if the package has it;
#   2. then, in the same root, the release's lintian finds no error (warnings are printed), and
#      the installed AppStream data passes appstreamcli validate --pedantic and the desktop
#      entry desktop-file-validate.
#
# Usage: packaging/check-package.sh DEB [SCREENSHOT.png]
# Needs root and mmdebstrap (packaging/install-deps.sh --checks).
set -euo pipefail

deb=$(realpath "${1:?usage: packaging/check-package.sh DEB [SCREENSHOT.png]}")
screenshot=$(realpath -m "${2:-linkwright-package-screenshot.png}")
here=$(cd "$(dirname "$0")" && pwd)
root=${LINKWRIGHT_PACKAGE_ROOT:-/var/tmp/linkwright-package-root}
trap '"$here/fresh-root.sh" remove "$root" 2>/dev/null || true' EXIT

step() { echo "--- check-package: $*"; }

version=$(dpkg-deb -f "$deb" Version)
case "$version" in
  *+deb12) release=bookworm ;;
  *+deb13) release=trixie ;;
  *) echo "check-package: version $version names no Debian release we build for (+deb12 or +deb13)" >&2; exit 2 ;;
esac

# The Python module (python/), when the build made it: installed, it imports and sweeps.
python_module=no
contents=$(dpkg-deb -c "$deb")  # whole, not piped into grep -q: pipefail would see a SIGPIPE
if grep -q '/dist-packages/linkwright/__init__.py$' <<<"$contents"; then python_module=yes; fi

step "install $(basename "$deb") on a fresh $release root"
"$here/fresh-root.sh" create "$root" "$release"
cp "$deb" "$root/tmp/"
deb_in_root=/tmp/$(basename "$deb")
"$here/fresh-root.sh" run "$root" "
  dpkg-query -W -f='\${Package}\n' | sort > /tmp/before.txt
  apt-get update -qq
  apt-get install -y -qq $deb_in_root > /tmp/install.log
  dpkg-query -W -f='\${Package}\n' | sort > /tmp/after.txt
  added=\$(comm -13 /tmp/before.txt /tmp/after.txt)
  echo \"apt-get install ./$(basename "$deb") added \$(echo \"\$added\" | wc -l) packages\"
  # Debian 13's python3-numpy itself depends on python3-numpy-dev (NumPy's C headers, nothing
  # more): the one -dev package the Python module's dependency brings.
  dev=\$(echo \"\$added\" | grep -E -- '-dev\$|-dev-' | grep -vx python3-numpy-dev || true)
  if [[ -n \"\$dev\" ]]; then echo \"check-package: development packages pulled in: \$dev\" >&2; exit 1; fi
  echo 'no -dev package among them'

  cd /tmp
  linkwright-cli classify --example thesis-crank-rocker | tee /tmp/classify.txt
  grep -q 'crank-rocker' /tmp/classify.txt
  QT_QPA_PLATFORM=offscreen linkwright --screenshot /tmp/shot.png
  test -s /tmp/shot.png
  if [[ $python_module == yes ]]; then
    python3 -c 'import linkwright, linkwright.batch; t = linkwright.example(\"thesis-crank-rocker\").sweep(); print(\"import linkwright:\", len(t), \"columns of\", t[\"crank_angle_deg\"].size, \"rows\")'
  fi
"
cp "$root/tmp/shot.png" "$screenshot"
if [[ "$(head -c 8 "$screenshot" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]]; then
  echo "check-package: $screenshot is not a PNG" >&2
  exit 1
fi
echo "check-package: the installed designer rendered its window: $screenshot ($(stat -c %s "$screenshot") bytes)"

step "$release's lintian, AppStream and desktop-entry checks"
"$here/fresh-root.sh" run "$root" "
  packaging/install-deps.sh --package-checks > /tmp/package-checks-install.log
  lintian --fail-on error --info $deb_in_root
  echo 'lintian: no errors'
  appstreamcli validate --pedantic --no-net /usr/share/metainfo/io.github.linkwright.linkwright.metainfo.xml
  desktop-file-validate /usr/share/applications/linkwright.desktop
  echo 'desktop-file-validate: clean'
"
