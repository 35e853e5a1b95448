#pragma once
// SLAM for a robot that does not know where it is: its 2D laser scans and wheel odometry go to
// MRPT's ICP-SLAM or to its Rao-Blackwellised particle-filter SLAM (the gmapping family), which
// estimate the robot's pose against a map of laser points they build as it goes. The occupancy
// grid the Explorer reads is then built from every scan at that estimate (OccupancyMapper), as
// a robot's costmap is from scans and the SLAM pose, so that drift shows in it. MRPT stays
// behind this header: callers see our scan and pose types only.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout::slam {

enum class SlamMode {
  kNone,  ///< no SLAM: the caller knows the true pose and maps with it
  kIcp,   ///< MRPT CMetricMapBuilderICP: each scan aligned by ICP with the points seen so far
  kRbpf,  ///< MRPT CMetricMapBuilderRBPF: particles with a map of points each, ICP-based
          ///< optimal proposal
};

/// The config group "slam".
/// Its fields are documented in parameters() and printed by `roomscout options`.
struct SlamOptions {
  std::string mode = "none";
  double match_distance_m = 0.1;
  double match_angle_deg = 5.0;
  double insert_distance_m = 0.2;
  double insert_angle_deg = 10.0;
  int particles = 10;
  double diverged_ate_m = 1.0;

  /// Throws OptionError naming the key for an unknown mode or a value out of range.
  SlamMode slamMode() const;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// One SLAM run from a known start pose, whose frame becomes the map frame. Not
/// thread-safe; several instances may run on different threads (rbpf's calls into MRPT's
/// global random generator are serialised and reseeded from `seed`, so a run is repeatable).
class Slam {
 public:
  /// The robot starts at `start` in the map frame (its odometry too). Throws OptionError for
  /// bad options (or mode "none") and InvalidArgument when MRPT fails to initialise.
  Slam(const SlamOptions& options, const Pose2& start, std::uint64_t seed);
  ~Slam();
  Slam(const Slam&) = delete;
  Slam& operator=(const Slam&) = delete;

  /// One scan, taken with the robot at odometry pose `odometry` (the laser at the robot's
  /// centre). Throws InvalidArgument for a scan of fewer than two beams or a non-finite pose.
  void update(const LaserScan& scan, const Pose2& odometry);

  /// The estimated pose of a robot now at odometry pose `odometry`: the last SLAM estimate
  /// moved on by the odometry since (the map -> odom correction of a ROS robot).
  Pose2 pose(const Pose2& odometry) const;
  /// Ends the run: a SLAM with a back end runs its last optimisation. update() may not be
  /// called afterwards.
  void finish();
  /// One pose per update() call: the SLAM's estimate of where the robot was when it took that
  /// scan, as of now (after the latest optimisation, for a SLAM that optimises).
  std::vector<Pose2> trajectory() const;
  SlamMode mode() const;
  /// Wall time of each update() [ms].
  const std::vector<double>& updateTimes_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace roomscout::slam
