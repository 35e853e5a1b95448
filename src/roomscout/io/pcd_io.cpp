#include "roomscout/io/pcd_io.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <tuple>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::io {

PcdFormat parsePcdFormat(std::string_view name) {
  if (name == "ascii") return PcdFormat::kAscii;
  if (name == "binary") return PcdFormat::kBinary;
  if (name == "binary_compressed") return PcdFormat::kBinaryCompressed;
  throw OptionError("unknown PCD format '" + std::string(name) +
                    "' (known: ascii, binary, binary_compressed)");
}

std::string_view pcdFormatName(PcdFormat format) {
  switch (format) {
    case PcdFormat::kAscii:
      return "ascii";
    case PcdFormat::kBinary:
      return "binary";
    case PcdFormat::kBinaryCompressed:
      return "binary_compressed";
  }
  return "binary";
}

void writePcdAtomic(const std::filesystem::path& path,
                    const std::vector<Eigen::Vector3f>& points_map, PcdFormat format,
                    std::string_view comment, double precision_m) {
  if (!(precision_m >= 0.0)) throw InvalidArgument("writePcdAtomic: precision_m must be >= 0");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(points_map.size());
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    Eigen::Vector3d p = points_map[i].cast<double>();
    if (precision_m > 0.0) p = (p / precision_m).array().round() * precision_m;
    cloud[i].x = static_cast<float>(p.x());
    cloud[i].y = static_cast<float>(p.y());
    cloud[i].z = static_cast<float>(p.z());
  }
  if (precision_m > 0.0) {
    std::sort(cloud.begin(), cloud.end(), [](const pcl::PointXYZ& a, const pcl::PointXYZ& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
  }
  cloud.width = static_cast<std::uint32_t>(points_map.size());
  cloud.height = 1;
  cloud.is_dense = true;
  if (cloud.empty()) format = PcdFormat::kAscii;  // PCL's binary readers fail on no data

  static std::atomic<int> counter{0};
  std::filesystem::path directory = path.parent_path();
  if (directory.empty()) directory = ".";
  std::string name(1, '.');  // hidden; built by appending (GCC 12 misreports "." + str)
  name += path.filename().string();
  name += ".pcl.";
  name += std::to_string(::getpid());
  name += '.';
  name += std::to_string(counter.fetch_add(1));
  const std::filesystem::path temp = directory / name;
  struct RemoveTemp {
    const std::filesystem::path& p;
    ~RemoveTemp() {
      std::error_code ec;
      std::filesystem::remove(p, ec);
    }
  } remove_temp{temp};

  pcl::PCDWriter writer;
  int status = -1;
  try {
    switch (format) {
      case PcdFormat::kAscii:
        status = writer.writeASCII(temp.string(), cloud, 8);
        break;
      case PcdFormat::kBinary:
        status = writer.writeBinary(temp.string(), cloud);
        break;
      case PcdFormat::kBinaryCompressed:
        status = writer.writeBinaryCompressed(temp.string(), cloud);
        break;
    }
  } catch (const std::exception& e) {
    throw InputError(path.string(), std::string("cannot write: ") + e.what());
  }
  if (status != 0) throw InputError(path.string(), "cannot write: PCL's PCD writer failed");

  std::string bytes = readFile(temp);
  if (!comment.empty()) {
    std::string line = "# ";
    for (char c : comment) line += (c == '\n' || c == '\r') ? ' ' : c;
    line += '\n';
    const std::size_t first_line_end = bytes.find('\n');
    bytes.insert(first_line_end == std::string::npos ? 0 : first_line_end + 1, line);
  }
  writeFileAtomic(path, bytes);
}

std::vector<Eigen::Vector3f> readPcd(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "file not found");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::PCDReader reader;
  int status = -1;
  try {
    pcl::PCLPointCloud2 header;
    int version = 0, data_type = 0;
    unsigned int data_idx = 0;
    Eigen::Vector4f origin;
    Eigen::Quaternionf orientation;
    if (reader.readHeader(path.string(), header, origin, orientation, version, data_type,
                          data_idx) != 0) {
      throw InputError(path.string(), "cannot read PCD: bad header");
    }
    int xyz = 0;
    for (const pcl::PCLPointField& f : header.fields)
      xyz += f.name == "x" || f.name == "y" || f.name == "z";
    if (xyz != 3) throw InputError(path.string(), "cannot read PCD: no x y z fields");
    if (header.width * header.height == 0)
      return {};  // PCL's reader crashes on an empty binary body
    status = reader.read(path.string(), cloud);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path.string(), std::string("cannot read PCD: ") + e.what());
  }
  if (status != 0) throw InputError(path.string(), "cannot read PCD: PCL's reader failed");
  std::vector<Eigen::Vector3f> points(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    points[i] = Eigen::Vector3f(cloud[i].x, cloud[i].y, cloud[i].z);
  return points;
}

}  // namespace roomscout::io
