#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The tractogram reader under MPI: a small .tck (written by nibabel) drawn as
# ray-cast tubes by one pvbatch process and by two MPI ranks that each read
# only their half of the file; compares the images and the ranks' shares
# (TestParallelTractogram.py); then two ranks on the file damaged in the
# second rank's half.
#   TestParallelTractogram.sh PVBATCH MPIEXEC PVPYTHON OUTPUT_DIR
set -euo pipefail
pvbatch="$1" mpiexec="$2" pvpython="$3" out="$4/TestParallelTractogram"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene="$here/TestParallelTractogramScene.py"
mkdir -p "$out"
rm -f "$out"/*.png "$out"/*.json
. "$here/parallel_attempt.sh"
"$pvpython" "$here/TestParallelTractogram.py" make "$out"
attempt "$pvbatch" --force-offscreen-rendering "$scene" "$out" 1rank
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" "$out" 2ranks
# A piece damaged on one rank: once, without retry (a hang is the failure).
status=0
timeout --kill-after=10 180 "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering \
  "$scene" "$out" 2ranks-damaged < /dev/null > "$out/2ranks-damaged.log" 2>&1 || status=$?
echo "$status" > "$out/2ranks-damaged.status"
"$pvpython" "$here/TestParallelTractogram.py" compare "$out"
