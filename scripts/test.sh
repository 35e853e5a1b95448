#!/usr/bin/env bash
# Installs what is missing, builds Release with tests, and runs every test but the slow ones.
# The dataset tests (label "dataset") read the shared data set from ROOMSCOUT_DATA_DIR, or else
# from ../shared/data next to this checkout; without either they skip.
# The browser tests (label "browser") run too, so Chromium is installed for them;
# ROOMSCOUT_BROWSER_TESTS=0 skips installing it (those tests then skip themselves).
set -euo pipefail
cd "$(dirname "$0")/.."
export ROOMSCOUT_BROWSER_TESTS="${ROOMSCOUT_BROWSER_TESTS:-1}"
scripts/setup.sh build
# The slow tests (label "slow", e.g. the README tables' episodes in the larger worlds) run
# only when asked for: ctest --test-dir build -L slow
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900 -LE '^slow$'
