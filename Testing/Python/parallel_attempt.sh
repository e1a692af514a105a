# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the MPI tests' scripts (TestParallel*.sh): attempt COMMAND...
# runs a pvbatch or mpiexec command, retried once when it cannot start or
# finish (an MPI start-up hang, or an X connection reset because an X server
# without -noreset, e.g. a user's display, reset when one rank's probe
# connection closed; scripts/xvfb-run-if-needed.sh passes -noreset).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
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
