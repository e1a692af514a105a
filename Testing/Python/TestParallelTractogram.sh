#!/usr/bin/env bash
# The tractogram reader under MPI: a small .tck (written by nibabel) drawn as
# ray-cast tubes by one pvbatch process and by two MPI ranks that each read
# only their half of the file; compares the images and the ranks' shares
# (TestParallelTractogram.py).
#   TestParallelTractogram.sh PVBATCH MPIEXEC PVPYTHON OUTPUT_DIR
set -euo pipefail
pvbatch="$1" mpiexec="$2" pvpython="$3" out="$4/TestParallelTractogram"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene="$here/TestParallelTractogramScene.py"
mkdir -p "$out"
rm -f "$out"/*.png "$out"/*.json
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# A run that cannot start is retried once (an MPI start-up hang, an X
# connection reset: see TestParallelRayCastTubes.sh).
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
"$pvpython" "$here/TestParallelTractogram.py" make "$out"
attempt "$pvbatch" --force-offscreen-rendering "$scene" "$out" 1rank
attempt "$mpiexec" --oversubscribe -np 2 "$pvbatch" --force-offscreen-rendering "$scene" "$out" 2ranks
"$pvpython" "$here/TestParallelTractogram.py" compare "$out"
