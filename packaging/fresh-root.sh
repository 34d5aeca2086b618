#!/usr/bin/env bash
# A fresh Debian 12 or 13 root, to prove what a new user's machine needs: nothing in it but
# Debian's minimal base (mmdebstrap --variant=minbase) and what our scripts install.
#
#   packaging/fresh-root.sh create ROOT RELEASE  make ROOT anew: RELEASE is bookworm (Debian 12)
#                                                or trixie (Debian 13), from the host's mirror
#   packaging/fresh-root.sh run ROOT COMMAND     run the bash COMMAND as root inside ROOT, in
#                                                /src, which is this source tree
#   packaging/fresh-root.sh remove ROOT          delete ROOT
#
# With LINKWRIGHT_COMPILER_CACHE=DIR (a host folder), run also mounts DIR in the root and sets
# CMake's compiler launcher to ccache (which the root must have), so CI compiles only what changed
# since its last run. ccache keys each object on the preprocessed source and the compiler's own
# bytes, so a header the root lacks still fails the build, and linking is never cached.
#
# Every mount (/proc, /dev/pts, the source tree, the apt download cache) is made inside a private mount
# namespace that dies with the command, so none outlives it on any exit path and the host's
# /dev and /proc are never touched: the root's /dev holds its own device nodes. remove refuses
# to delete a root that still has anything mounted under it.
set -euo pipefail

usage() { sed -n '5,9s/^# \{0,1\}//p' "$0" >&2; exit 2; }
[[ $# -ge 2 ]] || usage
action=$1
root=$(realpath -m "$2")
source_dir=$(cd "$(dirname "$0")/.." && pwd)
# Downloaded .deb files are kept here between runs, so a second run does not fetch Qt again.
apt_cache=${LINKWRIGHT_APT_CACHE:-/var/cache/linkwright/apt-archives}
compiler_cache=${LINKWRIGHT_COMPILER_CACHE:-}

[[ $(id -u) -eq 0 ]] || { echo "fresh-root: needs root (chroot and mounts)" >&2; exit 2; }
[[ "$root" != / && "$root" != "$source_dir"* ]] || { echo "fresh-root: refusing root $root" >&2; exit 2; }

mounted_under() { findmnt -rn -o TARGET | awk -v r="$root" 'index($0, r "/") == 1 || $0 == r'; }

remove_root() {
  if [[ -n "$(mounted_under)" ]]; then
    echo "fresh-root: not removing $root: still mounted: $(mounted_under | tr '\n' ' ')" >&2
    exit 1
  fi
  rm -rf --one-file-system "$root"
}

# The Debian mirror the host uses (deb822 or one-line sources), so a root of either release
# comes from the same archive as the host's own packages.
host_mirror() {
  local f line
  for f in /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list /etc/apt/sources.list; do
    [[ -s "$f" ]] || continue
    while read -r line; do
      [[ "$line" =~ ^[^#]*(https?://[^ ]+/debian)/?( |$) ]] && { echo "${BASH_REMATCH[1]}"; return 0; }
    done < "$f"
  done
  return 0
}

# deb822 sources for RELEASE: the release, its updates and its security archive, signed by the
# keys in debian-archive-keyring (which on Debian 12 holds Debian 13's keys too).
release_sources() {
  local release=$1 mirror=$2
  printf 'Types: deb\nURIs: %s\nSuites: %s %s-updates\nComponents: main\nSigned-By: %s\n\n' \
    "$mirror" "$release" "$release" /usr/share/keyrings/debian-archive-keyring.gpg
  printf 'Types: deb\nURIs: %s-security\nSuites: %s-security\nComponents: main\nSigned-By: %s\n' \
    "$mirror" "$release" /usr/share/keyrings/debian-archive-keyring.gpg
}

case "$action" in
  create)
    [[ $# -eq 3 ]] || usage
    release=$3
    case "$release" in
      bookworm) version=12 ;;
      trixie) version=13 ;;
      *) echo "fresh-root: release '$release' is not one we build for: bookworm (Debian 12) or trixie (Debian 13)" >&2; exit 2 ;;
    esac
    command -v mmdebstrap >/dev/null || { echo "fresh-root: mmdebstrap missing: packaging/install-deps.sh --checks" >&2; exit 2; }
    mirror=$(host_mirror)
    [[ -n "$mirror" ]] || { echo "fresh-root: no Debian mirror in this host's apt sources" >&2; exit 2; }
    [[ -e "$root" ]] && remove_root
    mkdir -p "$(dirname "$root")"
    sources=$(mktemp --suffix=.sources)
    trap 'rm -f "$sources"' EXIT
    release_sources "$release" "$mirror" > "$sources"
    # Root mode creates the device nodes in the root itself; no bind mount of /dev is needed.
    mmdebstrap --quiet --variant=minbase --mode=root "$release" "$root" "$sources"
    cp /etc/resolv.conf "$root/etc/resolv.conf"
    mkdir -p "$root/src"
    echo "fresh-root: Debian $version ($release) minimal root at $root ($(chroot "$root" dpkg-query -W | wc -l) packages)"
    ;;
  run)
    [[ $# -eq 3 ]] || usage
    [[ -x "$root/usr/bin/apt-get" ]] || { echo "fresh-root: $root is not a root made by create" >&2; exit 2; }
    mkdir -p "$apt_cache/partial"
    [[ -z "$compiler_cache" ]] || mkdir -p "$compiler_cache"
    # unshare gives a private mount namespace (propagation private): these mounts are
    # invisible to the host and vanish when the command ends, however it ends.
    unshare --mount --fork -- bash -euc '
      root=$1 src=$2 cache=$3 compiler_cache=$4 command=$5
      mount -t proc proc "$root/proc"
      # A pty instance of its own, for apt and dpkg logs.
      mount -t devpts -o newinstance,ptmxmode=0666 devpts "$root/dev/pts"
      mount --bind "$src" "$root/src"
      mount --bind "$cache" "$root/var/cache/apt/archives"
      launcher=()
      if [[ -n "$compiler_cache" ]]; then
        mkdir -p "$root/var/cache/ccache"
        mount --bind "$compiler_cache" "$root/var/cache/ccache"
        # CMake (3.17 and later) takes the launcher from the environment, so the commands run
        # in the root, the README'"'"'s among them, stay verbatim.
        # CCACHE_BASEDIR: paths under /src hashed relative to the compiling folder, so a second
        # build folder of the same tree (.ci/run'"'"'s build-venv) is compiled from the cache.
        launcher=(CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
          CCACHE_DIR=/var/cache/ccache CCACHE_BASEDIR=/src CCACHE_COMPILERCHECK=content CCACHE_MAXSIZE=8G)
      fi
      exec chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI="${CI:-}" \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "${launcher[@]}" \
        DEBIAN_FRONTEND=noninteractive /bin/bash -euo pipefail -c "cd /src && $command"
    ' fresh-root "$root" "$source_dir" "$apt_cache" "$compiler_cache" "$3"
    ;;
  remove)
    remove_root
    ;;
  *) usage ;;
esac
