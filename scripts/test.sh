#!/usr/bin/env bash
# Installs what is missing, builds Release with tests, and runs every test.
# Tests that read the shared data set find it through ROOMSCOUT_DATA_DIR
# (default: ../shared/data next to this checkout).
# The browser tests (label "browser") run too, so Chromium is installed for them;
# ROOMSCOUT_BROWSER_TESTS=0 skips installing it (those tests then skip themselves).
set -euo pipefail
cd "$(dirname "$0")/.."
export ROOMSCOUT_BROWSER_TESTS="${ROOMSCOUT_BROWSER_TESTS:-1}"
scripts/setup.sh build
export ROOMSCOUT_DATA_DIR="${ROOMSCOUT_DATA_DIR:-$(cd .. && pwd)/shared/data}"
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
