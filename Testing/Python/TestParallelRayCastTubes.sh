#!/usr/bin/env bash
# ParaView's parallel pipeline with ray-cast tubes: renders the scene with
# one pvbatch process and with two MPI ranks (IceT compositing), then
# compares the images (TestParallelRayCastTubes.py).
#   TestParallelRayCastTubes.sh PVBATCH MPIEXEC PVPYTHON OUTPUT_DIR
set -euo pipefail
pvbatch="$1" mpiexec="$2" pvpython="$3" out="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene="$here/ParallelRayCastTubesScene.py"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# A run that cannot start is retried once: an MPI start-up hang, or an X
# connection reset because an X server without -noreset (a user's display;
# scripts/xvfb-run-if-needed.sh passes it) reset when one rank's probe
# connection closed. The images are compared only when made.
attempt() {
  for try in 1 2; do
    if timeout --kill-after=10 240 "$@" < /dev/null; then
      return 0
    fi
    echo "run failed or timed out (try $try): $*"
  done
  echo "ERROR: could not render: $*"
  return 1
}
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
