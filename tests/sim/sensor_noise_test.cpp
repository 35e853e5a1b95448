#include "roomscout/sim/sensor_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/column_world.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/lidar_simulator.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

/// Mean and standard deviation of a sample.
struct Moments {
  double mean = 0.0, sd = 0.0;
  std::size_t n = 0;
};

Moments moments(const std::vector<double>& v) {
  Moments m;
  m.n = v.size();
  for (double x : v) m.mean += x;
  m.mean /= static_cast<double>(m.n);
  for (double x : v) m.sd += (x - m.mean) * (x - m.mean);
  m.sd = std::sqrt(m.sd / static_cast<double>(m.n - 1));
  return m;
}

/// The sample's mean is within 4 standard errors of 0 and its sd within 5 % of expected_sd.
void expectZeroMeanWithSd(const std::vector<double>& errors, double expected_sd,
                          const std::string& what) {
  const Moments m = moments(errors);
  EXPECT_NEAR(m.mean, 0.0, 4.0 * expected_sd / std::sqrt(static_cast<double>(m.n))) << what;
  EXPECT_NEAR(m.sd, expected_sd, 0.05 * expected_sd) << what;
}

/// A fraction of n trials is within 4 standard errors of probability p.
void expectFraction(std::size_t hits, std::size_t n, double p, const std::string& what) {
  const double nd = static_cast<double>(n);
  EXPECT_NEAR(static_cast<double>(hits) / nd, p, 4.0 * std::sqrt(p * (1.0 - p) / nd)) << what;
}

TEST(NoiseProfile, NoneIsAllZero) {
  const NoiseProfile p = NoiseProfile::named("none");
  EXPECT_TRUE(p.laser.none());
  EXPECT_TRUE(p.lidar.none());
  EXPECT_TRUE(p.odometry.none());
  EXPECT_EQ(p.laser.sd_m(0.3), 0.0);
  EXPECT_EQ(p.laser.sd_m(3.0), 0.0);
}

TEST(NoiseProfile, Tb3IsTheTurtleBot3Datasheets) {
  const NoiseProfile p = NoiseProfile::named("tb3");
  // LDS-01: +-15 mm below 0.5 m, +-5 % beyond, as 2 sd; 1 % dropouts.
  EXPECT_DOUBLE_EQ(p.laser.sd_near_m, 0.0075);
  EXPECT_DOUBLE_EQ(p.laser.near_limit_m, 0.5);
  EXPECT_DOUBLE_EQ(p.laser.sd_fraction, 0.025);
  EXPECT_DOUBLE_EQ(p.laser.dropout_probability, 0.01);
  EXPECT_DOUBLE_EQ(p.laser.sd_m(0.12), 0.0075);
  EXPECT_DOUBLE_EQ(p.laser.sd_m(0.3), 0.0075);
  EXPECT_DOUBLE_EQ(p.laser.sd_m(0.5), 0.0125);
  EXPECT_DOUBLE_EQ(p.laser.sd_m(2.0), 0.05);
  EXPECT_DOUBLE_EQ(p.laser.sd_m(3.5), 0.0875);
  // VLP-16: +-3 cm as 2 sd at every range, no dropouts.
  EXPECT_DOUBLE_EQ(p.lidar.dropout_probability, 0.0);
  for (double r : {0.5, 1.0, 10.0, 100.0}) EXPECT_DOUBLE_EQ(p.lidar.sd_m(r), 0.015) << r;
  // Wheel odometry.
  EXPECT_DOUBLE_EQ(p.odometry.translation_sd_per_m, 0.02);
  EXPECT_DOUBLE_EQ(p.odometry.rotation_sd_per_rad, 0.03);
  EXPECT_DOUBLE_EQ(p.odometry.rotation_sd_per_m, 0.01);
  EXPECT_FALSE(p.laser.none());
  EXPECT_FALSE(p.lidar.none());
  EXPECT_FALSE(p.odometry.none());
}

TEST(NoiseProfile, HarshIsTb3TimesTwoAndAHalfWithMoreDropouts) {
  const NoiseProfile t = NoiseProfile::named("tb3"), h = NoiseProfile::named("harsh");
  for (double r : {0.2, 0.5, 1.0, 3.0, 30.0}) {
    EXPECT_DOUBLE_EQ(h.laser.sd_m(r), 2.5 * t.laser.sd_m(r)) << r;
    EXPECT_DOUBLE_EQ(h.lidar.sd_m(r), 2.5 * t.lidar.sd_m(r)) << r;
  }
  EXPECT_DOUBLE_EQ(h.laser.dropout_probability, 0.03);
  EXPECT_DOUBLE_EQ(h.lidar.dropout_probability, 0.01);
  EXPECT_DOUBLE_EQ(h.odometry.translation_sd_per_m, 2.5 * t.odometry.translation_sd_per_m);
  EXPECT_DOUBLE_EQ(h.odometry.rotation_sd_per_rad, 2.5 * t.odometry.rotation_sd_per_rad);
  EXPECT_DOUBLE_EQ(h.odometry.rotation_sd_per_m, 2.5 * t.odometry.rotation_sd_per_m);
}

