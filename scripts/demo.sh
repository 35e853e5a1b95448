#!/usr/bin/env bash
# Installs what the roomscout command needs, builds it (Release, nothing else: scripts/test.sh
# adds the tests, benchmarks and ROS nodes), and explores the built-in medium_house (450 m²,
# 23 rooms) with the semantic method, writing its four maps under out/medium_house.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --demo build
build/roomscout explore --world medium_house --method semantic --seed 1 --out out/medium_house
cat <<'MAPS'
The four maps, in one frame, are in out/medium_house/:
  occupancy grid   occupancy.pgm + occupancy.yaml (ROS map_server)
  point cloud      pointcloud.pcd (view: pcl_viewer), pointcloud.png
  topological map  topology.json, topology.png
  semantic map     semantic.json, semantic.png, semantic_labels.png
  the run          metrics.json, trajectory.csv, run.png
MAPS
