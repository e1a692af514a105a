#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Set up (packages, configure, build), then run the demonstration: render the
# built-in synthetic data sets with the SplineViz renderers to PNG files.
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
echo "== demo images:"
ls -1 "$out"/*.png
