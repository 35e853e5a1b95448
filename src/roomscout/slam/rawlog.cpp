#include "roomscout/slam/rawlog.hpp"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "roomscout/core/errors.hpp"

namespace roomscout::slam {
namespace {

/// The whole file, decompressed when it is gzip (zlib reads other files as they are).
std::string readMaybeGzip(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "file not found");
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path.string(), "cannot read: is a directory");
  }
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr) throw InputError(path.string(), "cannot open for reading");
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const int n = gzread(file, buffer, sizeof(buffer));
    if (n < 0) {
      int code = 0;
      const std::string message = gzerror(file, &code);
      gzclose(file);
      throw InputError(path.string(), "truncated or corrupt gzip stream (zlib: " + message + ")");
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  // zlib reports a gzip stream cut short only when it is closed.
  const int closed = gzclose(file);
  if (closed == Z_BUF_ERROR) {
    throw InputError(path.string(), "truncated gzip stream (it ends before its trailer)");
  }
  if (closed != Z_OK) throw InputError(path.string(), "cannot read the gzip stream");
  return bytes;
}

bool finitePose(const mrpt::poses::CPose2D& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi());
}

Pose2 toPose2(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), wrapAngle(p.phi())}; }

/// Reads the objects of a rawlog and turns them into scans and odometry.
class RawlogParser {
 public:
  explicit RawlogParser(const std::filesystem::path& path) : path_(path.string()) {}

  Rawlog parse(const std::string& bytes) {
    mrpt::io::CMemoryStream stream;
    stream.assignMemoryNotOwn(bytes.data(), bytes.size());
    auto archive = mrpt::serialization::archiveFrom(stream);
    while (stream.getPosition() < bytes.size()) {
      const std::uint64_t start = stream.getPosition();
      mrpt::serialization::CSerializable::Ptr object;
      try {
        archive >> object;
      } catch (const mrpt::serialization::CExceptionEOF&) {
        fail(start, bytes.size(), "the file ends in the middle of an object (truncated)");
      } catch (const std::bad_alloc&) {
        fail(start, bytes.size(), "not an MRPT rawlog (a size field asks for too much memory)");
      } catch (const std::exception& e) {
        // MRPT reports running out of bytes inside an object as a generic error.
        if (stream.getPosition() >= bytes.size()) {
          fail(start, bytes.size(), "the file ends in the middle of an object (truncated)");
        }
        fail(start, bytes.size(), "not an MRPT rawlog (MRPT: " + mrptMessage(e.what()) + ")");
      }
      ++log_.entries;
      if (object) take(*object, start);
    }
    if (log_.entries == 0) throw InputError(path_, "empty file: no rawlog entries");
    if (log_.scans.empty()) {
      throw InputError(path_, "holds no 2D laser scans (CObservation2DRangeScan) in " +
                                  std::to_string(log_.entries) + " entries");
    }
    // The first scan's robot at the origin.
    const mrpt::poses::CPose2D first = odometry_at_scan_.front();
    for (std::size_t i = 0; i < log_.scans.size(); ++i) {
      log_.scans[i].T_odom_robot = toPose2(odometry_at_scan_[i] - first);
    }
    return std::move(log_);
  }

 private:
  [[noreturn]] void fail(std::uint64_t offset, std::uint64_t size, const std::string& problem) {
    throw InputError(path_, problem + " at byte " + std::to_string(offset) + " of " +
                                std::to_string(size) + " (uncompressed), after " +
                                std::to_string(log_.entries) + " entries");
  }

  /// A problem with the content of the entry that starts at byte `offset`.
  [[noreturn]] void failEntry(std::uint64_t offset, const std::string& problem) {
    throw InputError(path_, "entry " + std::to_string(log_.entries) + " (byte " +
                                std::to_string(offset) + " uncompressed): " + problem);
  }

  /// The innermost message of an MRPT exception, without its banners and call stacks (and
  /// without its guess that the stream might be gzip: it was read as gzip when it was).
  static std::string mrptMessage(const std::string& text) {
    const std::string tag = "Message:";
    const std::size_t at = text.rfind(tag);
    if (at == std::string::npos) return text.substr(0, text.find('\n'));
    std::string message = text.substr(at + tag.size());
    message = message.substr(0, message.find('\n'));
    message = message.substr(0, message.find(" (Perhaps it's a gz"));
    const std::size_t first = message.find_first_not_of(' ');
    return first == std::string::npos ? std::string() : message.substr(first);
  }

