#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# ParaView's parallel pipeline with ray-cast tubes: renders the scene with
# one pvbatch process and with two MPI ranks (IceT compositing), then
# compares the images (TestParallelRayCastTubes.py).
#   TestParallelRayCastTubes.sh PVBATCH MPIEXEC PVPYTHON OUTPUT_DIR
set -euo pipefail
pvbatch="$1" mpiexec="$2" pvpython="$3" out="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene="$here/ParallelRayCastTubesScene.py"
mkdir -p "$out"
. "$here/parallel_attempt.sh"
attempt "$pvbatch" --force-offscreen-rendering "$scene" "$out/TestParallelRayCastTubes-1rank.png"
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" \
  "$out/TestParallelRayCastTubes-2ranks.png"
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" \
  "$out/TestParallelRayCastTubes-2ranks-by-rank.png" by-rank
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" \
  "$out/TestParallelRayCastTubes-2ranks-culling.png" culling
attempt "$pvbatch" --force-offscreen-rendering "$scene" \
  "$out/TestParallelRayCastTubes-1rank-automatic.png" automatic
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" \
  "$out/TestParallelRayCastTubes-2ranks-automatic.png" automatic
"$pvpython" "$here/TestParallelRayCastTubes.py" "$out"
