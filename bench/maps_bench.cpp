// Topology and room segmentation per map: the benchmark maps of ../shared/data/room_segmentation
// (ROOMSCOUT_DATA_DIR, default ../shared/data) and a final large_office map
// (ROOMSCOUT_LARGE_OFFICE_MAP, default out/large_office/occupancy.yaml, written by
// `roomscout explore --world large_office --out out/large_office`).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "roomscout/io/map_server.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/maps/grid_image.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

fs::path dataDir() {
  const char* dir = std::getenv("ROOMSCOUT_DATA_DIR");
  return dir ? fs::path(dir) : fs::path("../shared/data");
}

/// Cell states and geometry of one benchmark map, or of the large_office map (name "large_office").
bool loadStates(const std::string& name, bool furnished, cv::Mat& states, GridGeometry& geometry) {
  try {
    if (name == "large_office") {
      const char* env = std::getenv("ROOMSCOUT_LARGE_OFFICE_MAP");
      const OccupancyGrid grid =
          io::loadOccupancyMap(env ? env : "out/large_office/occupancy.yaml");
      states = maps::stateImage(grid);
      geometry = grid.geometry();
      return true;
    }
    const fs::path dir = dataDir() / "room_segmentation";
    states = io::benchmarkStates(
        io::readGreyImage(dir / (name + (furnished ? "_furnitures.png" : ".png"))));
    geometry = GridGeometry(Vec2::Zero(), 0.05, states.cols, states.rows);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

const char* const kMaps[] = {"Freiburg101_scan", "Freiburg52_scan", "Freiburg79_scan", "lab_b_scan",
                             "lab_c_scan",       "lab_d_scan",      "lab_intel",       "lab_ipa",
                             "office_a",         "office_e",        "large_office"};

void BM_Segmentation(benchmark::State& state, const std::string& name, bool furnished) {
  cv::Mat states;
  GridGeometry geometry;
  if (!loadStates(name, furnished, states, geometry)) {
    state.SkipWithError("map not found (set ROOMSCOUT_DATA_DIR / ROOMSCOUT_LARGE_OFFICE_MAP)");
    return;
  }
  const RoomSegmenter segmenter;
  SemanticMap map;
  for (auto _ : state) {
    const RoomSegmentation seg = segmenter.segment(states, geometry.resolution_m());
    map.update(geometry, seg.labels, states);
    benchmark::DoNotOptimize(map.regions().data());
  }
  state.counters["rooms"] = static_cast<double>(map.regions().size());
}

void BM_Topology(benchmark::State& state, const std::string& name, bool furnished) {
  cv::Mat states;
  GridGeometry geometry;
  if (!loadStates(name, furnished, states, geometry)) {
    state.SkipWithError("map not found (set ROOMSCOUT_DATA_DIR / ROOMSCOUT_LARGE_OFFICE_MAP)");
    return;
  }
  const TopologyBuilder builder;
  std::size_t edges = 0;
  for (auto _ : state) {
    const TopologicalMap t = builder.build(states, geometry, nullptr);
    edges = t.edges().size();
    benchmark::DoNotOptimize(edges);
  }
  state.counters["edges"] = static_cast<double>(edges);
}

[[maybe_unused]] const bool kRegistered = [] {
  for (const char* name : kMaps) {
    for (const bool furnished : {false, true}) {
      if (furnished && std::string(name) == "large_office") continue;
      const std::string suffix = std::string(name) + (furnished ? "/furnished" : "");
      benchmark::RegisterBenchmark(("BM_Segmentation/" + suffix).c_str(), BM_Segmentation, name,
                                   furnished)
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("BM_Topology/" + suffix).c_str(), BM_Topology, name, furnished)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace roomscout
