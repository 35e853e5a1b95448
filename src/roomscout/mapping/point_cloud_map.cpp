#include "roomscout/mapping/point_cloud_map.hpp"

#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

constexpr int kBits = 21;
constexpr std::int64_t kBias = std::int64_t{1} << (kBits - 1);
constexpr std::uint64_t kFieldMask = (std::uint64_t{1} << kBits) - 1;

std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (static_cast<std::uint64_t>(x + kBias) << (2 * kBits)) | (static_cast<std::uint64_t>(y + kBias) << kBits) |
         static_cast<std::uint64_t>(z + kBias);
}

Eigen::Vector3f voxelCentre(std::uint64_t key, float voxel) {
  const auto field = [&](int shift) {
    return static_cast<float>(static_cast<std::int64_t>((key >> shift) & kFieldMask) - kBias);
  };
  return Eigen::Vector3f(field(2 * kBits) + 0.5f, field(kBits) + 0.5f, field(0) + 0.5f) * voxel;
}

std::uint64_t mix(std::uint64_t k) {  // splitmix64 finaliser
  k ^= k >> 30;
  k *= 0xbf58476d1ce4e5b9ull;
  k ^= k >> 27;
  k *= 0x94d049bb133111ebull;
  return k ^ (k >> 31);
}

}  // namespace

void PointCloudMapOptions::validate() const {
  if (!(voxel_size_m >= 0.001 && voxel_size_m <= 10.0)) {
    throw OptionError("pointcloud.voxel_size_m must be in [0.001, 10]");
  }
  if (max_points < 1) throw OptionError("pointcloud.max_points must be >= 1");
}

std::vector<ParameterRef> PointCloudMapOptions::parameters() {
  return {
      {"voxel_size_m", &voxel_size_m, "voxel side of the point cloud map [m]"},
      {"max_points", &max_points, "most voxels (points) the map holds"},
  };
}

PointCloudMap::PointCloudMap(const PointCloudMapOptions& options) : options_(options) {
  options_.validate();
  inv_voxel_ = static_cast<float>(1.0 / options_.voxel_size_m);
  keys_.assign(1024, kEmpty);
  slot_voxel_.assign(1024, 0);
  mask_ = keys_.size() - 1;
}

std::size_t PointCloudMap::slotOf(std::uint64_t key) const {
  std::size_t slot = mix(key) & mask_;
  while (keys_[slot] != key && keys_[slot] != kEmpty) slot = (slot + 1) & mask_;
  return slot;
}

void PointCloudMap::grow() {
  keys_.assign(keys_.size() * 2, kEmpty);
  slot_voxel_.assign(keys_.size(), 0);
  mask_ = keys_.size() - 1;
  for (std::size_t v = 0; v < voxel_keys_.size(); ++v) {
    const std::size_t slot = slotOf(voxel_keys_[v]);
    keys_[slot] = voxel_keys_[v];
    slot_voxel_[slot] = static_cast<std::uint32_t>(v);
  }
}

std::size_t PointCloudMap::insert(const std::vector<Eigen::Vector3f>& points_map) {
  const std::size_t before = counts_.size();
  const float voxel = static_cast<float>(options_.voxel_size_m);
  const float limit = static_cast<float>(kBias - 1);
  for (const Eigen::Vector3f& p : points_map) {
    const Eigen::Vector3f q = p * inv_voxel_;
    if (!q.allFinite() || q.cwiseAbs().maxCoeff() >= limit) continue;
    const std::int64_t ix = static_cast<std::int64_t>(std::floor(q.x()));
    const std::int64_t iy = static_cast<std::int64_t>(std::floor(q.y()));
    const std::int64_t iz = static_cast<std::int64_t>(std::floor(q.z()));
    const std::uint64_t key = pack(ix, iy, iz);
    std::size_t slot = slotOf(key);
    std::uint32_t v;
    if (keys_[slot] == key) {
      v = slot_voxel_[slot];
    } else {
      if (counts_.size() >= static_cast<std::size_t>(options_.max_points)) {
        ++dropped_;
        continue;
      }
      if ((counts_.size() + 1) * 2 > keys_.size()) {
        grow();
        slot = slotOf(key);
      }
      v = static_cast<std::uint32_t>(counts_.size());
      keys_[slot] = key;
      slot_voxel_[slot] = v;
      voxel_keys_.push_back(key);
      sums_.push_back(Eigen::Vector3f::Zero());
      counts_.push_back(0);
    }
    // Sums relative to the voxel centre keep float precision far from the origin.
    sums_[v] += p - voxelCentre(key, voxel);
    ++counts_[v];
  }
  return counts_.size() - before;
}

std::vector<Eigen::Vector3f> PointCloudMap::points() const {
  std::vector<Eigen::Vector3f> out(counts_.size());
  const float voxel = static_cast<float>(options_.voxel_size_m);
  for (std::size_t v = 0; v < counts_.size(); ++v) {
    out[v] = voxelCentre(voxel_keys_[v], voxel) + sums_[v] / static_cast<float>(counts_[v]);
  }
  return out;
}

std::pair<Eigen::Vector3f, Eigen::Vector3f> PointCloudMap::bounds() const {
  if (empty()) return {Eigen::Vector3f::Zero(), Eigen::Vector3f::Zero()};
  const std::vector<Eigen::Vector3f> pts = points();
  Eigen::Vector3f lo = pts.front(), hi = pts.front();
  for (const Eigen::Vector3f& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

std::size_t PointCloudMap::memoryBytes() const {
  return keys_.capacity() * sizeof(std::uint64_t) + slot_voxel_.capacity() * sizeof(std::uint32_t) +
         sums_.capacity() * sizeof(Eigen::Vector3f) + counts_.capacity() * sizeof(std::uint32_t) +
         voxel_keys_.capacity() * sizeof(std::uint64_t);
}

}  // namespace roomscout
