#!/usr/bin/env bash
# Installs what is missing, builds Release with tests, and runs every test.
# The dataset tests (label "dataset") read the shared data set from ROOMSCOUT_DATA_DIR, or else
# from ../shared/data next to this checkout; without either they skip.
# The browser tests (label "browser") run too, so Chromium is installed for them;
# ROOMSCOUT_BROWSER_TESTS=0 skips installing it (those tests then skip themselves).
set -euo pipefail
cd "$(dirname "$0")/.."
export ROOMSCOUT_BROWSER_TESTS="${ROOMSCOUT_BROWSER_TESTS:-1}"
scripts/setup.sh build
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
