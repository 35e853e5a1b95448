#!/usr/bin/env bash
# Installs what is missing, builds Release, and explores the built-in medium_house,
# writing its maps under out/medium_house.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
build/roomscout explore --world medium_house --method nearest_frontier --seed 1 --out out/medium_house
