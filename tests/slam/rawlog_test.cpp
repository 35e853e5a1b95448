// The rawlog reader on logs written here with MRPT: a straight drive towards a wall, in both of
// MRPT's formats, and logs that are missing, cut short, not rawlogs or without scans.

#include "roomscout/slam/rawlog.hpp"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::slam {
namespace {

using test::Contains;
using test::messageOf;
using test::TempDir;

constexpr int kBeams = 181;
constexpr double kWallX_m = 10.0;  ///< a wall across the drive, at x = 10 m
constexpr float kMaxRange_m = 8.0f;
constexpr double kStep_m = 0.5;

/// What the laser measures at x_m (heading +x) of the wall x = kWallX_m: beam angles from
/// -90 to +90 degrees right to left, no return where the wall is beyond kMaxRange_m.
struct TrueBeam {
  float range_m;
  bool valid;
};
std::vector<TrueBeam> trueBeams(double x_m) {
  std::vector<TrueBeam> beams(kBeams);
  for (int i = 0; i < kBeams; ++i) {
    const double angle = -M_PI / 2 + i * M_PI / (kBeams - 1);
    const double c = std::cos(angle);
    const double r = c > 1e-6 ? (kWallX_m - x_m) / c : 1e9;
    beams[i] = r <= kMaxRange_m ? TrueBeam{static_cast<float>(r), true} : TrueBeam{0.0f, false};
  }
  return beams;
}

mrpt::obs::CObservation2DRangeScan::Ptr makeScan(double x_m, bool right_to_left = true,
                                                 double sensor_yaw_rad = 0.0) {
  auto scan = mrpt::obs::CObservation2DRangeScan::Create();
  scan->aperture = static_cast<float>(M_PI);
  scan->rightToLeft = right_to_left;
  scan->maxRange = kMaxRange_m;
  scan->sensorPose = mrpt::poses::CPose3D(0.1, 0.0, 0.0, sensor_yaw_rad, 0.0, 0.0);
  scan->sensorLabel = "LASER";
  scan->resizeScan(kBeams);
  const std::vector<TrueBeam> beams = trueBeams(x_m);
  for (int i = 0; i < kBeams; ++i) {
    const TrueBeam& b = beams[right_to_left ? i : kBeams - 1 - i];
    scan->setScanRange(i, b.valid ? b.range_m : kMaxRange_m);
    scan->setScanRangeValidity(i, b.valid);
  }
  return scan;
}

mrpt::obs::CActionCollection odometryIncrement(double dx_m, double dyaw_rad = 0.0) {
  mrpt::obs::CActionRobotMovement2D move;
  move.computeFromOdometry(mrpt::poses::CPose2D(dx_m, 0.0, dyaw_rad),
                           mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
  mrpt::obs::CActionCollection actions;
  actions.insert(move);
  return actions;
}

/// A drive of `scans` scans along +x from x = 0, kStep_m apart, as action-observation pairs.
template <typename Stream>
void writeDrive(const std::filesystem::path& path, int scans, bool right_to_left = true,
                double first_increment_m = 0.0) {
  Stream stream(path.string());
  auto out = mrpt::serialization::archiveFrom(stream);
  for (int k = 0; k < scans; ++k) {
    out << odometryIncrement(k == 0 ? first_increment_m : kStep_m);
    mrpt::obs::CSensoryFrame frame;
    frame.insert(makeScan(k * kStep_m, right_to_left));
    out << frame;
  }
}

void expectDrive(const Rawlog& log, int scans) {
  ASSERT_EQ(log.scans.size(), static_cast<std::size_t>(scans));
  for (int k = 0; k < scans; ++k) {
    const RawlogScan& s = log.scans[k];
    EXPECT_NEAR(s.T_odom_robot.x_m, k * kStep_m, 1e-9) << "scan " << k;
    EXPECT_NEAR(s.T_odom_robot.y_m, 0.0, 1e-9);
    EXPECT_NEAR(s.T_odom_robot.yaw_rad, 0.0, 1e-9);
    EXPECT_NEAR(s.T_robot_laser.x_m, 0.1, 1e-6);
    EXPECT_NEAR(s.scan.angle_min_rad, -M_PI / 2, 1e-6);
    EXPECT_NEAR(s.scan.angle_increment_rad, M_PI / (kBeams - 1), 1e-6);
    EXPECT_FLOAT_EQ(s.scan.range_max_m, kMaxRange_m);
    ASSERT_EQ(s.scan.ranges_m.size(), static_cast<std::size_t>(kBeams));
    const std::vector<TrueBeam> truth = trueBeams(k * kStep_m);
    for (int i = 0; i < kBeams; ++i) {
      if (truth[i].valid) {
        EXPECT_FLOAT_EQ(s.scan.ranges_m[i], truth[i].range_m) << "scan " << k << " beam " << i;
      } else {
        EXPECT_EQ(s.scan.ranges_m[i], std::numeric_limits<float>::infinity())
            << "scan " << k << " beam " << i;
      }
    }
  }
}

TEST(RawlogTest, ReadsAGzipDriveWithItsAnglesRangesAndOdometry) {
  TempDir dir;
  const auto path = dir / "drive.rawlog";
  writeDrive<mrpt::io::CFileGZOutputStream>(path, 6);
  const Rawlog log = readRawlog(path);
  EXPECT_EQ(log.entries, 12u);
  EXPECT_FALSE(log.observations_only);
  EXPECT_EQ(log.odometry_readings, 6u);
  EXPECT_EQ(log.corrupt_beams, 0u);
  EXPECT_GT(log.invalid_beams, 0u);  // the beams that miss the wall within 8 m
  expectDrive(log, 6);
}

TEST(RawlogTest, ReadsAnUncompressedLogAndPutsTheFirstScanAtTheOrigin) {
  TempDir dir;
  const auto path = dir / "plain.rawlog";
  // The robot drives 3 m before the first scan: odometry starts there.
  writeDrive<mrpt::io::CFileOutputStream>(path, 4, true, 3.0);
  expectDrive(readRawlog(path), 4);
}

TEST(RawlogTest, ReadsALogSavedAsOneCRawlogObject) {
  TempDir dir;
  const auto path = dir / "object.rawlog";
  mrpt::obs::CRawlog rawlog;
  for (int k = 0; k < 3; ++k) {
    mrpt::obs::CActionCollection actions = odometryIncrement(k == 0 ? 0.0 : kStep_m);
    rawlog.insert(actions);
    mrpt::obs::CSensoryFrame frame;
    frame.insert(makeScan(k * kStep_m));
    rawlog.insert(frame);
  }
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    out << rawlog;
  }
  const Rawlog log = readRawlog(path);
  EXPECT_EQ(log.entries, 1u);
  expectDrive(log, 3);
}

TEST(RawlogTest, ReversesLeftToRightScans) {
  TempDir dir;
  const auto path = dir / "ltr.rawlog";
  writeDrive<mrpt::io::CFileGZOutputStream>(path, 3, false);
  expectDrive(readRawlog(path), 3);
}

TEST(RawlogTest, KeepsTheLasersMountingYaw) {
  TempDir dir;
  const auto path = dir / "yaw.rawlog";
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    out << odometryIncrement(0.0);
    mrpt::obs::CSensoryFrame frame;
    frame.insert(makeScan(0.0, true, M_PI / 2));
    out << frame;
  }
  const Rawlog log = readRawlog(path);
  ASSERT_EQ(log.scans.size(), 1u);
  EXPECT_NEAR(log.scans[0].T_robot_laser.yaw_rad, M_PI / 2, 1e-9);
  EXPECT_NEAR(log.scans[0].scan.angle_min_rad, -M_PI / 2, 1e-6);
}

