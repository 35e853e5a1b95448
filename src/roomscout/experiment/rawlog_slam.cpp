#include "roomscout/experiment/rawlog_slam.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/core/grid_limits.hpp"
#include "roomscout/experiment/build_info.hpp"
#include "roomscout/experiment/run_outputs.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"

namespace roomscout::experiment {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool hasReturn(const LaserScan& scan) {
  return std::any_of(scan.ranges_m.begin(), scan.ranges_m.end(), [&](float r) {
    return std::isfinite(r) && r >= scan.range_min_m && r <= scan.range_max_m;
  });
}

/// The scans as the maps see them: no-return beams clear space up to kRawlogMaxRange_m.
std::vector<LaserScan> mappingScans(const slam::Rawlog& log) {
  std::vector<LaserScan> scans;
  scans.reserve(log.scans.size());
  for (const slam::RawlogScan& s : log.scans) {
    scans.push_back(cappedToRange(s.scan, kRawlogMaxRange_m));
  }
  return scans;
}

/// A grid holding every laser position and every return within range, with a metre around.
GridGeometry fittingGeometry(const std::vector<LaserScan>& scans,
                             const std::vector<Pose2>& T_map_laser, double resolution_m,
                             const std::string& source) {
  const double inf = std::numeric_limits<double>::infinity();
  Vec2 lo(inf, inf), hi(-inf, -inf);
  auto include = [&](const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (std::size_t s = 0; s < scans.size(); ++s) {
    const Pose2& pose = T_map_laser[s];
    include(pose.position());
    const LaserScan& scan = scans[s];
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      const double r = scan.ranges_m[i];
      if (!std::isfinite(r) || r < scan.range_min_m || r > scan.range_max_m) continue;
      const double a =
          pose.yaw_rad + scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
      include(pose.position() + r * Vec2(std::cos(a), std::sin(a)));
    }
  }
  const double margin_m = 1.0;
  const Vec2 origin((std::floor((lo.x() - margin_m) / resolution_m)) * resolution_m,
                    (std::floor((lo.y() - margin_m) / resolution_m)) * resolution_m);
  const double width = std::ceil((hi.x() + margin_m - origin.x()) / resolution_m);
  const double height = std::ceil((hi.y() + margin_m - origin.y()) / resolution_m);
  checkGridSize(source, "map", width, height, resolution_m, "mapping.resolution_m");
  return GridGeometry(origin, resolution_m, static_cast<int>(width), static_cast<int>(height));
}

RawlogMap buildMap(const std::vector<LaserScan>& scans, const std::vector<Pose2>& T_map_laser,
                   const OccupancyGridOptions& options, const std::string& source) {
  RawlogMap map;
  map.grid =
      OccupancyGrid(fittingGeometry(scans, T_map_laser, options.resolution_m, source), options);
  OccupancyMapper mapper(map.grid);
  for (std::size_t i = 0; i < scans.size(); ++i) mapper.integrate(scans[i], T_map_laser[i]);
  map.consistency = slam::mapConsistency(map.grid, scans, T_map_laser, kRawlogMaxRange_m);
  return map;
}

nlohmann::json consistencyJson(const slam::MapConsistency& c) {
  return {{"mean_distance_m",
           c.mean_distance_m ? nlohmann::json(*c.mean_distance_m) : nlohmann::json(nullptr)},
          {"points", c.points},
          {"outside_points", c.outside_points}};
}

nlohmann::json mapJson(const RawlogMap& map) {
  const GridGeometry& g = map.grid.geometry();
  return {{"width", g.width()},
          {"height", g.height()},
          {"resolution_m", g.resolution_m()},
          {"origin_m", {g.origin_m().x(), g.origin_m().y()}},
          {"consistency", consistencyJson(map.consistency)}};
}

std::string posesCsv(const RawlogSlamResult& r) {
  std::string out = "scan,odom_x_m,odom_y_m,odom_yaw_rad,x_m,y_m,yaw_rad\n";
  for (std::size_t i = 0; i < r.T_map_robot.size(); ++i) {
    const Pose2& o = r.T_odom_robot[i];
    const Pose2& p = r.T_map_robot[i];
    out += formatString("%zu,%.4f,%.4f,%.5f,%.4f,%.4f,%.5f\n", i, o.x_m, o.y_m, o.yaw_rad, p.x_m,
                        p.y_m, p.yaw_rad);
  }
  return out;
}

}  // namespace

