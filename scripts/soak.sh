#!/usr/bin/env bash
# The soak: every exploration method on every plan of the shared data set, to find crashes,
# hangs and episodes that never end.
#   - the 50 HouseExpo plans, seeds 1-3, each seed from a random start (the same for every
#     method);
#   - the 20 room-segmentation maps (plain and furnished), read as worlds, seed 1.
# Then scripts/soak_summary.py checks that every episode has exactly one record and ended,
# done or at its time limit, and prints the figures. The benches resume: rerunning the script
# with the same OUT runs only what is missing.
#
# usage: scripts/soak.sh OUT [JOBS] [METHODS]
#   OUT      folder for the two benches (houseexpo/, room_segmentation/)
#   JOBS     episodes at a time (default: the number of cores)
#   METHODS  comma-separated (default: every method `roomscout methods` lists)
# ROOMSCOUT (default build/roomscout) names the binary; ROOMSCOUT_DATA_DIR the data set
# (default ../shared/data beside this checkout). SOAK_HOURS bounds each bench's wall time
# (default 12): a bench that runs longer counts as a hang and fails the soak.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: scripts/soak.sh OUT [JOBS] [METHODS]}"
jobs="${2:-$(nproc)}"
roomscout="${ROOMSCOUT:-build/roomscout}"
data="${ROOMSCOUT_DATA_DIR:-$(cd .. && pwd)/shared/data}"
methods="${3:-$("$roomscout" methods | awk '{print $1}' | paste -sd, -)}"
hours="${SOAK_HOURS:-12}"
for d in "$data/floorplans/houseexpo" "$data/room_segmentation"; do
  [ -d "$d" ] || { echo "soak: no such folder: $d (set ROOMSCOUT_DATA_DIR)" >&2; exit 2; }
done

mkdir -p "$out"
timeout "${hours}h" "$roomscout" bench --worlds "$data/floorplans/houseexpo" --methods "$methods" \
  --seeds 3 --random-starts --jobs "$jobs" --out "$out/houseexpo"
timeout "${hours}h" "$roomscout" bench --worlds "$data/room_segmentation" --methods "$methods" \
  --seeds 1 --jobs "$jobs" --out "$out/room_segmentation"
python3 scripts/soak_summary.py --methods "$methods" \
  "$out/houseexpo=$data/floorplans/houseexpo:3" "$out/room_segmentation=$data/room_segmentation:1"