TEST(NoiseProfile, UnknownNameThrowsNamingTheKeyAndTheValidNames) {
  try {
    NoiseProfile::named("gazebo");
    FAIL() << "no exception";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    for (const char* part : {"noise.profile", "gazebo", "none", "tb3", "harsh"}) {
      EXPECT_NE(message.find(part), std::string::npos) << message;
    }
  }
  EXPECT_THROW(NoiseProfile::named(""), OptionError);
  EXPECT_THROW(NoiseProfile::named("TB3"), OptionError);
}

TEST(NoiseOptions, ProfileKeyValidatesAndResolves) {
  NoiseOptions o;
  EXPECT_EQ(o.profile, "none");
  EXPECT_NO_THROW(o.validate());
  EXPECT_TRUE(o.resolved().laser.none());
  const std::vector<ParameterRef> params = o.parameters();
  ASSERT_EQ(params.size(), 1u);
  EXPECT_EQ(params[0].name, "profile");
  for (const char* name : {"none", "tb3", "harsh"}) {
    EXPECT_NE(params[0].doc.find(name), std::string_view::npos) << params[0].doc;
  }
  *std::get<std::string*>(params[0].value) = "harsh";
  EXPECT_NO_THROW(o.validate());
  EXPECT_DOUBLE_EQ(o.resolved().laser.dropout_probability, 0.03);
  o.profile = "loud";
  EXPECT_THROW(o.validate(), OptionError);
  EXPECT_THROW(o.resolved(), OptionError);
}

TEST(RangeNoise, SimulatorsRejectInvalidNoise) {
  const WorldModel model(testing::squareRoom(4.0, 0.2));
  EXPECT_THROW(LaserSimulator(model, {}, 1, RangeNoise{.sd_near_m = -0.1}), InvalidArgument);
  EXPECT_THROW(LaserSimulator(model, {}, 1, RangeNoise{.dropout_probability = 1.5}),
               InvalidArgument);
  const ColumnWorld columns(model);
  EXPECT_THROW(LidarSimulator(columns, {}, 1, RangeNoise{.sd_fraction = std::nan("")}),
               InvalidArgument);
  EXPECT_THROW(OdometrySimulator(OdometryNoise{.rotation_sd_per_m = -1.0}, {}, 1), InvalidArgument);
}

/// 40000 single-beam LDS-01 readings of a wall at about `range_m` ahead, with the tb3 noise:
/// Gaussian with the profile's sd around the true range, 1 % dropouts that read 0.
void expectLaserStatistics(double range_m) {
  const WorldModel model(testing::squareRoom(4.0, 0.2));  // inner faces at 0.1 and 3.9 m
  const RangeNoise noise = NoiseProfile::named("tb3").laser;
  LaserOptions options;
  options.num_beams = 1;  // the beam points along yaw - pi
  LaserSimulator laser(model, options, 5, noise);
  const Pose2 pose{3.9 - range_m, 2.0, M_PI};
  const double truth_m = laser.castRay(pose.position(), 0.0, options.range_max_m);
  ASSERT_NEAR(truth_m, range_m, 0.05);
  const double sd_m = noise.sd_m(truth_m);
  const std::size_t n = 40000;
  std::vector<double> errors;
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const LaserScan scan = laser.scan(pose);
    ASSERT_EQ(scan.ranges_m.size(), 1u);
    const float r = scan.ranges_m[0];
    ASSERT_TRUE(std::isfinite(r));
    if (r == 0.0f) {
      ++dropped;
    } else {
      errors.push_back(static_cast<double>(r) - truth_m);
    }
  }
  const std::string what = "range " + std::to_string(truth_m);
  expectZeroMeanWithSd(errors, sd_m, what);
  expectFraction(dropped, n, noise.dropout_probability, what);
}

TEST(RangeNoise, LaserReadingsNearAWallHaveTheNearSd) { expectLaserStatistics(0.3); }

TEST(RangeNoise, LaserReadingsFarFromAWallHaveTheFractionalSd) { expectLaserStatistics(2.0); }

