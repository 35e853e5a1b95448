#pragma once
// The 3D point cloud map of an episode (observer name "pointcloud"): a simulated VLP-16 on the
// robot revolves at its rate; revolutions taken at keyframe poses (LIO-SAM's rule by default)
// are cast against the ColumnWorld, moved into the map frame by the robot's pose and
// inserted into a voxel-filtered PointCloudMap. Each update time covers ray cast + insert.
// Given a MapWorker, the keyframes are cast and inserted there, in order (the same map).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "roomscout/explorer/map_worker.hpp"
#include "roomscout/mapping/keyframe_selector.hpp"
#include "roomscout/mapping/point_cloud_map.hpp"
#include "roomscout/sim/column_world.hpp"
#include "roomscout/sim/episode_observer.hpp"
#include "roomscout/sim/lidar_simulator.hpp"
#include "roomscout/sim/sensor_noise.hpp"

namespace roomscout::sim {

/// Its fields are documented in groups() and printed by `roomscout options`.
struct PointCloudObserverOptions {
  LidarOptions lidar;
  PointCloudMapOptions map;
  KeyframeOptions keyframes;
  bool remove_floor_ceiling = false;
  RangeNoise lidar_noise;  ///< the lidar's range noise: noise.profile's, set by the
                           ///< caller (not a YAML key of its own)
  void validate() const;
  /// Groups "lidar", "pointcloud" (map options and remove_floor_ceiling) and "keyframes".
  std::vector<ParameterGroup> groups();
};

class PointCloudObserver final : public EpisodeObserver {
 public:
  /// `world` must outlive the observer. Builds the 3D ground truth (ColumnWorld) of `world`.
  /// @param worker casts and inserts the keyframes (borrowed; must outlive the observer);
  ///        null: at once. With a worker, map() and the update times are up to date only
  ///        after onFinish().
  PointCloudObserver(const WorldModel& world, const PointCloudObserverOptions& options,
                     std::uint64_t seed, MapWorker* worker = nullptr);
  ~PointCloudObserver() override;

  std::string_view name() const override { return "pointcloud"; }
  void onStep(const EpisodeSnapshot& snapshot) override;
  void onFinish(const EpisodeSnapshot& snapshot) override;
  const std::vector<double>& updateTimes_ms() const override { return update_ms_; }

  const PointCloudMap& map() const { return map_; }
  const ColumnWorld& columns() const { return *columns_; }
  const PointCloudObserverOptions& options() const { return options_; }
  int scans() const { return scans_; }
  int keyframes() const { return keyframes_.keyframes(); }
  /// One line describing how the map was built, for file headers and run records.
  std::string description() const;

 private:
  /// Casts a revolution from the true pose and inserts it at the believed one.
  void insertScan(const Pose2& truth, const Pose2& believed);

  PointCloudObserverOptions options_;
  MapWorker* worker_;  ///< null unless it has a thread: a worker without one changes nothing
  std::unique_ptr<ColumnWorld> columns_;
  LidarSimulator lidar_;
  KeyframeSelector keyframes_;
  PointCloudMap map_;
  double next_scan_s_ = 0.0;
  int scans_ = 0;
  std::vector<Eigen::Vector3f> points_map_;  ///< scratch, reused between scans
  std::vector<double> update_ms_;
};

}  // namespace roomscout::sim
