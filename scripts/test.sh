#!/usr/bin/env bash
# Installs what is missing, builds Release with tests, and runs every test.
# Tests that read the shared data set find it through ROOMSCOUT_DATA_DIR
# (default: ../shared/data next to this checkout).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
export ROOMSCOUT_DATA_DIR="${ROOMSCOUT_DATA_DIR:-$(cd .. && pwd)/shared/data}"
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
