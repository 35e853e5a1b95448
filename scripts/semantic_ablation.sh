#!/usr/bin/env bash
# Measures what each of `semantic`'s additions to the paper's method is worth: runs `semantic`
# as it is and with one addition switched off at a time (the values are those
# SemanticExplorerOptions::paper() uses), then prints one table per world with
# scripts/method_table.py (paired by seed, ratio to `semantic` as it is).
#
# usage: scripts/semantic_ablation.sh OUT [WORLDS] [SEEDS] [JOBS]
#   OUT     folder for the benches (one per variant; rerunning resumes them)
#   WORLDS  default small_house,medium_house,large_office
#   SEEDS   bench --seeds: N or A-B (default 41-46)
#   JOBS    episodes at a time (default: the number of cores)
# ROOMSCOUT (default build/roomscout) names the binary.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: scripts/semantic_ablation.sh OUT [WORLDS] [SEEDS] [JOBS]}"
worlds="${2:-small_house,medium_house,large_office}"
seeds="${3:-41-46}"
jobs="${4:-$(nproc)}"
roomscout="${ROOMSCOUT:-build/roomscout}"

# variant name -> the `semantic` options that switch one addition off
declare -A variants=(
  [semantic]=""
  [no_geodesic_cost]="geodesic_cost: false"
  [no_slivers]="min_unknown_m2: 0, min_frontier_m: 0, pocket_area_m2: 0"
  [no_label_search]="label_search_m: 0"
  [no_hubs]="hub_min_neighbours: 0"
  [no_next_room]="next_room_cost_factor: 1, mass_weight: 0"
  [no_heading]="heading_weight: 0"
  [no_segment]="segment_weight: 0"
  [no_leaf_rooms]="leaf_rooms: false"
  [no_end_phase]="idle_end_s: 0"
  [tree_rate_100]="iterations_per_s: 100"
)
order=(semantic no_geodesic_cost no_slivers no_label_search no_hubs no_next_room no_heading
       no_segment no_leaf_rooms no_end_phase tree_rate_100)

mkdir -p "$out"
sources=()
for v in "${order[@]}"; do
  printf 'semantic: {%s}\n' "${variants[$v]}" > "$out/$v.yaml"
  echo "semantic_ablation: $v (${variants[$v]:-as it is})" >&2
  "$roomscout" bench --worlds "$worlds" --methods semantic --seeds "$seeds" --jobs "$jobs" \
    --config "$out/$v.yaml" --out "$out/$v" > "$out/$v.log" 2>&1
  sources+=("$v=$out/$v")
done
python3 scripts/method_table.py --reference semantic --versus semantic --worlds "$worlds" "${sources[@]}"
