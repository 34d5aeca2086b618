#!/usr/bin/env bash
# Checks a built Debian package as a distribution and a new user would:
#   1. lintian finds no error (warnings are printed);
#   2. its AppStream data passes appstreamcli validate --pedantic and its desktop entry
#      desktop-file-validate;
#   3. on a fresh Debian 12 root, `apt-get install ./linkwright_*.deb` pulls in no -dev package,
#      linkwright-cli classifies the thesis crank-rocker and the designer renders a window
#      offscreen; the picture is copied to SCREENSHOT.
#
# Usage: packaging/check-package.sh DEB [SCREENSHOT.png]
# Needs root and the tools of packaging/install-deps.sh --checks.
set -euo pipefail

deb=$(realpath "${1:?usage: packaging/check-package.sh DEB [SCREENSHOT.png]}")
screenshot=$(realpath -m "${2:-linkwright-package-screenshot.png}")
here=$(cd "$(dirname "$0")" && pwd)
root=${LINKWRIGHT_PACKAGE_ROOT:-/var/tmp/linkwright-package-root}
unpacked=$(mktemp -d)
trap 'rm -rf "$unpacked"; "$here/fresh-root.sh" remove "$root" 2>/dev/null || true' EXIT

step() { echo "--- check-package: $*"; }

step "lintian $(basename "$deb")"
lintian --fail-on error --info "$deb"
echo "lintian: no errors"

step "AppStream data and desktop entry"
dpkg-deb -x "$deb" "$unpacked"
appstreamcli validate --pedantic --no-net "$unpacked"/usr/share/metainfo/*.metainfo.xml
desktop-file-validate "$unpacked"/usr/share/applications/linkwright.desktop
echo "desktop-file-validate: clean"

step "install on a fresh Debian 12 root"
"$here/fresh-root.sh" create "$root"
cp "$deb" "$root/tmp/"
deb_in_root=/tmp/$(basename "$deb")
"$here/fresh-root.sh" run "$root" "
  dpkg-query -W -f='\${Package}\n' | sort > /tmp/before.txt
  apt-get update -qq
  apt-get install -y -qq $deb_in_root > /tmp/install.log
  dpkg-query -W -f='\${Package}\n' | sort > /tmp/after.txt
  added=\$(comm -13 /tmp/before.txt /tmp/after.txt)
  echo \"apt-get install ./$(basename "$deb") added \$(echo \"\$added\" | wc -l) packages\"
  dev=\$(echo \"\$added\" | grep -E -- '-dev\$|-dev-' || true)
  if [[ -n \"\$dev\" ]]; then echo \"check-package: development packages pulled in: \$dev\" >&2; exit 1; fi
  echo 'no -dev package among them'

  cd /tmp
  linkwright-cli classify --example thesis-crank-rocker | tee /tmp/classify.txt
  grep -q 'crank-rocker' /tmp/classify.txt
  QT_QPA_PLATFORM=offscreen linkwright --screenshot /tmp/shot.png
  test -s /tmp/shot.png
"
cp "$root/tmp/shot.png" "$screenshot"
if [[ "$(head -c 8 "$screenshot" | od -An -tx1 | tr -d ' \n')" != 89504e470d0a1a0a ]]; then
  echo "check-package: $screenshot is not a PNG" >&2
  exit 1
fi
echo "check-package: the installed designer rendered its window: $screenshot ($(stat -c %s "$screenshot") bytes)"
