#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Run a small 3D OpenFOAM tutorial for the LR-spline fitting demo
# (Examples/Python/lr_spline_fit_openfoam.py): the porous angled duct of
# porousSimpleFoam (22,000 hexahedra, 200 steady iterations; about 15 s on
# 2 cores). Installs Debian's OpenFOAM and its tutorials when missing
# (unless SPLINEVIZ_NO_INSTALL is set: then it fails).
#   scripts/openfoam-case.sh [case-dir]     (default: build/openfoam/angledDuct)
# Prints the case's .foam file for ParaView's OpenFOAM reader.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case_dir="${1:-$here/build/openfoam/angledDuct}"
tutorial=/usr/share/doc/openfoam-examples/examples/incompressible/porousSimpleFoam/angledDuct
if [ ! -d "$tutorial" ] || ! command -v porousSimpleFoam >/dev/null; then
  if [ -n "${SPLINEVIZ_NO_INSTALL:-}" ]; then
    echo "error: Debian's openfoam and openfoam-examples are not installed (scripts/setup.sh installs them)" >&2
    exit 1
  fi
  echo "== installing Debian's openfoam and openfoam-examples" >&2
  apt-get install -y openfoam openfoam-examples >&2
fi
if [ -f "$case_dir/200/U" ]; then
  echo "$case_dir/case.foam"
  exit 0
fi
rm -rf "$case_dir"
mkdir -p "$case_dir"
cp -r "$tutorial/explicit/system" "$case_dir/"
cp -r "$tutorial/common/0.orig" "$case_dir/0"
cp -r "$tutorial/common/constant" "$case_dir/constant"
# (links to the common file; Debian 12 ships it compressed, Debian 13 not)
rm -f "$case_dir/system/blockMeshDict.m4.gz" "$case_dir/system/blockMeshDict.m4"
if [ -f "$tutorial/common/blockMeshDict.m4.gz" ]; then
  zcat "$tutorial/common/blockMeshDict.m4.gz" > "$case_dir/system/blockMeshDict.m4"
else
  cp "$tutorial/common/blockMeshDict.m4" "$case_dir/system/blockMeshDict.m4"
fi
find "$case_dir" -name "*.gz" -exec gunzip -f {} +
m4 "$case_dir/system/blockMeshDict.m4" > "$case_dir/system/blockMeshDict"
(
  cd "$case_dir"
  # shellcheck disable=SC1091
  set +u
  source /usr/share/openfoam/etc/bashrc >/dev/null 2>&1 || true
  set -u
  echo "== blockMesh, porousSimpleFoam in $case_dir" >&2
  blockMesh > log.blockMesh 2>&1
  start=$(date +%s)
  porousSimpleFoam > log.porousSimpleFoam 2>&1
  echo "== porousSimpleFoam: $(($(date +%s) - start)) s" >&2
)
touch "$case_dir/case.foam"
echo "$case_dir/case.foam"
