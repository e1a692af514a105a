#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Run the libFuzzer targets of the sanitizer build (scripts/test.sh --sanitize
# builds them in build-sanitize/), one after the other. The targets, their
# seeds and input size limits are listed in Testing/Fuzz/targets.txt.
#
#   scripts/fuzz.sh                    # 120 s per target
#   scripts/fuzz.sh --time 600         # seconds per target
#   scripts/fuzz.sh --runs 1000000     # a long campaign: 10^6 executions per target
#   scripts/fuzz.sh --runs 1000000 FuzzG2Parser   # one target
#   scripts/fuzz.sh --time 45 --parallel           # CI: as many at once as there
#                                                  # are cores (SPLINEVIZ_FUZZ_JOBS)
#
# Every target starts from its seeds (Testing/Fuzz/corpus/, the real files in
# Testing/Data/External/, the regression inputs) and keeps what it learns in
# build-sanitize/fuzz/corpus-<target>/ (reused by the next run). An input that
# crashes, leaks, takes more than 1 s (-timeout=1) or more than 2 GiB
# (-rss_limit_mb) is written to build-sanitize/fuzz/ and fails the run: copy
# it to Testing/Fuzz/regressions/<target>/ once it is fixed (ctest replays
# that folder). The last lines of each run (executions, coverage) are printed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SPLINEVIZ_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
limit=(-max_total_time=120)
targets=()
parallel=""
while [ $# -gt 0 ]; do
  case "$1" in
    --parallel) parallel=1; shift ;;
    --time) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
fuzz="$here/Testing/Fuzz"
table="$fuzz/targets.txt"
# column $2 of target $1's line in the table
column() { awk -v t="$1" -v c="$2" '$1 == t { print $c }' "$table"; }
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(awk '/^[A-Za-z]/ { print $1 }' "$table")
fi
work="$build/fuzz"
mkdir -p "$work"
export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer || true)}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}"
# The leak suppressions of the sanitizer build (each proven outside SplineViz).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$here/Testing/Sanitizers/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# The targets are single-threaded (one input at a time); VTK's SMP tools
# stay sequential so that a crash points at the input that caused it.
export VTK_SMP_BACKEND_IN_USE=Sequential
run_target() {
  local t="$1" exe seeds ext log start maxlen globs c g f
  exe="$build/bin/$t"
  if [ ! -x "$exe" ]; then
    echo "ERROR: $exe not built (scripts/test.sh --sanitize builds it)" >&2
    return 1
  fi
  if [ -z "$(column "$t" 1)" ]; then
    echo "ERROR: $t is not in $table" >&2
    return 1
  fi
  seeds=()
  for c in $(column "$t" 2 | tr ',' ' '); do
    seeds+=("$fuzz/corpus/$c")
  done
  maxlen="$(column "$t" 3)"
  # The real files (large ones too: -max_len cuts them, truncated files are
  # good inputs as well).
  ext="$work/external-$t"
  mkdir -p "$ext"
  globs="$(column "$t" 4)"
  if [ "$globs" != "-" ]; then
    for g in $(echo "$globs" | tr ',' ' '); do
      for f in "$here"/Testing/Data/External/$g; do
        if [ -f "$f" ]; then cp -f "$f" "$ext/"; fi
      done
    done
  fi
  if [ -d "$fuzz/regressions/$t" ]; then
    seeds+=("$fuzz/regressions/$t")
  fi
  mkdir -p "$work/corpus-$t"
  log="$work/$t.log"
  start=$(date +%s)
  if "$exe" "${limit[@]}" -timeout=1 -rss_limit_mb=2048 -max_len="$maxlen" \
      -print_final_stats=1 -artifact_prefix="$work/$t-" \
      "$work/corpus-$t" "${seeds[@]}" "$ext" >"$log" 2>&1; then
    echo "== $t (${limit[*]}): ok after $(( $(date +%s) - start )) s"
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb)|^#[0-9]+.*DONE" "$log" | tail -3 || true
    return 0
  fi
  echo "ERROR: $t found a problem (input in $work/$t-*); the end of its log:"
  tail -60 "$log"
  return 1
}

status=0
if [ -n "$parallel" ]; then
  # As many targets at once as there are cores: more would starve them into
  # libFuzzer's 1 s limit per input.
  jobs="${SPLINEVIZ_FUZZ_JOBS:-$(nproc)}"
  pids=()
  names=()
  for t in "${targets[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
      sleep 1
    done
    run_target "$t" > "$work/$t.summary" 2>&1 &
    pids+=($!)
    names+=("$t")
  done
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || status=1
    cat "$work/${names[$i]}.summary"
  done
else
  for t in "${targets[@]}"; do
    run_target "$t" || status=1
  done
fi
exit $status
