#!/usr/bin/env bash
# Run the libFuzzer targets of the sanitizer build (scripts/test.sh --sanitize
# builds them in build-sanitize/), one after the other.
#
#   scripts/fuzz.sh                    # CI: 120 s per target
#   scripts/fuzz.sh --time 600         # seconds per target
#   scripts/fuzz.sh --runs 1000000     # a long campaign: 10^6 executions per target
#   scripts/fuzz.sh --runs 1000000 FuzzG2Parser   # one target
#   scripts/fuzz.sh --time 120 --parallel          # CI: all targets at once
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
if [ ${#targets[@]} -eq 0 ]; then
  targets=(FuzzLRSplineParser FuzzG2Parser FuzzLRSplineReader)
  targets+=(FuzzIFEMReader)
fi
fuzz="$here/Testing/Fuzz"
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
  local t="$1" exe seeds ext log start
  exe="$build/bin/$t"
  if [ ! -x "$exe" ]; then
    echo "ERROR: $exe not built (scripts/test.sh --sanitize builds it)" >&2
    return 1
  fi
  case "$t" in
    FuzzLRSplineParser) seeds=("$fuzz/corpus/lr") ;;
    FuzzG2Parser) seeds=("$fuzz/corpus/g2") ;;
    FuzzIFEMReader) seeds=("$fuzz/corpus/ifem") ;;
    *) seeds=("$fuzz/corpus/lr" "$fuzz/corpus/g2") ;;
  esac
  # The real files (the 1.2 MB .lr too: -max_len cuts it, truncated files are
  # good inputs as well).
  ext="$work/external-$t"
  mkdir -p "$ext"
  for f in "$here"/Testing/Data/External/*.lr "$here"/Testing/Data/External/*.g2; do
    case "$t:$f" in
      FuzzLRSplineParser:*.g2 | FuzzG2Parser:*.lr | FuzzIFEMReader:*) ;;
      *) cp -f "$f" "$ext/" ;;
    esac
  done
  if [ -d "$fuzz/regressions/$t" ]; then
    seeds+=("$fuzz/regressions/$t")
  fi
  mkdir -p "$work/corpus-$t"
  log="$work/$t.log"
  start=$(date +%s)
  maxlen=4096
  [ "$t" = FuzzIFEMReader ] && maxlen=32768 # HDF5 files: the seeds are 7-27 kB
  if "$exe" "${limit[@]}" -timeout=1 -rss_limit_mb=2048 -max_len=$maxlen \
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
  pids=()
  for t in "${targets[@]}"; do
    run_target "$t" > "$work/$t.summary" 2>&1 &
    pids+=($!)
  done
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || status=1
    cat "$work/${targets[$i]}.summary"
  done
else
  for t in "${targets[@]}"; do
    run_target "$t" || status=1
  done
fi
exit $status
