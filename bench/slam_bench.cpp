// SLAM in the loop: the cost of one SLAM update per scan (the graph SLAM with its map, MRPT's
// ICP-SLAM and particle-filter SLAM) on a recorded drive through the small house, and a whole
// large_office episode with TurtleBot3 noise and each SLAM.

#include <benchmark/benchmark.h>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "roomscout/slam/slam.hpp"

namespace roomscout {
namespace {

struct Drive {
  Pose2 start;
  GridGeometry map;  ///< the simulator's map of the world
  std::vector<LaserScan> scans;
  std::vector<Pose2> odometry;  ///< where the robot's odometry put it at each scan
};

/// The scans and odometry of a nearest_frontier exploration of small_house (seed 1), with the
/// tb3 profile's laser and odometry noise.
const Drive& smallHouseDrive() {
  static const Drive drive = [] {
    const sim::WorldModel model(sim::loadBuiltinWorld("small_house"));
    sim::EpisodeConfig config;
    auto strategy = createStrategy("nearest_frontier", 1);
    const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1);
    const sim::NoiseProfile noise = sim::NoiseProfile::named("tb3");
    sim::LaserSimulator laser(model, config.laser, 1, noise.laser);
    Drive d;
    d.start = model.start();
    d.map = sim::mapGeometryFor(model, config.mapping.resolution_m);
    sim::OdometrySimulator odometry(noise.odometry, d.start, 2);
    Pose2 last = d.start;
    for (const sim::TrajectorySample& s : r.trajectory) {
      odometry.step(last, s.pose);
      last = s.pose;
      d.scans.push_back(laser.scan(s.pose));
      d.odometry.push_back(odometry.pose());
    }
    return d;
  }();
  return drive;
}

void BM_SlamUpdate(benchmark::State& state, const char* mode) {
  const Drive& drive = smallHouseDrive();
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  sim::TimingStats stats;
  for (auto _ : state) {
    slam::SlamOptions options;
    options.mode = mode;
    // As the simulator sets it up: the tb3 odometry and laser models, the map on its grid.
    slam::Slam slam(sim::slamOptionsFor(options, sim::NoiseProfile::named("tb3")), drive.start, 1,
                    OccupancyGridOptions{}, drive.map);
    for (std::size_t i = 0; i < n && i < drive.scans.size(); ++i)
      slam.update(drive.scans[i], drive.odometry[i]);
    stats = sim::TimingStats::of(slam.updateTimes_ms());
  }
  state.counters["scans"] = static_cast<double>(stats.count);
  state.counters["median_ms"] = stats.median_ms;
  state.counters["p95_ms"] = stats.p95_ms;
}
BENCHMARK_CAPTURE(BM_SlamUpdate, graph, "graph")
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_SlamUpdate, icp, "icp")->Arg(100000)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_SlamUpdate, rbpf, "rbpf")->Arg(1500)->Unit(benchmark::kSecond)->Iterations(1);

void BM_ExploreLargeOfficeWithTb3Noise(benchmark::State& state, const char* mode) {
  const sim::WorldModel model(sim::loadBuiltinWorld("large_office"));
  sim::EpisodeResult r;
  for (auto _ : state) {
    sim::EpisodeConfig config;
    config.noise.profile = "tb3";
    config.slam.mode = mode;
    auto strategy = createStrategy("semantic", 1);
    r = sim::runEpisode(model, config, *strategy, 1);
  }
  state.counters["rate"] = r.exploration_rate;
  state.counters["sim_time_s"] = r.sim_time_s;
  state.counters["ate_rmse_m"] = r.slam ? r.slam->error.rmse_m : 0.0;
  state.counters["slam_median_ms"] = r.slam_update.median_ms;
  state.counters["slam_p95_ms"] = r.slam_update.p95_ms;
  state.counters["wall_time_s"] = r.wall_time_s;
}
BENCHMARK_CAPTURE(BM_ExploreLargeOfficeWithTb3Noise, graph, "graph")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_ExploreLargeOfficeWithTb3Noise, icp, "icp")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace roomscout