TEST(RawlogTest, ReadsTheObservationsOnlyFormatWithOdometryReadings) {
  TempDir dir;
  const auto path = dir / "obs.rawlog";
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    for (int k = 0; k < 4; ++k) {
      mrpt::obs::CObservationOdometry odometry;
      // Absolute readings from (2, 1), heading +x: taken relative to the first.
      odometry.odometry = mrpt::poses::CPose2D(2.0 + k * kStep_m, 1.0, 0.0);
      out << odometry << *makeScan(k * kStep_m);
    }
  }
  const Rawlog log = readRawlog(path);
  EXPECT_TRUE(log.observations_only);
  EXPECT_EQ(log.odometry_readings, 4u);
  expectDrive(log, 4);
}

TEST(RawlogTest, TurnsNanAndNegativeRangesIntoNoInformationAndCountsScansWithoutReturns) {
  TempDir dir;
  const auto path = dir / "bad_ranges.rawlog";
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    out << odometryIncrement(0.0);
    auto scan = makeScan(4.0);  // the wall 6 m ahead
    scan->setScanRange(90, std::numeric_limits<float>::quiet_NaN());
    scan->setScanRange(91, -2.0f);
    scan->setScanRange(92, std::numeric_limits<float>::infinity());  // flagged valid
    mrpt::obs::CSensoryFrame frame;
    frame.insert(scan);
    out << frame;
    auto empty = makeScan(0.0);
    for (int i = 0; i < kBeams; ++i) empty->setScanRangeValidity(i, false);
    mrpt::obs::CSensoryFrame frame2;
    frame2.insert(empty);
    out << odometryIncrement(kStep_m) << frame2;
  }
  const Rawlog log = readRawlog(path);
  ASSERT_EQ(log.scans.size(), 2u);
  const std::vector<float>& r = log.scans[0].scan.ranges_m;
  EXPECT_EQ(r[90], 0.0f);
  EXPECT_LT(r[90], log.scans[0].scan.range_min_m);  // below range_min: no information
  EXPECT_EQ(r[91], 0.0f);
  EXPECT_EQ(r[92], std::numeric_limits<float>::infinity());
  EXPECT_EQ(log.corrupt_beams, 2u);
  EXPECT_EQ(log.scans_without_returns, 1u);
}