  void take(const mrpt::serialization::CSerializable& object, std::uint64_t offset) {
    using namespace mrpt::obs;
    if (const auto* actions = dynamic_cast<const CActionCollection*>(&object)) {
      // The first 2D movement, not getBestMovementEstimation(): that one picks by covariance
      // and returns none when a covariance is NaN.
      const CActionRobotMovement2D::Ptr move = actions->getActionByClass<CActionRobotMovement2D>();
      if (!move) return;
      if (!move->poseChange) failEntry(offset, "an odometry increment has no pose change");
      const mrpt::poses::CPose2D increment = move->poseChange->getMeanVal();
      if (!finitePose(increment)) {
        failEntry(offset, "odometry increment is not finite (" + increment.asString() + ")");
      }
      odometry_ = odometry_ + increment;
      ++log_.odometry_readings;
    } else if (const auto* frame = dynamic_cast<const CSensoryFrame*>(&object)) {
      for (const CObservation::Ptr& o : *frame) {
        if (o) takeObservation(*o, offset);
      }
    } else if (const auto* rawlog = dynamic_cast<const CRawlog*>(&object)) {
      // A whole CRawlog serialised as one object: its entries in order.
      for (std::size_t i = 0; i < rawlog->size(); ++i) {
        if (const auto entry = rawlog->getAsGeneric(i)) take(*entry, offset);
      }
    } else if (const auto* observation = dynamic_cast<const CObservation*>(&object)) {
      log_.observations_only = true;
      takeObservation(*observation, offset);
    }
  }

  void takeObservation(const mrpt::obs::CObservation& observation, std::uint64_t offset) {
    using namespace mrpt::obs;
    if (const auto* odometry = dynamic_cast<const CObservationOdometry*>(&observation)) {
      if (!finitePose(odometry->odometry)) {
        failEntry(offset, "odometry reading is not finite (" + odometry->odometry.asString() + ")");
      }
      // Absolute readings, taken relative to the first.
      if (!first_reading_) first_reading_ = odometry->odometry;
      odometry_ = odometry->odometry - *first_reading_;
      ++log_.odometry_readings;
    } else if (const auto* scan = dynamic_cast<const CObservation2DRangeScan*>(&observation)) {
      takeScan(*scan, offset);
    }
  }

  void takeScan(const mrpt::obs::CObservation2DRangeScan& in, std::uint64_t offset) {
    const std::size_t n = in.getScanSize();
    if (n < 2) failEntry(offset, "a laser scan has " + std::to_string(n) + " beams (at least 2)");
    if (!std::isfinite(in.aperture) || !(in.aperture > 0.0f) ||
        !(in.aperture <= 2.0f * static_cast<float>(M_PI) + 1e-3f)) {
      failEntry(offset, "a laser scan's aperture is not in (0, 2 pi]");
    }
    if (!std::isfinite(in.maxRange) || !(in.maxRange > 0.0f)) {
      failEntry(offset, "a laser scan's maximum range is not a positive number");
    }
    const mrpt::math::TPose3D sensor = in.sensorPose.asTPose();
    if (!std::isfinite(sensor.x) || !std::isfinite(sensor.y) || !std::isfinite(sensor.yaw)) {
      failEntry(offset, "a laser scan's sensor pose is not finite");
    }

    RawlogScan out;
    out.T_robot_laser = {sensor.x, sensor.y, wrapAngle(sensor.yaw)};
    LaserScan& scan = out.scan;
    const double aperture = in.aperture;
    scan.angle_min_rad = -0.5 * aperture;
    scan.angle_increment_rad = aperture / static_cast<double>(n - 1);
    scan.range_min_m = kRangeMin_m;
    scan.range_max_m = in.maxRange;
    scan.ranges_m.resize(n);
    constexpr float kNoReturn = std::numeric_limits<float>::infinity();
    std::size_t returns = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const float r = in.getScanRange(i);
      float value;
      if (std::isnan(r) || r < 0.0f) {
        value = 0.0f;  // corrupt: no information
        ++log_.corrupt_beams;
      } else if (!in.getScanRangeValidity(i) || r > in.maxRange) {
        value = kNoReturn;
        ++log_.invalid_beams;
      } else {
        value = r;
        if (r >= kRangeMin_m) ++returns;
      }
      // MRPT's beam i lies at -aperture/2 + i * step when right to left, +aperture/2 - i * step
      // otherwise: reverse the latter so that angles grow with the index.
      scan.ranges_m[in.rightToLeft ? i : n - 1 - i] = value;
    }
    if (returns == 0) ++log_.scans_without_returns;
    log_.scans.push_back(std::move(out));
    odometry_at_scan_.push_back(odometry_);
  }

  static constexpr double kRangeMin_m = 0.01;

  std::string path_;
  Rawlog log_;
  mrpt::poses::CPose2D odometry_;  ///< accumulated so far
  std::optional<mrpt::poses::CPose2D> first_reading_;
  std::vector<mrpt::poses::CPose2D> odometry_at_scan_;
};

}  // namespace

Rawlog readRawlog(const std::filesystem::path& path) {
  const std::string bytes = readMaybeGzip(path);
  return RawlogParser(path).parse(bytes);
}

}  // namespace roomscout::slam
