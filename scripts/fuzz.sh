#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang, ASan + UBSan, see configure_sanitize.sh) and
# runs each for SECONDS on a scratch copy of its seed corpus fuzz/corpus/NAME/ (the copy, with
# what the run adds, stays in BUILD_DIR/fuzz-runs/NAME/; the repository's corpus is not
# touched). Fails when any target finds a crash, a sanitizer report, a leak, an input slower
# than 5 s or an allocation over 1 GB; the input is saved as
# BUILD_DIR/fuzz-runs/NAME/{crash,leak,timeout,oom}-<sha1> and the log beside it.
# Prints per target the executions, executions per second, coverage (cov: edges, ft:
# features) and corpus size reached.
# Usage: scripts/fuzz.sh [SECONDS] [BUILD_DIR]          (defaults: 60, build-fuzz)
# ROOMSCOUT_FUZZ_TARGETS="world_yaml pcd" runs only those targets; FUZZ_JOBS (default: the
# number of cores) targets run at a time, one core each.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build_dir="${2:-build-fuzz}"

bash scripts/configure_sanitize.sh "$build_dir" > /dev/null
targets=()
if [ -n "${ROOMSCOUT_FUZZ_TARGETS:-}" ]; then
  read -r -a targets <<< "$ROOMSCOUT_FUZZ_TARGETS"
else
  for source in fuzz/*_fuzzer.cpp; do
    name="$(basename "$source" .cpp)"
    targets+=("${name%_fuzzer}")
  done
fi
build_targets=()
for name in "${targets[@]}"; do build_targets+=("roomscout_${name}_fuzzer"); done
cmake --build "$build_dir" -j "$(nproc)" --target "${build_targets[@]}"

# A report stops the target at once; leaks are reported (libFuzzer checks every input that
# allocated more than it freed). ASan's quarantine of freed memory is 64 MB instead of 256 MB:
# the targets stay far below the 1 GB RSS limit and run faster.
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:abort_on_error=1:symbolize=1:quarantine_size_mb=64}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"

runs="$(cd "$build_dir" && pwd)/fuzz-runs"
fuzzer_dir="$(cd "$build_dir" && pwd)/fuzz"
# One target: a scratch copy of its corpus, then libFuzzer; its exit status in WORK/status.
run_target() {
  local name="$1" work="$runs/$1" status=0
  rm -rf "$work"
  mkdir -p "$work/corpus"
  cp -r "fuzz/corpus/$name/." "$work/corpus/"
  (cd "$work" && "$fuzzer_dir/${name}_fuzzer" -max_total_time="$seconds" \
    -rss_limit_mb=1024 -malloc_limit_mb=1024 -timeout=5 -print_final_stats=1 \
    -artifact_prefix="$work/" corpus > log.txt 2>&1) || status=$?
  echo "$status" > "$work/status"
}
# As many targets at a time as there are cores (FUZZ_JOBS), each on one core.
parallel="${FUZZ_JOBS:-$(nproc)}"
for name in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  echo "fuzz: $name for ${seconds}s"
  run_target "$name" &
done
wait

failed=()
summary=()
for name in "${targets[@]}"; do
  work="$runs/$name"
  status="$(cat "$work/status" 2> /dev/null || echo 1)"
  # The last status line: "#N  DONE  cov: C ft: F corp: U/S ... exec/s: E ..."
  line="$(grep -E '^#[0-9]+' "$work/log.txt" | tail -n 1 || true)"
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log.txt")"
  rate="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/log.txt")"
  cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$line")"
  ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$line")"
  corpus="$(find "$work/corpus" -type f | wc -l)"
  summary+=("$(printf '%-16s %10s %8s %7s %7s %7s' "$name" "${execs:-?}" "${rate:-?}" \
    "${cov:-?}" "${ft:-?}" "$corpus")")
  if [ "$status" -ne 0 ]; then
    failed+=("$name")
    echo "fuzz: $name FAILED (exit $status); log $work/log.txt:"
    grep -E '^==[0-9]+==|^SUMMARY|runtime error|Test unit written|deadly signal|out-of-memory|timeout after|^    #[0-9] ' "$work/log.txt" | head -n 30 || true
  fi
done

printf '%-16s %10s %8s %7s %7s %7s\n' target execs exec/s cov ft corpus
printf '%s\n' "${summary[@]}"
if ((${#failed[@]})); then
  echo "fuzz: failed: ${failed[*]}"
  exit 1
fi
echo "fuzz: every target ran ${seconds}s without a finding"
