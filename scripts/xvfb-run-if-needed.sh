#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Run a command with an X display: the current one if it answers, otherwise a
# private Xvfb (24-bit, large enough for 1200x768 renderings; Mesa llvmpipe
# gives OpenGL 4.5 with tessellation shaders). -noreset: by default an X
# server resets when its last client disconnects and drops connections made
# during the reset, so that processes starting while another one ends (ctest
# -j, MPI ranks) would fail at random with "bad X server connection".
set -euo pipefail
if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1920x1200x24 +extension GLX -noreset" "$@"
