// Whole-system kernels on the built-in large_office: laser scan + map update, A* across the
// building, and a complete exploration episode.

#include <benchmark/benchmark.h>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout {
namespace {

const sim::WorldModel& largeOffice() {
  static const sim::WorldModel model(sim::loadBuiltinWorld("large_office"));
  return model;
}

/// Poses spread over the reachable floor, deterministic.
std::vector<Pose2> samplePoses(const sim::WorldModel& model, const sim::ExplorationTruth& truth,
                               int count) {
  std::vector<Pose2> poses;
  const auto& cells = truth.reachableCells();
  for (int i = 0; i < count; ++i) {
    const Vec2 p =
        truth.geometry().centerOf(truth.geometry().cellAt(cells[(cells.size() * i) / count]));
    if (model.robotFits(p)) poses.push_back({p.x(), p.y(), 0.1 * i});
  }
  return poses;
}

void BM_LaserScanAndMapUpdate(benchmark::State& state) {
  const sim::WorldModel& model = largeOffice();
  const GridGeometry geometry = sim::mapGeometryFor(model, 0.05);
  const sim::ExplorationTruth truth(model, geometry, 0.105);
  const std::vector<Pose2> poses = samplePoses(model, truth, 64);
  OccupancyGrid grid(geometry);
  OccupancyMapper mapper(grid);
  sim::LaserSimulator laser(model, sim::LaserOptions{}, 1);
  std::size_t i = 0;
  for (auto _ : state) {
    const Pose2& pose = poses[i++ % poses.size()];
    const LaserScan scan = laser.scan(pose);
    benchmark::DoNotOptimize(mapper.integrate(scan, pose));
  }
}
BENCHMARK(BM_LaserScanAndMapUpdate)->Unit(benchmark::kMicrosecond);

void BM_AStarAcrossLargeOffice(benchmark::State& state) {
  const sim::WorldModel& model = largeOffice();
  const GridGeometry geometry = sim::mapGeometryFor(model, 0.05);
  const sim::ExplorationTruth truth(model, geometry, 0.105);
  // The fully explored map: truly free cells free, everything else occupied.
  OccupancyGrid grid(geometry);
  for (std::size_t c = 0; c < geometry.cellCount(); ++c) {
    grid.setState(c, truth.trulyFree()[c] ? CellState::kFree : CellState::kOccupied);
  }
  Costmap costmap;
  costmap.update(grid);
  // The two reachable cells farthest apart along x.
  const auto& cells = truth.reachableCells();
  auto byX = [&](std::uint32_t a, std::uint32_t b) {
    return geometry.cellAt(a).x < geometry.cellAt(b).x;
  };
  Vec2 start =
      geometry.centerOf(geometry.cellAt(*std::min_element(cells.begin(), cells.end(), byX)));
  Vec2 goal =
      geometry.centerOf(geometry.cellAt(*std::max_element(cells.begin(), cells.end(), byX)));
  AStarPlanner planner;
  double length = 0.0;
  for (auto _ : state) {
    const PlanResult r = planner.plan(costmap, start, goal);
    length = r.path.length_m;
    benchmark::DoNotOptimize(r);
  }
  state.counters["path_m"] = length;
}
BENCHMARK(BM_AStarAcrossLargeOffice)->Unit(benchmark::kMillisecond);

void BM_ExploreLargeOffice(benchmark::State& state) {
  const sim::WorldModel& model = largeOffice();
  double rate = 0.0, sim_time = 0.0;
  for (auto _ : state) {
    sim::EpisodeConfig config;
    auto strategy = createStrategy("nearest_frontier", 1);
    const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1);
    rate = r.exploration_rate;
    sim_time = r.sim_time_s;
  }
  state.counters["rate"] = rate;
  state.counters["sim_time_s"] = sim_time;
}
BENCHMARK(BM_ExploreLargeOffice)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace roomscout
