#pragma once
// A SLAM run over a recorded log (`roomscout slam --rawlog`): every scan through the SLAM, the
// map drawn at its final poses and at the odometry's, and how well each map fits the scans.
// Knows files, no command line.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/slam/map_consistency.hpp"
#include "roomscout/slam/rawlog.hpp"
#include "roomscout/slam/slam.hpp"

namespace roomscout::experiment {

/// Scan points farther than this are left out of the maps' bounds and of the consistency
/// figure, and beams without a return clear space only this far [m].
constexpr double kRawlogMaxRange_m = 30.0;

/// One map of a log: the grid and how well it fits the scans.
struct RawlogMap {
  OccupancyGrid grid;
  slam::MapConsistency consistency;
};

/// What a SLAM made of a log, beside what odometry alone makes of it.
struct RawlogSlamResult {
  std::string mode;                 ///< slam.mode
  std::vector<Pose2> T_odom_robot;  ///< per scan, as the log has it
  std::vector<Pose2> T_map_robot;   ///< per scan, the SLAM's estimate after finish()
  std::size_t slam_updates = 0;     ///< scans given to the SLAM (those with a return)
  RawlogMap slam_map;               ///< every scan at the SLAM's final pose of its laser
  RawlogMap odometry_map;           ///< every scan at the odometry's pose of its laser
  sim::TimingStats update;          ///< Slam::update() per scan
  slam::SlamStats stats;            ///< what the SLAM did (graph: nodes, loop closures, ...)
  double slam_s = 0.0;              ///< wall time of every update() and finish()
  double maps_s = 0.0;              ///< wall time of both maps and their consistency
};

/// Runs a SLAM in `options.mode` (not "none") over `log`, seeded with `seed`: scans without a
/// single return are not given to it (it has nothing to match) and take the pose of the scan
/// before them moved on by the odometry. The laser is what the SLAM tracks (the log's
/// T_robot_laser is taken off again for the robot's poses). Maps have `grid`'s resolution and
/// cover every scan point within kRawlogMaxRange_m. Throws OptionError for bad options,
/// InvalidArgument when the SLAM fails, and InputError(source, ...) for a map too large to build
/// (a SLAM that diverged far).
RawlogSlamResult runRawlogSlam(const slam::Rawlog& log, const slam::SlamOptions& options,
                               const OccupancyGridOptions& grid, std::uint64_t seed,
                               const std::string& source);

/// What summary.json records besides the result.
struct RawlogRunInfo {
  std::string rawlog;  ///< the log's path
  std::uint64_t seed = 0;
  nlohmann::json options;    ///< resolved options, {group: {name: value}}
  double read_s = 0.0;       ///< wall time of reading the log
  double wall_time_s = 0.0;  ///< the whole command, reading included
};

/// summary.json's content (docs/slam.md, "Real logs").
nlohmann::json rawlogSummaryJson(const RawlogRunInfo& info, const slam::Rawlog& log,
                                 const RawlogSlamResult& result);

/// Writes map.pgm/.yaml and map.png (the SLAM's map and trajectory), odometry_map.pgm/.yaml and
/// odometry_map.png, poses.csv and, last, summary.json into `directory`, each atomically.
void writeRawlogOutputs(const std::filesystem::path& directory, const RawlogRunInfo& info,
                        const slam::Rawlog& log, const RawlogSlamResult& result);

}  // namespace roomscout::experiment