TEST(RangeNoise, NoNoiseLeavesTheLaserExactAndIndependentOfTheSeed) {
  const WorldModel model(testing::squareRoom(4.0, 0.2));
  LaserSimulator a(model, {}, 1), b(model, {}, 2, RangeNoise{});
  const Pose2 pose{1.3, 2.2, 0.4};
  const LaserScan sa = a.scan(pose), sb = b.scan(pose);
  EXPECT_EQ(sa.ranges_m, sb.ranges_m);
  for (std::size_t i = 0; i < sa.ranges_m.size(); ++i) {
    const double angle = pose.yaw_rad + sa.angle_min_rad + i * sa.angle_increment_rad;
    EXPECT_EQ(sa.ranges_m[i], static_cast<float>(a.castRay(pose.position(), angle, 3.5))) << i;
  }
}

/// The harsh VLP-16 noise in a closed room: 1 % of the 16 x 1800 returns lost, the rest off
/// the true range along their beam by the profile's constant sd.
TEST(RangeNoise, LidarDropsReturnsAndSpreadsRanges) {
  const WorldModel model(testing::squareRoom(6.0, 0.2));
  const ColumnWorld columns(model);
  const RangeNoise noise = NoiseProfile::named("harsh").lidar;
  LidarSimulator lidar(columns, {}, 3, noise);
  const Pose2 pose{2.7, 3.1, 0.3};
  const std::size_t beams = 16u * 1800u;
  std::size_t points = 0;
  std::vector<double> errors;
  for (int revolution = 0; revolution < 3; ++revolution) {
    const LidarScan scan = lidar.scan(pose);
    points += scan.points_sensor.size();
    const Eigen::Vector3d origin = scan.T_map_sensor.translation();
    for (const Eigen::Vector3f& p : scan.points_sensor) {
      const Eigen::Vector3d q = p.cast<double>();
      const double range_m = q.norm();
      // Sensor and map frames differ by the heading only.
      const double azimuth = pose.yaw_rad + std::atan2(q.y(), q.x());
      const double elevation = std::asin(q.z() / range_m);
      const std::optional<LidarHit> hit = lidar.castRay(origin, azimuth, elevation, 100.0);
      ASSERT_TRUE(hit.has_value());
      errors.push_back(range_m - hit->range_m);
    }
  }
  expectFraction(3 * beams - points, 3 * beams, noise.dropout_probability, "lidar dropouts");
  expectZeroMeanWithSd(errors, noise.sd_m(1.0), "lidar ranges");
}

/// Final odometry poses of `runs` simulators with seeds 1..runs, each fed the same true path.
std::vector<Pose2> odometryRuns(const OdometryNoise& noise, const std::vector<Pose2>& path,
                                int runs) {
  std::vector<Pose2> ends;
  for (int seed = 1; seed <= runs; ++seed) {
    OdometrySimulator odometry(noise, path.front(), static_cast<std::uint64_t>(seed));
    for (std::size_t i = 1; i < path.size(); ++i) odometry.step(path[i - 1], path[i]);
    ends.push_back(odometry.pose());
  }
  return ends;
}

/// 1 m straight along +x in steps of step_m.
std::vector<Pose2> straightMetre(double step_m) {
  std::vector<Pose2> path;
  const int steps = static_cast<int>(std::lround(1.0 / step_m));
  for (int i = 0; i <= steps; ++i) path.push_back({i * step_m, 0.0, 0.0});
  return path;
}

constexpr int kRuns = 10000;

TEST(OdometryNoise, DrivingOneMetreGivesTheSdsPerMetre) {
  const OdometryNoise noise = NoiseProfile::named("tb3").odometry;
  const std::vector<Pose2> ends = odometryRuns(noise, straightMetre(0.05), kRuns);
  std::vector<double> along, heading;
  for (const Pose2& p : ends) {
    along.push_back(p.x_m - 1.0);
    heading.push_back(wrapAngle(p.yaw_rad));
  }
  expectZeroMeanWithSd(along, noise.translation_sd_per_m, "along-track error after 1 m");
  expectZeroMeanWithSd(heading, noise.rotation_sd_per_m, "heading error after 1 m");
}

TEST(OdometryNoise, TurningOneRadianGivesTheSdPerRadian) {
  const OdometryNoise noise = NoiseProfile::named("tb3").odometry;
  std::vector<Pose2> path;
  for (int i = 0; i <= 100; ++i) path.push_back({1.0, 2.0, 0.01 * i});
  std::vector<double> heading;
  for (const Pose2& p : odometryRuns(noise, path, kRuns)) {
    heading.push_back(wrapAngle(p.yaw_rad - 1.0));
    ASSERT_EQ(p.x_m, 1.0);  // turning in place moves nothing
    ASSERT_EQ(p.y_m, 2.0);
  }
  expectZeroMeanWithSd(heading, noise.rotation_sd_per_rad, "heading error after 1 rad");
}

