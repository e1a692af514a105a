#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The installed SplineViz, as another project and a ParaView user see it.
#
#   TestInstall.sh install    CMAKE BUILD PREFIX PYDEST
#       cmake --install into PREFIX (emptied first); the layout is checked
#       (PYDEST: the Python package's folder under PREFIX, as VTK's CMake
#       package chose it: lib/python3.11/site-packages with ParaView 5.11,
#       lib/python3/dist-packages with Debian 13's VTK 9.3).
#   TestInstall.sh downstream CMAKE BUILD PREFIX WORK PYTHON
#       builds Downstream/ with find_package(SplineViz) against PREFIX only
#       (one program linking SplineViz::SplineViz, one only SplineViz::IO,
#       which must not load any rendering library), runs them on .tck files
#       written by write_tck.py (3 and 7 streamlines) and on a damaged file
#       (must fail: negative control).
#   TestInstall.sh python     CMAKE BUILD PREFIX PYDEST WORK PYTHON
#       PYTHON (the Python of the VTK built against) imports the installed
#       package and reads a .tck with it.
#   TestInstall.sh plugin     CMAKE BUILD PREFIX PYDEST WORK PYTHON PVBATCH
#       pvbatch loads the installed plugin through its .plugins file
#       (PV_PLUGIN_CONFIG_FILE) and, without it, by the path the installed
#       `splineviz` package finds; reads a .tck with it (TestInstalledPlugin.py).
# Nothing of the build tree is on any search path (the installed RUNPATHs
# must be enough).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mode="$1" cmake="$2" build="$3" prefix="$4"
unset LD_LIBRARY_PATH PYTHONPATH PV_PLUGIN_PATH PV_PLUGIN_CONFIG_FILE SPLINEVIZ_PLUGIN
fail() { echo "ERROR: $*" >&2; exit 1; }

config_var() { # the value of a variable the installed SplineVizConfig.cmake sets
  grep -o "SplineViz_$1: .*" "$work/configure.log" | head -n1 | sed "s/^SplineViz_$1: //"
}

case "$mode" in
install)
  rm -rf "$prefix"
  "$cmake" --install "$build" --prefix "$prefix" >/dev/null
  for f in lib/cmake/splineviz/SplineVizConfig.cmake lib/cmake/splineviz/SplineVizConfigVersion.cmake \
    lib/cmake/splineviz/SplineViz-targets.cmake include/splineviz/vtkTractogramReader.h \
    include/splineviz/SplineVizIOModule.h include/splineviz/vtkTessellatedTubeMapper.h; do
    [ -e "$prefix/$f" ] || fail "not installed: $f"
  done
  for m in Core Filters IO Rendering; do
    ls "$prefix"/lib/libSplineViz$m.so.* >/dev/null || fail "libSplineViz$m not installed"
  done
  [ -e "$prefix/$5/splineviz/__init__.py" ] || fail "Python package not installed in $prefix/$5"
  echo "installed into $prefix"
  ;;
downstream)
  work="$5" python="$6"
  rm -rf "$work" && mkdir -p "$work"
  # Only the installed tree: no package registry, no build tree.
  "$cmake" -S "$here/Downstream" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log"; fail "find_package(SplineViz) against $prefix failed"; }
  found="$(config_var DIR)"
  [ "$found" = "$prefix/lib/cmake/splineviz" ] || fail "SplineViz found in '$found', not in $prefix"
  "$cmake" --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "build failed"; }
  for n in 3 7; do
    "$python" "$here/write_tck.py" "$work/lines$n.tck" "$n"
  done
  head -c 100 "$work/lines7.tck" >"$work/cut.tck"
  for name in CountStreamlines CountStreamlinesIO; do
    program="$work/build/$name"
    # ldd's output kept whole first: `ldd | grep -q` under pipefail fails at
    # random when grep stops reading at its match and ldd dies of SIGPIPE.
    libs="$(ldd "$program")" || fail "ldd $program failed"
    if grep -q "$build/lib/" <<<"$libs"; then fail "$name loads libraries from the build tree: $libs"; fi
    grep -q "$prefix/lib/libSplineVizIO.so" <<<"$libs" || fail "$name: libSplineVizIO not loaded from $prefix: $libs"
    if [ "$name" = CountStreamlinesIO ] && grep -q "libSplineVizRendering\|libvtkRendering" <<<"$libs"; then
      fail "$name (SplineViz::IO only) loads a rendering library: $libs"
    fi
    for n in 3 7; do
      out="$("$program" "$work/lines$n.tck")"
      echo "$name, $n written: $out"
      # streamline i has i + 2 points: n(n+3)/2 in all
      [ "$out" = "streamlines: $n points: $((n * (n + 3) / 2))" ] || fail "$name read '$out' from $n streamlines"
    done
    # Negative control: a file cut inside its data must be refused.
    if "$program" "$work/cut.tck" >"$work/cut.log" 2>&1; then
      fail "$name read a truncated file: $(cat "$work/cut.log")"
    fi
  done
  echo "truncated file refused"
  ;;
python)
  pythonpath="$prefix/$5" work="$6" python="$7"
  rm -rf "$work" && mkdir -p "$work"
  "$python" "$here/write_tck.py" "$work/lines5.tck" 5
  PYTHONPATH="$pythonpath" "$python" -c "
import splineviz, sys
assert splineviz.__file__.startswith('$prefix'), splineviz.__file__
r = splineviz.vtkTractogramReader(); r.SetFileName('$work/lines5.tck'); r.Update()
assert r.GetOutput().GetNumberOfLines() == 5, r.GetOutput().GetNumberOfLines()
print(sys.executable, 'imported', splineviz.__file__)"
  ;;
plugin)
  pythonpath="$prefix/$5" work="$6" python="$7" pvbatch="$8"
  rm -rf "$work" && mkdir -p "$work"
  "$python" "$here/write_tck.py" "$work/lines5.tck" 5
  plugins_xml="$(ls "$prefix"/lib/paraview-*/plugins/SplineViz.plugins.xml | head -n1)"
  # ParaView's plugin manager reads .plugins files named by PV_PLUGIN_CONFIG_FILE.
  PYTHONPATH="$pythonpath" PV_PLUGIN_CONFIG_FILE="$plugins_xml" \
    "$pvbatch" --force-offscreen-rendering "$here/TestInstalledPlugin.py" "$prefix" "$work/lines5.tck" 5 startup
  PYTHONPATH="$pythonpath" \
    "$pvbatch" --force-offscreen-rendering "$here/TestInstalledPlugin.py" "$prefix" "$work/lines5.tck" 5 by-path
  ;;
*) fail "unknown mode $mode" ;;
esac
