#pragma once
// Real laser logs in MRPT's rawlog format (the Radish data sets, Intel Research Lab, as MRPT
// publishes them), read into our scan and pose types. MRPT stays behind this header.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"

namespace roomscout::slam {

/// One 2D laser scan of a log and where the robot's odometry put it.
struct RawlogScan {
  /// In the laser's frame: beams counter-clockwise from angle_min_rad, as MRPT lays them out
  /// (N beams evenly over the aperture, centred on the laser's heading; right to left, or
  /// reversed here when the log says left to right). range_min_m is 0.01 m, range_max_m the
  /// log's maximum range. A beam MRPT flags invalid, or one beyond the maximum range, is +inf
  /// (no return: free space up to range_max_m); a NaN or negative range is 0 (no information).
  LaserScan scan;
  /// The robot's pose by odometry alone when the scan was taken; the first scan's robot is at
  /// the origin with heading 0.
  Pose2 T_odom_robot;
  /// Where the laser sits on the robot (MRPT's sensorPose projected on the plane).
  Pose2 T_robot_laser;
};

/// The scans of one log and what the reader found in it.
struct Rawlog {
  std::vector<RawlogScan> scans;
  std::size_t entries = 0;                ///< top-level objects in the file
  bool observations_only = false;         ///< true: the log's observation-only format (odometry
                                          ///< from CObservationOdometry), false: action-observation
  std::size_t odometry_readings = 0;      ///< odometry increments (or readings) applied
  std::size_t invalid_beams = 0;          ///< beams flagged invalid or beyond the maximum range
  std::size_t corrupt_beams = 0;          ///< NaN, negative or -inf ranges
  std::size_t scans_without_returns = 0;  ///< scans without a single valid range
};

/// Reads an MRPT rawlog, gzip-compressed or not, in either of MRPT's formats: pairs of
/// CActionCollection (odometry increments, CActionRobotMovement2D) and CSensoryFrame
/// (observations), or a sequence of observations (CObservation2DRangeScan and
/// CObservationOdometry, whose absolute readings are taken relative to the first); either
/// format may also come as one serialised CRawlog object. Every
/// CObservation2DRangeScan becomes a RawlogScan, with the odometry accumulated up to it;
/// other observations are skipped.
/// Throws InputError(path, problem) when the file is missing or unreadable, is a truncated
/// gzip stream, holds something other than MRPT serialised objects, ends in the middle of
/// one, holds no 2D laser scan, or has an odometry increment or reading that is not finite,
/// or a scan of fewer than two beams or with a non-finite aperture, maximum range or sensor pose.
Rawlog readRawlog(const std::filesystem::path& path);

}  // namespace roomscout::slam
