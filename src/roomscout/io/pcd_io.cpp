#include "roomscout/io/pcd_io.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

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

namespace {

/// Checks that a PCD file's header is consistent and that the body can hold the points it
/// announces, before PCL sees the file: PCL's reader allocates POINTS x point size from the
/// header alone, and reads a binary_compressed body past its buffer when the sizes disagree.
/// Throws InputError(path, "cannot read PCD: ...").
void checkPcdHeader(const std::filesystem::path& path) {
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(path.string(), "cannot read PCD: " + problem);
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open the file");
  std::error_code ec;
  const std::uint64_t file_size = std::filesystem::file_size(path, ec);
  if (ec) fail("cannot read the file size");
  const auto number = [&](const std::string& token, const std::string& key) {
    std::uint64_t value = 0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size() || value > (1ULL << 40))
      fail(key + ": expected a non-negative integer, got '" + token + "'");
    return value;
  };
  std::vector<std::uint64_t> sizes, counts;
  std::vector<std::string> names, types;
  std::optional<std::uint64_t> points, width, height;
  std::string data;
  std::string line;
  // The header: one keyword per line, up to and including DATA; PCL reads at most this much.
  for (int lines = 0; data.empty() && std::getline(in, line); ++lines) {
    if (lines > 1000) fail("no DATA line in the first 1000 lines");
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#') continue;
    std::vector<std::string> values;
    for (std::string v; words >> v;) values.push_back(v);
    // PCL recognises a keyword by its prefix ("COUNTS" is COUNT): so do we.
    const auto is = [&](std::string_view k) { return key.compare(0, k.size(), k) == 0; };
    if (is("FIELDS") || is("COLUMNS")) {
      names = values;
    } else if (is("TYPE")) {
      types = values;
    } else if (is("SIZE")) {
      sizes.clear();
      for (const std::string& v : values) sizes.push_back(number(v, "SIZE"));
    } else if (is("COUNT")) {
      counts.clear();
      for (const std::string& v : values) counts.push_back(number(v, "COUNT"));
    } else if (is("POINTS") || is("WIDTH") || is("HEIGHT")) {
      const std::string k = is("POINTS") ? "POINTS" : is("WIDTH") ? "WIDTH" : "HEIGHT";
      if (values.empty()) fail(k + ": expected a number");
      const std::uint64_t value = number(values[0], k);
      (k == "POINTS" ? points : k == "WIDTH" ? width : height) = value;
    } else if (is("DATA")) {
      data = values.empty() ? std::string("?") : values[0];
    }
  }
  if (data.empty()) fail("no DATA line");
  const std::size_t fields = names.size();
  if (fields == 0 || sizes.size() != fields || types.size() != fields ||
      (!counts.empty() && counts.size() != fields))
    fail("FIELDS, SIZE, TYPE and COUNT do not have the same number of entries");
  if (counts.empty()) counts.assign(fields, 1);
  // PCL copies 4 bytes for each of x, y and z whatever the header says.
  for (std::size_t i = 0; i < fields; ++i) {
    if ((names[i] == "x" || names[i] == "y" || names[i] == "z") &&
        (sizes[i] != 4 || types[i] != "F" || counts[i] != 1))
      fail("field " + names[i] + " is not a float (SIZE 4, TYPE F, COUNT 1)");
  }
  std::uint64_t point_bytes = 0, values_per_point = 0;
  for (std::size_t i = 0; i < fields; ++i) {
    if (sizes[i] != 1 && sizes[i] != 2 && sizes[i] != 4 && sizes[i] != 8)
      fail("SIZE: " + std::to_string(sizes[i]) + " is not 1, 2, 4 or 8");
    if (counts[i] == 0 || counts[i] > (1U << 20))
      fail("COUNT: " + std::to_string(counts[i]) + " is not 1 to 2^20");
    point_bytes += sizes[i] * counts[i];
    values_per_point += counts[i];
  }
  const std::uint64_t n =
      points ? *points : (width && height && *width <= (1U << 31) ? *width * *height : 0);
  if (width && height && *width <= (1U << 31) && *height <= (1U << 31) && *width * *height != n)
    fail("WIDTH x HEIGHT is not POINTS");
  // The DATA line may end the file without a newline: then the body is empty.
  const std::streamoff body_start = in.tellg();
  const std::uint64_t body =
      body_start < 0 ? 0 : file_size - std::min(file_size, static_cast<std::uint64_t>(body_start));
  const std::string announced =
      std::to_string(n) + " points of " + std::to_string(point_bytes) + " bytes";
  if (data == "ascii") {
    // A value is at least one character and a separator.
    if (n > (body + 1) / (2 * values_per_point))
      fail("the header announces " + announced + " but the ASCII body has only " +
           std::to_string(body) + " bytes");
  } else if (data == "binary") {
    if (n > body / point_bytes)
      fail("the header announces " + announced + " but the binary body has only " +
           std::to_string(body) + " bytes");
  } else if (data == "binary_compressed") {
    if (n == 0) return;
    unsigned char sizes_le[8];
    if (body < 8 || !in.read(reinterpret_cast<char*>(sizes_le), 8))
      fail("binary_compressed body shorter than its 8-byte size header");
    const auto le32 = [&](int at) {
      return std::uint64_t{sizes_le[at]} | (std::uint64_t{sizes_le[at + 1]} << 8) |
             (std::uint64_t{sizes_le[at + 2]} << 16) | (std::uint64_t{sizes_le[at + 3]} << 24);
    };
    const std::uint64_t compressed = le32(0), uncompressed = le32(4);
    if (compressed > body - 8)
      fail("compressed size " + std::to_string(compressed) + " is beyond the end of the file");
    if (n > (1ULL << 40) / point_bytes || uncompressed != n * point_bytes)
      fail("the header announces " + announced + " but the uncompressed size is " +
           std::to_string(uncompressed) + " bytes");
    // LZF expands at most about 100-fold (a 3-byte back reference copies up to 264 bytes).
    if (uncompressed > 100 * compressed + 64)
      fail("uncompressed size " + std::to_string(uncompressed) +
           " is impossible for a compressed size of " + std::to_string(compressed));
  } else {
    fail("DATA: unknown format '" + data + "' (known: ascii, binary, binary_compressed)");
  }
}

}  // namespace

std::vector<Eigen::Vector3f> readPcd(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "file not found");
  checkPcdHeader(path);
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
    // PCL's own reading of the header must agree with the check above: x, y and z floats,
    // every field at least one value, points within the point size.
    for (const pcl::PCLPointField& f : header.fields) {
      if ((f.name == "x" || f.name == "y" || f.name == "z") &&
          (f.datatype != pcl::PCLPointField::FLOAT32 || f.count != 1))
        throw InputError(path.string(), "cannot read PCD: field " + f.name +
                                            " is not a float (SIZE 4, TYPE F, COUNT 1)");
      if (f.count < 1 || f.offset + pcl::getFieldSize(f.datatype) * f.count > header.point_step)
        throw InputError(path.string(), "cannot read PCD: inconsistent field " + f.name);
    }
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
