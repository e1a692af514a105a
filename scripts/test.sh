#!/usr/bin/env bash
# Set up (packages, configure, build), then run every test with ctest
# (C++ image and unit tests, Python tests, the ParaView plugin tests) on an
# X display of its own when there is none.
#
#   scripts/test.sh                 # everything
#   scripts/test.sh -R RayCast      # extra arguments go to ctest
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SPLINEVIZ_BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh"
cd "$build"
# Exercise the threaded code paths (vtkSMPTools is sequential by default).
export VTK_SMP_BACKEND_IN_USE="${VTK_SMP_BACKEND_IN_USE:-STDThread}"
echo "== running the tests"
"$here/scripts/xvfb-run-if-needed.sh" ctest --output-on-failure --timeout 900 "$@"
echo "== test images (rendered and, for failures, differences): $build/Testing/Temporary"
