#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install what SplineViz needs (Debian 12 packages; idempotent, non-interactive),
# then configure and build it in ./build (or $SPLINEVIZ_BUILD_DIR).
#
#   scripts/setup.sh            # install missing packages, configure, build
#   SPLINEVIZ_SKIP_INSTALL=1 scripts/setup.sh   # do not touch packages
#   SPLINEVIZ_CMAKE_ARGS="..." scripts/setup.sh  # extra configure options
#                                  (scripts/test.sh --sanitize uses them)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SPLINEVIZ_BUILD_DIR:-$here/build}"

# ParaView 5.11 with its own VTK 9.2 and the development packages its CMake
# package needs for the components SplineViz uses; Xvfb for headless
# rendering (Mesa llvmpipe: OpenGL 4.5 with tessellation); GLM; DIPY for the
# real diffusion data of the tensor examples; NiBabel, the independent
# implementation the neuroimaging IO tests compare with; h5py, with which the
# IFEM reader's tests read the HDF5 files independently (libhdf5-dev is the
# library the reader itself uses); OpenFOAM and its tutorials, the real CFD
# case of the LR-spline fitting test and example (scripts/openfoam-case.sh);
# clang with its
# sanitizer and libFuzzer runtimes and llvm-symbolizer for the sanitizer build.
packages=(
  build-essential cmake
  paraview-dev python3-paraview
  qtbase5-dev libqt5svg5-dev qttools5-dev qtxmlpatterns5-dev-tools
  mpi-default-dev libhdf5-dev libdouble-conversion-dev libutfcpp-dev
  libglew-dev liblz4-dev libtiff-dev libexpat1-dev libeigen3-dev
  libfreetype-dev libjpeg-dev liblzma-dev libpng-dev zlib1g-dev libx11-dev
  libgl-dev libopengl-dev libglx-dev python3-dev python3-numpy
  libglm-dev
  xvfb xauth x11-utils
  python3-dipy python3-nibabel python3-h5py
  openfoam openfoam-examples m4
  clang libclang-rt-14-dev llvm
)

if [ -z "${SPLINEVIZ_SKIP_INSTALL:-}" ]; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "== installing: ${missing[*]}"
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -q
    $sudo apt-get install -y -q "${missing[@]}"
  else
    echo "== all packages present"
  fi
fi

echo "== configuring $build"
# shellcheck disable=SC2086 # SPLINEVIZ_CMAKE_ARGS is a list of options
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release ${SPLINEVIZ_CMAKE_ARGS:-}
echo "== building with $(nproc) jobs"
cmake --build "$build" -j "$(nproc)"
echo "== built; to use it: source $build/splineviz-env.sh"