RawlogSlamResult runRawlogSlam(const slam::Rawlog& log, const slam::SlamOptions& options,
                               const OccupancyGridOptions& grid, std::uint64_t seed,
                               const std::string& source) {
  grid.validate();
  RawlogSlamResult result;
  result.mode = options.mode;
  const std::size_t n = log.scans.size();
  if (n == 0) throw InvalidArgument("runRawlogSlam: the log has no scans");
  std::vector<Pose2> T_odom_laser(n);
  for (std::size_t i = 0; i < n; ++i) {
    result.T_odom_robot.push_back(log.scans[i].T_odom_robot);
    T_odom_laser[i] = compose(log.scans[i].T_odom_robot, log.scans[i].T_robot_laser);
  }

  // The SLAM tracks the laser, its map frame that of the first scan's laser. A scan with no
  // return is tied to the last scan the SLAM saw (or the start) by odometry.
  const auto slam_start = Clock::now();
  slam::Slam slam(options, T_odom_laser.front(), seed);
  std::vector<std::size_t> update_of(n);  // the SLAM update of each scan, or kNone
  std::vector<std::size_t> anchor_of(n);  // the scan it is tied to by odometry, or kNone
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::size_t last_updated = kNone;
  for (std::size_t i = 0; i < n; ++i) {
    if (hasReturn(log.scans[i].scan)) {
      slam.update(log.scans[i].scan, T_odom_laser[i]);
      update_of[i] = result.slam_updates++;
      anchor_of[i] = kNone;
      last_updated = i;
    } else {
      update_of[i] = kNone;
      anchor_of[i] = last_updated;
    }
  }
  slam.finish();
  const std::vector<Pose2> trajectory = slam.trajectory();
  if (trajectory.size() != result.slam_updates) {
    throw InvalidArgument(formatString("SLAM (%s) returned %zu poses for %zu updates",
                                       options.mode.c_str(), trajectory.size(),
                                       result.slam_updates));
  }
  result.slam_s = secondsSince(slam_start);
  result.update = sim::TimingStats::of(slam.updateTimes_ms());
  result.stats = slam.stats();

  std::vector<Pose2> T_map_laser(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (update_of[i] != kNone) {
      T_map_laser[i] = trajectory[update_of[i]];
    } else {
      const std::size_t a = anchor_of[i];
      // Before the first update the map frame is the odometry's (the SLAM started there).
      const Pose2 T_map_anchor = a == kNone ? T_odom_laser.front() : T_map_laser[a];
      const Pose2 T_odom_anchor = T_odom_laser[a == kNone ? 0 : a];
      T_map_laser[i] = compose(T_map_anchor, compose(inverse(T_odom_anchor), T_odom_laser[i]));
    }
    result.T_map_robot.push_back(compose(T_map_laser[i], inverse(log.scans[i].T_robot_laser)));
  }

  const auto maps_start = Clock::now();
  const std::vector<LaserScan> scans = mappingScans(log);
  result.slam_map = buildMap(scans, T_map_laser, grid, source);
  result.odometry_map = buildMap(scans, T_odom_laser, grid, source);
  result.maps_s = secondsSince(maps_start);
  return result;
}

namespace {
nlohmann::json timingJson(const sim::TimingStats& t) {
  return {{"median", t.median_ms}, {"p95", t.p95_ms}, {"count", t.count}};
}
}  // namespace

nlohmann::json rawlogSummaryJson(const RawlogRunInfo& info, const slam::Rawlog& log,
                                 const RawlogSlamResult& r) {
  return {
      {"rawlog", info.rawlog},
      {"format", log.observations_only ? "observations" : "action-observation pairs"},
      {"entries", log.entries},
      {"scans", log.scans.size()},
      {"odometry_readings", log.odometry_readings},
      {"invalid_beams", log.invalid_beams},
      {"corrupt_beams", log.corrupt_beams},
      {"scans_without_returns", log.scans_without_returns},
      {"mode", r.mode},
      {"seed", info.seed},
      {"slam_updates", r.slam_updates},
      {"wall_time_s", info.wall_time_s},
      {"read_s", info.read_s},
      {"slam_s", r.slam_s},
      {"maps_s", r.maps_s},
      {"update_ms",
       {{"median", r.update.median_ms}, {"p95", r.update.p95_ms}, {"count", r.update.count}}},
      {"graph",
       {{"nodes", r.stats.nodes},
        {"submaps", r.stats.submaps},
        {"matches_rejected", r.stats.matches_rejected},
        {"loop_closures", r.stats.loop_closures},
        {"optimisations", r.stats.optimisations},
        {"loop_search_ms", timingJson(sim::TimingStats::of(r.stats.loop_search_ms))},
        {"optimise_ms", timingJson(sim::TimingStats::of(r.stats.optimise_ms))}}},
      {"consistency_max_range_m", kRawlogMaxRange_m},
      {"maps", {{"slam", mapJson(r.slam_map)}, {"odometry", mapJson(r.odometry_map)}}},
      {"options", info.options},
      {"version", gitRevision()},
      {"host", hostName()},
  };
}

void writeRawlogOutputs(const std::filesystem::path& directory, const RawlogRunInfo& info,
                        const slam::Rawlog& log, const RawlogSlamResult& result) {
  io::ensureWritableDirectory(directory);
  io::saveOccupancyMap(result.slam_map.grid, directory / "map.yaml");
  io::writeImageAtomic(directory / "map.png",
                       renderMapWithPath(result.slam_map.grid, result.T_map_robot));
  io::saveOccupancyMap(result.odometry_map.grid, directory / "odometry_map.yaml");
  io::writeImageAtomic(directory / "odometry_map.png",
                       renderMapWithPath(result.odometry_map.grid, result.T_odom_robot));
  io::writeFileAtomic(directory / "poses.csv", posesCsv(result));
  // summary.json last: its presence says the outputs are complete.
  io::writeFileAtomic(directory / "summary.json",
                      rawlogSummaryJson(info, log, result).dump(2) + "\n");
}

}  // namespace roomscout::experiment
