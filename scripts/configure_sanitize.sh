#!/usr/bin/env bash
# Configures the clang build that scripts/sanitize.sh and scripts/fuzz.sh share: AddressSanitizer
# and UndefinedBehaviorSanitizer on roomscout's targets, the libFuzzer targets of fuzz/, the
# tests, no ROS nodes and no benchmarks; -O1 -g so that the tests stay fast enough and reports
# carry line numbers. Uses ccache when it is installed.
# Usage: scripts/configure_sanitize.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:?usage: scripts/configure_sanitize.sh BUILD_DIR}"
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DPYTHON_EXECUTABLE=/usr/bin/python3 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DROOMSCOUT_BUILD_ROS=OFF \
  -DROOMSCOUT_BUILD_BENCHMARKS=OFF -DROOMSCOUT_BUILD_TESTS=ON -DROOMSCOUT_SANITIZE=ON \
  -DROOMSCOUT_BUILD_FUZZERS=ON "${launcher[@]}"
