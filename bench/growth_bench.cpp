// Map update cost against the area a map knows: the rooms and the skeleton of a fully explored
// building, updated after one 6 m square of it changed (as a robot's map changes between two
// updates), beside a build from scratch of the same map. Per built-in world (187 to 5000 m2)
// and per world file listed in ROOMSCOUT_GROWTH_WORLDS (comma-separated world YAML files, e.g.
// made by scripts/make_building.py). The counter known_m2 is the area the map knows.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "roomscout/maps/incremental_rooms.hpp"
#include "roomscout/maps/incremental_topology.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/maps/topology_builder.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/world_source.hpp"

namespace roomscout {
namespace {

constexpr double kRes = 0.05;

/// A building's map once fully explored, and the same with one square unknown.
struct GrownMap {
  cv::Mat full, holed;
  GridGeometry geometry;
  double known_m2 = 0.0;
};

GrownMap grownMap(const std::string& world_spec) {
  const sim::WorldModel model(sim::loadWorld(world_spec));
  const GridGeometry& raster = model.geometry();
  const double scale = raster.resolution_m() / kRes;
  GrownMap m;
  m.geometry = GridGeometry(raster.origin_m(), kRes, static_cast<int>(raster.width() * scale),
                            static_cast<int>(raster.height() * scale));
  const sim::ExplorationTruth truth(model, m.geometry, 0.105);
  // Free: the truly free cells joined to the robot's reachable space; walls: the cells around.
  cv::Mat free(m.geometry.height(), m.geometry.width(), CV_8U,
               const_cast<std::uint8_t*>(truth.trulyFree().data()));
  free = free.clone();
  cv::Mat fill_mask = cv::Mat::zeros(free.rows + 2, free.cols + 2, CV_8U);
  const Cell seed = m.geometry.cellAt(truth.reachableCells().front());
  cv::floodFill(free, fill_mask, cv::Point(seed.x, seed.y), 255, nullptr, 0, 0,
                4 | cv::FLOODFILL_MASK_ONLY | (255 << 8));
  const cv::Mat space = fill_mask(cv::Rect(1, 1, free.cols, free.rows)) != 0;
  cv::Mat seen;
  cv::dilate(space, seen, cv::Mat::ones(3, 3, CV_8U));
  m.full = cv::Mat(free.size(), CV_8U, cv::Scalar(static_cast<int>(CellState::kUnknown)));
  m.full.setTo(static_cast<int>(CellState::kOccupied), seen);
  m.full.setTo(static_cast<int>(CellState::kFree), space);
  m.known_m2 = cv::countNonZero(seen) * kRes * kRes;
  // The square around the middle one of the reachable cells.
  const std::vector<std::uint32_t>& reachable = truth.reachableCells();
  const Cell middle = m.geometry.cellAt(reachable[reachable.size() / 2]);
  const int side = static_cast<int>(6.0 / kRes);
  m.holed = m.full.clone();
  m.holed(cv::Rect(middle.x - side / 2, middle.y - side / 2, side, side) &
          cv::Rect(0, 0, m.full.cols, m.full.rows))
      .setTo(static_cast<int>(CellState::kUnknown));
  return m;
}

/// Each iteration is two updates: the square seen, then unseen again.
void BM_RoomsUpdate(benchmark::State& state, const std::string& world) {
  const GrownMap m = grownMap(world);
  IncrementalRoomSegmenter rooms;
  SemanticMap semantic;
  semantic.update(m.geometry, rooms.update(m.holed, m.geometry).labels, m.holed);
  for (auto _ : state) {
    for (const cv::Mat* states : {&m.full, &m.holed}) {
      semantic.update(m.geometry, rooms.update(*states, m.geometry).labels, *states);
      benchmark::DoNotOptimize(semantic.regions().data());
    }
  }
  state.SetItemsProcessed(2 * state.iterations());
  state.counters["known_m2"] = m.known_m2;
  state.counters["window_share"] =
      rooms.windowUpdates() /
      std::max(1.0, static_cast<double>(rooms.windowUpdates() + rooms.fullUpdates() - 1));
}

void BM_RoomsFromScratch(benchmark::State& state, const std::string& world) {
  const GrownMap m = grownMap(world);
  const RoomSegmenter segmenter;
  SemanticMap semantic;
  for (auto _ : state) {
    semantic.update(m.geometry, segmenter.segment(m.full, kRes).labels, m.full);
    benchmark::DoNotOptimize(semantic.regions().data());
  }
  state.counters["known_m2"] = m.known_m2;
}

void BM_SkeletonUpdate(benchmark::State& state, const std::string& world) {
  const GrownMap m = grownMap(world);
  IncrementalTopologyBuilder skeleton;
  skeleton.update(m.holed, m.geometry, nullptr);
  for (auto _ : state) {
    for (const cv::Mat* states : {&m.full, &m.holed}) {
      const TopologicalMap t = skeleton.update(*states, m.geometry, nullptr);
      benchmark::DoNotOptimize(t.edges().data());
    }
  }
  state.SetItemsProcessed(2 * state.iterations());
  state.counters["known_m2"] = m.known_m2;
}

void BM_SkeletonFromScratch(benchmark::State& state, const std::string& world) {
  const GrownMap m = grownMap(world);
  const TopologyBuilder builder;
  for (auto _ : state) {
    const TopologicalMap t = builder.build(m.full, m.geometry, nullptr);
    benchmark::DoNotOptimize(t.edges().data());
  }
  state.counters["known_m2"] = m.known_m2;
}

[[maybe_unused]] const bool kRegistered = [] {
  std::vector<std::string> worlds = sim::builtinWorldNames();
  if (const char* extra = std::getenv("ROOMSCOUT_GROWTH_WORLDS")) {
    std::stringstream list(extra);
    for (std::string item; std::getline(list, item, ',');) {
      if (!item.empty()) worlds.push_back(item);
    }
  }
  for (const std::string& world : worlds) {
    benchmark::RegisterBenchmark(("BM_RoomsUpdate/" + world).c_str(), BM_RoomsUpdate, world)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_RoomsFromScratch/" + world).c_str(), BM_RoomsFromScratch,
                                 world)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_SkeletonUpdate/" + world).c_str(), BM_SkeletonUpdate, world)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_SkeletonFromScratch/" + world).c_str(),
                                 BM_SkeletonFromScratch, world)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
}  // namespace roomscout
