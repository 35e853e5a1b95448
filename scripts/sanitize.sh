#!/usr/bin/env bash
# CI's sanitizer step: one clang build (configure_sanitize.sh: ASan + UBSan, -O1 -g, with the
# fuzz targets), the fast tests run under the sanitizers, then every fuzz target for
# FUZZ_SECONDS from its committed seed corpus (scripts/fuzz.sh). Any sanitizer report fails
# the step: UBSan stops at the first error (-fno-sanitize-recover), ASan reports (leaks
# included) make the test exit non-zero.
# Usage: scripts/sanitize.sh [BUILD_DIR] [FUZZ_SECONDS]   (defaults: build-sanitize, 60)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build-sanitize}"
fuzz_seconds="${2:-60}"

bash scripts/configure_sanitize.sh "$build_dir"
# Only what this step runs: the fast tests' binaries (with the command line they depend on);
# fuzz.sh builds the fuzz targets.
fast_labels=(core mapping planning maps explorer io plots experiment)
binaries=()
for label in "${fast_labels[@]}"; do binaries+=("roomscout_${label}_test"); done
cmake --build "$build_dir" -j "$(nproc)" --target "${binaries[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:abort_on_error=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan_suppressions.txt}"
# The fast tests: every label but those that run whole exploration episodes, which take
# minutes under ASan (sim, exploration, slam, cli: episodes of the built-in worlds, the SLAM
# episodes and the command line driving them; dataset: episodes of real floor plans), and
# browser (Chromium, not our code). Their parsers and file readers are covered by the io and
# experiment tests and the fuzz targets.
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" --timeout 900 \
  -L "^($(IFS='|'; echo "${fast_labels[*]}"))\$" -LE '^browser$'
bash scripts/fuzz.sh "$fuzz_seconds" "$build_dir"
