#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Set up (packages, configure, build), then run every test with ctest
# (C++ image and unit tests, Python tests, the ParaView plugin tests) on an
# X display of its own when there is none.
#
#   scripts/test.sh                 # everything
#   scripts/test.sh -R RayCast      # extra arguments go to ctest
#   scripts/test.sh --sanitize      # the same in the sanitizer build:
#                                   # clang, ASan + UBSan (+ LeakSanitizer),
#                                   # libFuzzer targets, in build-sanitize/
#   scripts/test.sh --ci            # without the slowest GL image tests
#                                   # (Testing/Sanitizers/ci-exclude.txt),
#                                   # as CI's Debian 13 legs run it
#   scripts/test.sh --sanitize --ci # the sanitizer subset CI runs (see
#                                   # docs/reliability.md)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sanitize=""
ci_subset=""
args=()
for a in "$@"; do
  case "$a" in
    --sanitize) sanitize=1 ;;
    --ci) ci_subset=1 ;;
    *) args+=("$a") ;;
  esac
done
if [ -n "$sanitize" ]; then
  build="${SPLINEVIZ_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
  # -O1: the usual optimisation for sanitized code (fast enough, exact
  # stacks); asserts stay on. The normal build (build/) is not affected.
  export SPLINEVIZ_CMAKE_ARGS="-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
-DCMAKE_C_FLAGS_RELEASE=-O1 -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
-DSPLINEVIZ_SANITIZE=ON -DSPLINEVIZ_FUZZ=ON ${SPLINEVIZ_CMAKE_ARGS:-}"
  if [ -n "$ci_subset" ]; then
    # CI's time budget: no plugin and no benchmark programs (the plugin's
    # pvbatch tests run in the normal suite and in the full sanitizer run).
    SPLINEVIZ_CMAKE_ARGS="$SPLINEVIZ_CMAKE_ARGS -DSPLINEVIZ_BUILD_PLUGIN=OFF -DSPLINEVIZ_BUILD_BENCHMARKS=OFF"
  else
    SPLINEVIZ_CMAKE_ARGS="$SPLINEVIZ_CMAKE_ARGS -DSPLINEVIZ_BUILD_PLUGIN=ON -DSPLINEVIZ_BUILD_BENCHMARKS=ON"
  fi
else
  build="${SPLINEVIZ_BUILD_DIR:-$here/build}"
fi
SPLINEVIZ_BUILD_DIR="$build" "$here/scripts/setup.sh"
cd "$build"
# Exercise the threaded code paths (vtkSMPTools is sequential by default).
export VTK_SMP_BACKEND_IN_USE="${VTK_SMP_BACKEND_IN_USE:-STDThread}"
timeout=900
if [ -n "$sanitize" ]; then
  timeout=2700
  export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer || true)}"
fi
if [ -n "$ci_subset" ]; then
  # Every test but the ones listed in Testing/Sanitizers/ci-exclude.txt
  # (slow GL image tests whose code paths other GL tests cover).
  exclude="$(grep -v '^#' "$here/Testing/Sanitizers/ci-exclude.txt" | grep -v '^$' | paste -sd '|' || true)"
  # ctest keeps only its last -E: a caller's own -E joins the list.
  merged=()
  n=${#args[@]}
  i=0
  while [ "$i" -lt "$n" ]; do
    if [ "${args[$i]}" = "-E" ] && [ $((i + 1)) -lt "$n" ]; then
      exclude="${exclude:+$exclude|}${args[$((i + 1))]}"
      i=$((i + 2))
    else
      merged+=("${args[$i]}")
      i=$((i + 1))
    fi
  done
  args=(${merged[@]+"${merged[@]}"})
  if [ -n "$exclude" ]; then
    args=(-E "$exclude" ${args[@]+"${args[@]}"})
  fi
fi
echo "== running the tests${sanitize:+ (sanitizer build)}"
# As many tests at once as there are cores (SPLINEVIZ_TEST_JOBS to change it):
# the GL tests share the X display, the MPI tests oversubscribe, both fine.
jobs="${SPLINEVIZ_TEST_JOBS:-$(nproc)}"
"$here/scripts/xvfb-run-if-needed.sh" ctest --output-on-failure --timeout "$timeout" -j "$jobs" \
  ${args[@]+"${args[@]}"}
echo "== test images (rendered and, for failures, differences): $build/Testing/Temporary"
