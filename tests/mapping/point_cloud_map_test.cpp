#include "roomscout/mapping/point_cloud_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

TEST(PointCloudMap, OnePointPerVoxelAtTheCentroid) {
  PointCloudMap map;  // 0.05 m voxels
  EXPECT_EQ(map.insert({{0.01f, 0.01f, 0.01f}, {0.03f, 0.02f, 0.04f}}), 1u);
  EXPECT_EQ(map.insert({{0.01f, 0.01f, 0.01f}}), 0u);  // the same voxel again: no new point
  ASSERT_EQ(map.size(), 1u);
  const Eigen::Vector3f c = map.points().front();
  EXPECT_NEAR(c.x(), (0.01 + 0.03 + 0.01) / 3, 1e-6);
  EXPECT_NEAR(c.y(), (0.01 + 0.02 + 0.01) / 3, 1e-6);
  EXPECT_NEAR(c.z(), (0.01 + 0.04 + 0.01) / 3, 1e-6);
  // Across a voxel boundary, including negative coordinates: separate voxels.
  EXPECT_EQ(map.insert({{0.06f, 0.01f, 0.01f}, {-0.01f, 0.01f, 0.01f}, {0.01f, -0.01f, -0.01f}}),
            3u);
  EXPECT_EQ(map.size(), 4u);
}

TEST(PointCloudMap, CountsDistinctVoxelsOfRandomPoints) {
  PointCloudMapOptions options;
  options.voxel_size_m = 0.1;
  PointCloudMap map(options);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  std::set<std::tuple<int, int, int>> voxels;
  std::vector<Eigen::Vector3f> batch;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3f p(u(rng), u(rng), u(rng) * 0.3f);
    batch.push_back(p);
    const Eigen::Vector3f q = p * static_cast<float>(1.0 / options.voxel_size_m);
    voxels.insert({static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())),
                   static_cast<int>(std::floor(q.z()))});
    if (batch.size() == 10000) {
      map.insert(batch);
      batch.clear();
    }
  }
  EXPECT_EQ(map.size(), voxels.size());
  // Every centroid lies inside its voxel, so inside the points' bounds.
  const auto [lo, hi] = map.bounds();
  EXPECT_GE(lo.x(), -5.0f);
  EXPECT_LE(hi.x(), 5.0f);
  EXPECT_GE(lo.z(), -1.5f);
  EXPECT_LE(hi.z(), 1.5f);
}

TEST(PointCloudMap, BoundsOfTheCentroids) {
  PointCloudMap map;
  map.insert({{1.0f, 2.0f, 0.0f}, {-3.0f, 4.0f, 2.5f}});
  const auto [lo, hi] = map.bounds();
  EXPECT_NEAR(lo.x(), -3.0f, 1e-5);
  EXPECT_NEAR(lo.y(), 2.0f, 1e-5);
  EXPECT_NEAR(lo.z(), 0.0f, 1e-5);
  EXPECT_NEAR(hi.x(), 1.0f, 1e-5);
  EXPECT_NEAR(hi.y(), 4.0f, 1e-5);
  EXPECT_NEAR(hi.z(), 2.5f, 1e-5);
}

TEST(PointCloudMap, MemoryIsBoundedByMaxPoints) {
  PointCloudMapOptions options;
  options.max_points = 100;
  PointCloudMap map(options);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 1000; ++i) points.emplace_back(i * 0.1f, 0.0f, 0.0f);
  EXPECT_EQ(map.insert(points), 100u);
  EXPECT_EQ(map.size(), 100u);
  EXPECT_EQ(map.droppedPoints(), 900u);
  const std::size_t bytes = map.memoryBytes();
  map.insert(points);  // a full map does not grow
  EXPECT_EQ(map.size(), 100u);
  EXPECT_EQ(map.memoryBytes(), bytes);
  EXPECT_LT(bytes, 100u * 1024u);
}

TEST(PointCloudMap, SkipsNonFiniteAndOutOfBoundsPoints) {
  PointCloudMap map;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(map.insert({{nan, 0, 0}, {0, inf, 0}, {1e9f, 0, 0}, {1, 1, 1}}), 1u);
  EXPECT_EQ(map.size(), 1u);
}

TEST(PointCloudMap, FarFromTheOriginKeepsPrecision) {
  PointCloudMap map;
  map.insert({{5000.01f, -3000.02f, 1.03f}});
  const Eigen::Vector3f c = map.points().front();
  EXPECT_NEAR(c.x(), 5000.01f, 1e-3);
  EXPECT_NEAR(c.y(), -3000.02f, 1e-3);
}

TEST(PointCloudMap, RejectsBadOptions) {
  PointCloudMapOptions o;
  o.voxel_size_m = 0.0;
  EXPECT_THROW(PointCloudMap{o}, OptionError);
  o = {};
  o.max_points = 0;
  EXPECT_THROW(PointCloudMap{o}, OptionError);
}

}  // namespace
}  // namespace roomscout