TEST(OdometryNoise, ErrorDoesNotDependOnTheStepSize) {
  const OdometryNoise noise = NoiseProfile::named("harsh").odometry;
  std::vector<double> sd_along, sd_heading;
  for (double step_m : {0.01, 0.1}) {
    std::vector<double> along, heading;
    for (const Pose2& p : odometryRuns(noise, straightMetre(step_m), kRuns)) {
      along.push_back(p.x_m - 1.0);
      heading.push_back(wrapAngle(p.yaw_rad));
    }
    const std::string what = "step " + std::to_string(step_m);
    expectZeroMeanWithSd(along, noise.translation_sd_per_m, what);
    expectZeroMeanWithSd(heading, noise.rotation_sd_per_m, what);
    sd_along.push_back(moments(along).sd);
    sd_heading.push_back(moments(heading).sd);
  }
  EXPECT_NEAR(sd_along[0] / sd_along[1], 1.0, 0.05);
  EXPECT_NEAR(sd_heading[0] / sd_heading[1], 1.0, 0.05);
}

/// 20000 steps of a differential-drive path that curves both ways, reverses, and wraps the
/// heading around many times, plus a sideways slip now and then.
std::vector<Pose2> curvyPath() {
  std::vector<Pose2> path{{3.0, -2.0, 2.5}};
  const double dt_s = 0.05;
  for (int i = 1; i <= 20000; ++i) {
    const double t = i * dt_s;
    const double v = 0.4 * std::sin(0.05 * t) + 0.1;
    const double w = 1.2 * std::sin(0.3 * t) + 0.4 * std::cos(0.11 * t);
    const Pose2& a = path.back();
    Pose2 b;
    const double dtheta = w * dt_s;
    const double mid = a.yaw_rad + 0.5 * dtheta;
    b.x_m = a.x_m + v * dt_s * std::cos(mid);
    b.y_m = a.y_m + v * dt_s * std::sin(mid);
    if (i % 97 == 0) b.y_m += 0.01;
    b.yaw_rad = wrapAngle(a.yaw_rad + dtheta);
    path.push_back(b);
  }
  return path;
}

TEST(OdometryNoise, NoNoiseReproducesTheTruePose) {
  const std::vector<Pose2> path = curvyPath();
  OdometrySimulator odometry(OdometryNoise{}, path.front(), 9);
  for (std::size_t i = 1; i < path.size(); ++i) {
    odometry.step(path[i - 1], path[i]);
    ASSERT_NEAR(odometry.pose().x_m, path[i].x_m, 1e-9) << i;
    ASSERT_NEAR(odometry.pose().y_m, path[i].y_m, 1e-9) << i;
    ASSERT_NEAR(wrapAngle(odometry.pose().yaw_rad - path[i].yaw_rad), 0.0, 1e-9) << i;
  }
}

TEST(OdometryNoise, SameSeedSameOdometry) {
  const std::vector<Pose2> path = curvyPath();
  const OdometryNoise noise = NoiseProfile::named("tb3").odometry;
  OdometrySimulator a(noise, path.front(), 4), b(noise, path.front(), 4), c(noise, path.front(), 5);
  for (std::size_t i = 1; i < path.size(); ++i) {
    a.step(path[i - 1], path[i]);
    b.step(path[i - 1], path[i]);
    c.step(path[i - 1], path[i]);
  }
  EXPECT_EQ(a.pose().x_m, b.pose().x_m);
  EXPECT_EQ(a.pose().y_m, b.pose().y_m);
  EXPECT_EQ(a.pose().yaw_rad, b.pose().yaw_rad);
  EXPECT_NE(a.pose().x_m, c.pose().x_m);
  // The noisy odometry drifts from the truth, but starts where it was told to.
  EXPECT_GT(std::hypot(a.pose().x_m - path.back().x_m, a.pose().y_m - path.back().y_m), 1e-3);
  const OdometrySimulator fresh(noise, {1.0, 2.0, 3.0}, 1);
  EXPECT_EQ(fresh.pose().x_m, 1.0);
  EXPECT_EQ(fresh.pose().y_m, 2.0);
  EXPECT_EQ(fresh.pose().yaw_rad, 3.0);
}

}  // namespace
}  // namespace roomscout::sim
