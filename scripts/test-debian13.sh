#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Build SplineViz and run its test suite on Debian 13 ("trixie": ParaView
# 5.13.2 with VTK 9.3, Python 3.13, a newer Mesa) inside a debootstrap root,
# beside the Debian 12 host (ParaView 5.11). Two configurations, each in a
# root of its own (Debian's python3-paraview and python3-vtk9 both ship
# `vtkmodules`, so they cannot be installed together):
#
#   scripts/test-debian13.sh                 # ParaView 5.13: module, Python
#                                            # package, plugin; every test
#   scripts/test-debian13.sh --vtk           # plain VTK 9.3 (libvtk9-dev,
#                                            # python3-vtk9), no ParaView: the
#                                            # module, its Python package in
#                                            # Debian's python3, the tests
#                                            # that need no plugin
#   scripts/test-debian13.sh -R Plugin       # extra arguments go to
#                                            # scripts/test.sh (--ci) and
#                                            # ctest
#   scripts/test-debian13.sh --prepare [--vtk]   # only bootstrap the root and
#                                            # install its packages (.ci/run
#                                            # does this while the host builds)
#   SPLINEVIZ_DEBIAN13_DIR=/some/dir scripts/test-debian13.sh
#
# Needs root (debootstrap, chroot, mounts) and the network for the first run.
# The roots, their packages, the build trees and a ccache live under
# $SPLINEVIZ_DEBIAN13_DIR (default /var/cache/splineviz-debian13) and are
# reused: a first run bootstraps and installs, later runs only rebuild what
# changed. The sources are a copy of this working tree (uncommitted changes
# are tested too). Mounts live in a private mount namespace and vanish when
# the script ends. Times from nothing on the idle 2-core machine: see
# docs/testing.md.
# SPLINEVIZ_DEBIAN13_MIRROR: the package mirror (default: the host's).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${SPLINEVIZ_DEBIAN13_DIR:-/var/cache/splineviz-debian13}"
flavour=paraview
in_namespace=""
prepare=""
ctest_args=()
for a in "$@"; do
  case "$a" in
    --vtk) flavour=vtk ;;
    --prepare) prepare=1 ;;
    --in-namespace) in_namespace=1 ;;
    *) ctest_args+=("$a") ;;
  esac
done
flavour_args=()
if [ "$flavour" = vtk ]; then
  flavour_args+=(--vtk)
fi
if [ -n "$prepare" ]; then
  flavour_args+=(--prepare)
fi

# Both roots: the build tools, Xvfb and Mesa for headless rendering, the
# Python packages the independent references of the tests use (NiBabel,
# DIPY, h5py) and OpenFOAM with its tutorials (the real CFD case of the
# LR-spline fitting tests).
common_packages=(
  build-essential cmake ccache
  python3-dev python3-numpy python3-nibabel python3-dipy python3-h5py
  libglm-dev xvfb xauth x11-utils libgl1-mesa-dri
  openfoam openfoam-examples m4
)
# What Debian 13's ParaView 5.13 CMake package needs to configure (its
# find_dependency calls: more third-party -dev packages than 5.11's).
paraview_packages=(
  paraview-dev python3-paraview
  qtbase5-dev libqt5svg5-dev qttools5-dev qtxmlpatterns5-dev-tools
  mpi-default-dev libhdf5-dev libeigen3-dev
  libdouble-conversion-dev libutfcpp-dev liblz4-dev libtiff-dev libexpat1-dev
  libfreetype-dev libjpeg-dev liblzma-dev libpng-dev zlib1g-dev libx11-dev
  libgl-dev libopengl-dev libglx-dev libxt-dev libjsoncpp-dev libpugixml-dev
  libcgns-dev libnetcdf-dev libprotobuf-dev protobuf-compiler libgl2ps-dev
  libtheora-dev libogg-dev libsqlite3-dev libxml2-dev libfmt-dev
  libexodusii-dev libfast-float-dev libcli11-dev nlohmann-json3-dev
  libexprtk-dev libglew-dev
)
# Plain VTK 9.3: its -dev package pulls the libraries its CMake package needs.
vtk_packages=(libvtk9-dev python3-vtk9)
if [ "$flavour" = vtk ]; then
  root="$cache/root-vtk"
  build_dir="$cache/build-vtk"
  packages=("${common_packages[@]}" "${vtk_packages[@]}")
  # The plain VTK's CMake package (ParaView is not installed in this root),
  # no plugin.
  cmake_args="-DSPLINEVIZ_BUILD_PLUGIN=OFF -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/vtk-9.3"
else
  root="$cache/root"
  build_dir="$cache/build"
  packages=("${common_packages[@]}" "${paraview_packages[@]}")
  cmake_args=""
fi

if [ -z "$in_namespace" ]; then
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
      exec sudo --preserve-env=SPLINEVIZ_DEBIAN13_DIR,SPLINEVIZ_DEBIAN13_MIRROR "$0" "$@"
    fi
    echo "test-debian13.sh needs root (debootstrap, chroot, mounts) and there is no sudo" >&2
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
  exec unshare --mount --propagation private "$0" --in-namespace "${flavour_args[@]}" \
    ${ctest_args[@]+"${ctest_args[@]}"}
fi

start=$(date +%s)
stage() { echo "== [debian13 $flavour $(( $(date +%s) - start )) s] $*"; }
src="$cache/src-$flavour"
mkdir -p "$root/src" "$root/build" "$root/ccache" "$build_dir" "$cache/ccache"
# A copy of the working tree (tracked and untracked files, not ignored ones;
# modification times kept, so that only changed files are rebuilt): the tree
# may be edited while this runs (bash reads scripts as it goes).
rm -rf "$src" && mkdir -p "$src"
(cd "$here" && git ls-files -z --cached --others --exclude-standard |
  tar --null --files-from=- --ignore-failed-read -cf - 2>/dev/null) | tar -xf - -C "$src"
mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev"
mount --rbind /sys "$root/sys" # hwloc (MPI) reads the CPU topology there
mount --bind "$src" "$root/src"
mount -o remount,bind,ro "$root/src"
mount --bind "$build_dir" "$root/build"
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
stage "$(in_root dpkg-query -W -f='${Package} ${Version}, ' paraview-dev libvtk9-dev cmake \
  mesa-libgallium 2>/dev/null || true)"
if [ -n "$prepare" ]; then
  stage "prepared"
  exit 0
fi

stage "configure, build and test"
status=0
in_root /bin/bash -c 'cd /src && SPLINEVIZ_SKIP_INSTALL=1 SPLINEVIZ_BUILD_DIR=/build CCACHE_DIR=/ccache \
  SPLINEVIZ_CMAKE_ARGS="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
-DSPLINEVIZ_BUILD_BENCHMARKS=OFF $0" scripts/test.sh "$@"' "$cmake_args" \
  ${ctest_args[@]+"${ctest_args[@]}"} || status=$?
stage "done (status $status)"
exit "$status"