TEST(RawlogTest, RefusesANonFiniteOdometryIncrementNamingFileAndEntry) {
  TempDir dir;
  const auto path = dir / "nan_odometry.rawlog";
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    mrpt::obs::CSensoryFrame frame;
    frame.insert(makeScan(0.0));
    out << odometryIncrement(0.0) << frame;
    out << odometryIncrement(std::numeric_limits<double>::quiet_NaN()) << frame;
  }
  const std::string message = messageOf<InputError>([&] { readRawlog(path); });
  EXPECT_TRUE(Contains(message, path.string()));
  EXPECT_TRUE(Contains(message, "entry 3"));
  EXPECT_TRUE(Contains(message, "odometry increment is not finite"));
}

/// The InputError of reading `path`, checked to name it.
std::string errorNaming(const std::filesystem::path& path) {
  try {
    readRawlog(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), path.string());
    EXPECT_TRUE(Contains(e.what(), path.string()));
    return e.problem();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw another exception type: " << e.what();
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

TEST(RawlogTest, AMissingFileIsNamed) {
  TempDir dir;
  EXPECT_EQ(errorNaming(dir / "nowhere.rawlog"), "file not found");
}

TEST(RawlogTest, ATruncatedGzipLogIsNamed) {
  TempDir dir;
  const auto whole = dir / "whole.rawlog";
  writeDrive<mrpt::io::CFileGZOutputStream>(whole, 20);
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 200u);
  const auto cut = dir.write("cut.rawlog", std::string_view(bytes).substr(0, bytes.size() / 2));
  EXPECT_TRUE(Contains(errorNaming(cut), "truncated"));
  // Cut just before the 8-byte gzip trailer: every object is there, the stream is not whole.
  const auto no_trailer =
      dir.write("no_trailer.rawlog", std::string_view(bytes).substr(0, bytes.size() - 8));
  EXPECT_TRUE(Contains(errorNaming(no_trailer), "truncated"));
}

TEST(RawlogTest, AnUncompressedLogCutInsideAnObjectIsNamed) {
  TempDir dir;
  const auto whole = dir / "whole.rawlog";
  writeDrive<mrpt::io::CFileOutputStream>(whole, 5);
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const auto cut = dir.write("cut.rawlog", std::string_view(bytes).substr(0, bytes.size() - 100));
  EXPECT_TRUE(Contains(errorNaming(cut), "truncated"));
}

TEST(RawlogTest, GarbageIsNotARawlog) {
  TempDir dir;
  std::string noise(4096, '\0');
  std::uint32_t state = 12345;
  for (char& c : noise) {
    state = state * 1664525u + 1013904223u;
    c = static_cast<char>(state >> 24);
  }
  EXPECT_TRUE(Contains(errorNaming(dir.write("noise.rawlog", noise)), "not an MRPT rawlog"));
  EXPECT_TRUE(Contains(errorNaming(dir.write("text.rawlog", "image: map.pgm\nresolution: 0.05\n")),
                       "not an MRPT rawlog"));
  EXPECT_TRUE(Contains(errorNaming(dir.write("empty.rawlog", "")), "empty file"));
}

TEST(RawlogTest, ALogWithoutLaserScansIsNamed) {
  TempDir dir;
  const auto path = dir / "odometry_only.rawlog";
  {
    mrpt::io::CFileGZOutputStream stream(path.string());
    auto out = mrpt::serialization::archiveFrom(stream);
    for (int k = 0; k < 3; ++k) out << odometryIncrement(kStep_m) << mrpt::obs::CSensoryFrame();
  }
  EXPECT_TRUE(Contains(errorNaming(path), "holds no 2D laser scans"));
}

}  // namespace
}  // namespace roomscout::slam
