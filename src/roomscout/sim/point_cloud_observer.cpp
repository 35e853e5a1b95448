#include "roomscout/sim/point_cloud_observer.hpp"
#include "roomscout/core/format.hpp"

#include <chrono>
#include <cstdio>

namespace roomscout::sim {

void PointCloudObserverOptions::validate() const {
  lidar.validate();
  map.validate();
  keyframes.validate();
}

std::vector<ParameterGroup> PointCloudObserverOptions::groups() {
  std::vector<ParameterRef> map_parameters = map.parameters();
  map_parameters.push_back(
      {"remove_floor_ceiling", &remove_floor_ceiling,
       "drop returns from the floor and ceiling planes (false keeps them, as in LIO-SAM's map)"});
  return {{"lidar", lidar.parameters()},
          {"pointcloud", map_parameters},
          {"keyframes", keyframes.parameters()}};
}

PointCloudObserver::PointCloudObserver(const WorldModel& world,
                                       const PointCloudObserverOptions& options, std::uint64_t seed,
                                       MapWorker* worker)
    : options_(options),
      worker_(worker != nullptr && worker->background() ? worker : nullptr),
      columns_(std::make_unique<ColumnWorld>(world)),
      lidar_(*columns_, options.lidar, seed, options.lidar_noise),
      keyframes_(options.keyframes),
      map_(options.map) {
  options_.validate();
}

PointCloudObserver::~PointCloudObserver() {
  if (worker_ != nullptr) worker_->wait();  // jobs still queued refer to this observer
}

void PointCloudObserver::onStep(const EpisodeSnapshot& snapshot) {
  if (snapshot.time_s < next_scan_s_ - 1e-9) return;
  next_scan_s_ += 1.0 / options_.lidar.rate_hz;
  ++scans_;
  // The keyframe rule needs only the pose, so revolutions that are not keyframes are not cast.
  // Keyframes are chosen, and revolutions placed, at the pose the robot believes it has.
  if (!keyframes_.accept(snapshot.believed())) return;
  if (worker_ != nullptr) {
    worker_->post([this, truth = snapshot.robot, believed = snapshot.believed()] {
      insertScan(truth, believed);
    });
  } else {
    insertScan(snapshot.robot, snapshot.believed());
  }
}

void PointCloudObserver::onFinish(const EpisodeSnapshot&) {
  if (worker_ != nullptr) worker_->drain();
}

namespace {

Eigen::Isometry3d planar(const Pose2& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Eigen::Vector3d(p.x_m, p.y_m, 0.0));
  T.rotate(Eigen::AngleAxisd(p.yaw_rad, Eigen::Vector3d::UnitZ()));
  return T;
}

}  // namespace

void PointCloudObserver::insertScan(const Pose2& truth, const Pose2& believed) {
  const auto start = std::chrono::steady_clock::now();
  const LidarScan scan = lidar_.scan(truth);
  // The sensor's mounting on the robot, carried onto the believed pose.
  const bool told_the_truth =
      truth.x_m == believed.x_m && truth.y_m == believed.y_m && truth.yaw_rad == believed.yaw_rad;
  const Eigen::Isometry3d T_believed_sensor =
      told_the_truth ? scan.T_map_sensor
                     : planar(believed) * planar(truth).inverse() * scan.T_map_sensor;
  const Eigen::Affine3f T_map_sensor = Eigen::Affine3f(T_believed_sensor.matrix().cast<float>());
  points_map_.clear();
  points_map_.reserve(scan.points_sensor.size());
  for (std::size_t i = 0; i < scan.points_sensor.size(); ++i) {
    if (options_.remove_floor_ceiling && scan.surfaces[i] != LidarSurface::kObject) continue;
    points_map_.push_back(T_map_sensor * scan.points_sensor[i]);
  }
  map_.insert(points_map_);
  update_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

std::string PointCloudObserver::description() const {
  return formatString("%s; voxel %g m; %s; floor and ceiling %s", "simulated VLP-16",
                      options_.map.voxel_size_m, options_.keyframes.describe().c_str(),
                      options_.remove_floor_ceiling ? "removed" : "kept");
}

}  // namespace roomscout::sim
