#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Build SplineViz and run its test suite on Debian 13 ("trixie": ParaView
# 5.13.2 with VTK 9.3, Python 3.13, a newer Mesa) inside a debootstrap root,
# beside the Debian 12 host (ParaView 5.11). Needs root (debootstrap, chroot,
# mounts) and the network for the first run.
#
#   scripts/test-debian13.sh                 # everything
#   scripts/test-debian13.sh -R Plugin       # extra arguments go to ctest
#   SPLINEVIZ_DEBIAN13_DIR=/some/dir scripts/test-debian13.sh
#
# The root, its packages, the build tree and a ccache live under
# $SPLINEVIZ_DEBIAN13_DIR (default /var/cache/splineviz-debian13) and are
# reused: the first run bootstraps and installs (about 4 minutes) and builds
# from scratch; later runs only update what changed. The sources are a copy
# of this working tree (uncommitted changes are tested too).
# Mounts live in a private mount namespace and vanish when the script ends.
# Measured on the 2-core machine (loaded by other builds): bootstrap 78 s,
# packages 8.5 min, build about 27 min, suite 30 min (ctest -j2): about an
# hour from nothing, so it is not part of .ci/run (which uses 30-40 of its
# 60 minutes already).
# SPLINEVIZ_DEBIAN13_MIRROR: the package mirror (default: the host's).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${SPLINEVIZ_DEBIAN13_DIR:-/var/cache/splineviz-debian13}"
root="$cache/root"

# What Debian 13's ParaView 5.13 CMake package needs to configure (its
# find_dependency calls: more third-party -dev packages than 5.11's), the
# build tools, Xvfb and Mesa for headless rendering, and the Python packages
# the independent references of the tests use (NiBabel, DIPY, h5py).
packages=(
  build-essential cmake ccache
  paraview-dev python3-paraview
  qtbase5-dev libqt5svg5-dev qttools5-dev qtxmlpatterns5-dev-tools
  mpi-default-dev libhdf5-dev libglm-dev libeigen3-dev
  libdouble-conversion-dev libutfcpp-dev liblz4-dev libtiff-dev libexpat1-dev
  libfreetype-dev libjpeg-dev liblzma-dev libpng-dev zlib1g-dev libx11-dev
  libgl-dev libopengl-dev libglx-dev libxt-dev libjsoncpp-dev libpugixml-dev
  libcgns-dev libnetcdf-dev libprotobuf-dev protobuf-compiler libgl2ps-dev
  libtheora-dev libogg-dev libsqlite3-dev libxml2-dev libfmt-dev
  libexodusii-dev libfast-float-dev libcli11-dev nlohmann-json3-dev
  libexprtk-dev libglew-dev
  python3-dev python3-numpy python3-nibabel python3-dipy python3-h5py
  xvfb xauth x11-utils libgl1-mesa-dri
)

if [ "${1:-}" != "--in-namespace" ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "test-debian13.sh needs root (debootstrap, chroot, mounts)" >&2
    exit 2
  fi
  start=$(date +%s)
  mkdir -p "$cache"
  if [ ! -e "$root/.splineviz-bootstrapped" ]; then
    command -v debootstrap >/dev/null ||
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q debootstrap
    mirror="${SPLINEVIZ_DEBIAN13_MIRROR:-}"
    if [ -z "$mirror" ]; then
      # The mirror apt already uses (deb822 or one-line sources).
      mirror="$(grep -h -o -E '(URIs:[[:space:]]*|^deb[[:space:]]+)https?://[^[:space:]]+/debian/?' \
        /etc/apt/sources.list.d/* /etc/apt/sources.list 2>/dev/null | head -n1 |
        sed -E 's/^(URIs:[[:space:]]*|deb[[:space:]]+)//' || true)"
      mirror="${mirror:-http://deb.debian.org/debian}"
    fi
    echo "== [debian13] bootstrapping Debian 13 in $root from $mirror"
    rm -rf "$root"
    debootstrap --variant=minbase trixie "$root" "$mirror"
    touch "$root/.splineviz-bootstrapped"
  fi
  echo "== [debian13] root ready after $(( $(date +%s) - start )) s"
  exec unshare --mount --propagation private "$0" --in-namespace "$@"
fi
shift # --in-namespace

start=$(date +%s)
stage() { echo "== [debian13 $(( $(date +%s) - start )) s] $*"; }
mkdir -p "$root/src" "$root/build" "$root/ccache" "$cache/build" "$cache/ccache"
# A copy of the working tree (tracked and untracked files, not ignored ones;
# modification times kept, so that only changed files are rebuilt): the tree
# may be edited while this runs (bash reads scripts as it goes).
rm -rf "$cache/src" && mkdir -p "$cache/src"
(cd "$here" && git ls-files -z --cached --others --exclude-standard |
  tar --null --files-from=- --ignore-failed-read -cf - 2>/dev/null) | tar -xf - -C "$cache/src"
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mount --rbind /sys "$root/sys" # hwloc (MPI) reads the CPU topology there
mount --bind "$cache/src" "$root/src"
mount -o remount,bind,ro "$root/src"
mount --bind "$cache/build" "$root/build"
mount --bind "$cache/ccache" "$root/ccache"
cp /etc/resolv.conf "$root/etc/resolv.conf"
in_root() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"; }

# Packages: installed again only when the list above changes.
wanted="$(printf '%s\n' "${packages[@]}" | sort)"
if [ "$wanted" != "$(cat "$root/.splineviz-packages" 2>/dev/null)" ]; then
  stage "installing packages"
  in_root apt-get update -q
  in_root apt-get install -y -q --no-install-recommends "${packages[@]}"
  in_root apt-get clean
  printf '%s\n' "$wanted" >"$root/.splineviz-packages"
fi
stage "$(in_root dpkg-query -W -f='${Package} ${Version}, ' paraview-dev cmake mesa-libgallium 2>/dev/null || true)"

stage "configure, build and test"
status=0
in_root /bin/bash -c 'cd /src && SPLINEVIZ_SKIP_INSTALL=1 SPLINEVIZ_BUILD_DIR=/build CCACHE_DIR=/ccache \
  SPLINEVIZ_CMAKE_ARGS="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache -DSPLINEVIZ_BUILD_BENCHMARKS=OFF" \
  scripts/test.sh "$@"' test-debian13 "$@" || status=$?
stage "done (status $status)"
exit "$status"
