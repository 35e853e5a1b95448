#pragma once
// Point cloud maps as PCD files (PCL's format; Open3D and CloudCompare read it too), written
// and read with PCL. Coordinates are the map frame of occupancy.yaml [m]; fields x y z (float).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace roomscout::io {

enum class PcdFormat { kAscii, kBinary, kBinaryCompressed };

/// "ascii", "binary" or "binary_compressed"; throws OptionError naming the known formats.
PcdFormat parsePcdFormat(std::string_view name);
std::string_view pcdFormatName(PcdFormat format);

/// Writes `points_map` as a PCD file with PCL, atomically: PCL writes a temporary file in the
/// same directory, a `# comment` line (newlines replaced by spaces) is added after the
/// format line, and the result replaces `path` by rename. VIEWPOINT is the identity (the
/// map frame). An empty cloud is written as ASCII whatever `format` says (PCL's binary
/// readers fail on an empty body). With precision_m > 0 the coordinates are rounded to multiples of
/// it and the points sorted by x, then y, then z: far smaller binary_compressed files (PCL's LZF
/// then finds repeated bytes), at an error of at most precision_m / 2 per axis.
/// Throws InputError naming the path when it cannot be written, InvalidArgument for a
/// negative precision.
void writePcdAtomic(const std::filesystem::path& path,
                    const std::vector<Eigen::Vector3f>& points_map, PcdFormat format,
                    std::string_view comment = {}, double precision_m = 0.0);

/// Reads the x y z fields of a PCD file with PCL. Throws InputError naming the path when it is
/// missing or PCL cannot parse it.
std::vector<Eigen::Vector3f> readPcd(const std::filesystem::path& path);

}  // namespace roomscout::io
