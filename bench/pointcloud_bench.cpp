// The 3D point cloud map on the built-in large_office: one VLP-16 revolution (ray cast) and
// its insertion into the voxel map, and, for streaming inserts, the incremental voxel hash
// (PointCloudMap) against re-filtering the accumulated cloud with pcl::VoxelGrid.

#include <benchmark/benchmark.h>

#include "roomscout/mapping/point_cloud_map.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/lidar_simulator.hpp"

#ifdef ROOMSCOUT_BENCH_PCL
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>
#endif

namespace roomscout {
namespace {

struct Office {
  sim::WorldModel model{sim::loadBuiltinWorld("large_office")};
  sim::ColumnWorld columns{model};
  std::vector<Pose2> poses;
  Office() {
    const GridGeometry geometry = sim::mapGeometryFor(model, 0.05);
    const sim::ExplorationTruth truth(model, geometry, 0.105);
    const auto& cells = truth.reachableCells();
    const int count = 200;
    for (int i = 0; i < count; ++i) {
      const Vec2 p =
          truth.geometry().centerOf(truth.geometry().cellAt(cells[(cells.size() * i) / count]));
      if (model.robotFits(p)) poses.push_back({p.x(), p.y(), 0.37 * i});
    }
  }
};

const Office& office() {
  static const Office o;
  return o;
}

std::vector<Eigen::Vector3f> toMap(const sim::LidarScan& scan) {
  const Eigen::Affine3f T_map_sensor(scan.T_map_sensor.matrix().cast<float>());
  std::vector<Eigen::Vector3f> points_map;
  points_map.reserve(scan.points_sensor.size());
  for (const Eigen::Vector3f& p : scan.points_sensor) points_map.push_back(T_map_sensor * p);
  return points_map;
}

/// Scans along the poses, in the map frame (the same for every streaming benchmark).
const std::vector<std::vector<Eigen::Vector3f>>& officeScans() {
  static const std::vector<std::vector<Eigen::Vector3f>> scans = [] {
    sim::LidarSimulator lidar(office().columns, {}, 1);
    std::vector<std::vector<Eigen::Vector3f>> out;
    for (std::size_t i = 0; i < 100 && i < office().poses.size(); ++i)
      out.push_back(toMap(lidar.scan(office().poses[i])));
    return out;
  }();
  return scans;
}

void BM_Vlp16RayCast(benchmark::State& state) {
  const Office& o = office();
  sim::LidarSimulator lidar(o.columns, {}, 1);
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const sim::LidarScan scan = lidar.scan(o.poses[i++ % o.poses.size()]);
    points += scan.points_sensor.size();
    benchmark::DoNotOptimize(scan.points_sensor.data());
  }
  state.counters["points_per_scan"] = static_cast<double>(points) / state.iterations();
}
BENCHMARK(BM_Vlp16RayCast)->Unit(benchmark::kMillisecond);

/// What the "pointcloud" observer times per keyframe: ray cast + transform + insert.
void BM_Vlp16RayCastAndInsert(benchmark::State& state) {
  const Office& o = office();
  sim::LidarSimulator lidar(o.columns, {}, 1);
  PointCloudMap map;
  std::size_t i = 0;
  for (auto _ : state) {
    const sim::LidarScan scan = lidar.scan(o.poses[i++ % o.poses.size()]);
    map.insert(toMap(scan));
  }
  state.counters["map_points"] = static_cast<double>(map.size());
}
BENCHMARK(BM_Vlp16RayCastAndInsert)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("median",
                        [](const std::vector<double>& v) {
                          std::vector<double> s = v;
                          std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
                          return s[s.size() / 2];
                        })
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

/// Streams state.range(0) scans into the incremental voxel hash; time per scan.
void BM_StreamVoxelHash(benchmark::State& state) {
  const auto& scans = officeScans();
  const std::size_t n = std::min<std::size_t>(state.range(0), scans.size());
  std::size_t size = 0;
  for (auto _ : state) {
    PointCloudMap map;
    for (std::size_t i = 0; i < n; ++i) map.insert(scans[i]);
    size = map.size();
  }
  state.counters["map_points"] = static_cast<double>(size);
  state.counters["ms_per_scan"] = benchmark::Counter(
      static_cast<double>(n) * 1e-3,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StreamVoxelHash)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

#ifdef ROOMSCOUT_BENCH_PCL
/// The PCL way to keep a streamed map voxel-filtered: append the scan, re-filter the map with
/// pcl::VoxelGrid (centroid per voxel, as PointCloudMap). Time per scan.
void BM_StreamPclVoxelGrid(benchmark::State& state) {
  const auto& scans = officeScans();
  const std::size_t n = std::min<std::size_t>(state.range(0), scans.size());
  std::size_t size = 0;
  for (auto _ : state) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr map(new pcl::PointCloud<pcl::PointXYZ>);
    pcl::VoxelGrid<pcl::PointXYZ> filter;
    filter.setLeafSize(0.05f, 0.05f, 0.05f);
    for (std::size_t i = 0; i < n; ++i) {
      for (const Eigen::Vector3f& p : scans[i]) map->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
      pcl::PointCloud<pcl::PointXYZ>::Ptr filtered(new pcl::PointCloud<pcl::PointXYZ>);
      filter.setInputCloud(map);
      filter.filter(*filtered);
      map = filtered;
    }
    size = map->size();
  }
  state.counters["map_points"] = static_cast<double>(size);
  state.counters["ms_per_scan"] = benchmark::Counter(
      static_cast<double>(n) * 1e-3,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StreamPclVoxelGrid)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace roomscout
