// Fuzz target: a PCD point cloud as io::readPcd reads it back (pointcloud.pcd of a run's
// maps). The only accepted failure is InputError.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/pcd_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path path = fuzz::scratchDir() / "cloud.pcd";
  fuzz::writeFile(path, fuzz::asText(data, size));
  try {
    const std::vector<Eigen::Vector3f> points = io::readPcd(path);
    (void)points;
  } catch (const InputError&) {
  }
  return 0;
}
