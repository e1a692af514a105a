#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Set up (packages, configure, build), then run the demonstration: render the
# built-in synthetic data sets with the SplineViz renderers to PNG files, and
# fit and render a real OpenFOAM simulation.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SPLINEVIZ_BUILD_DIR:-$here/build}"
out="${1:-$build/demo}"
"$here/scripts/setup.sh"
# shellcheck disable=SC1091
source "$build/splineviz-env.sh"
mkdir -p "$out"
echo "== rendering the demonstration into $out"
"$here/scripts/xvfb-run-if-needed.sh" pvpython "$here/Examples/Python/demo.py" "$out"
# A real simulation: OpenFOAM's porous angled duct (run once, about 15 s, and
# cached in the build tree), fitted by LR splines at 1 % and volume rendered
# trimmed by the mesh's boundary, with streamlines (about 30 s).
echo "== the OpenFOAM case fitted and rendered (Examples/Python/lr_spline_fit_openfoam.py)"
foam="$("$here/scripts/openfoam-case.sh")"
"$here/scripts/xvfb-run-if-needed.sh" pvpython "$here/Examples/Python/lr_spline_fit_openfoam.py" \
  "$foam" "$out"
echo "== demo images:"
ls -1 "$out"/*.png
