#include "roomscout/mapping/point_cloud_map.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

constexpr int kBits = 21;
constexpr std::int64_t kBias = std::int64_t{1} << (kBits - 1);
constexpr std::uint64_t kFieldMask = (std::uint64_t{1} << kBits) - 1;

std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (static_cast<std::uint64_t>(x + kBias) << (2 * kBits)) |
         (static_cast<std::uint64_t>(y + kBias) << kBits) | static_cast<std::uint64_t>(z + kBias);
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
      {"max_points", &max_points,
       "most voxels (points) the map holds, about 70 bytes each; beyond it no voxel is created, "
       "but points in existing voxels still count"},
  };
}

PointCloudMap::PointCloudMap(const PointCloudMapOptions& options) : options_(options) {
  options_.validate();
  inv_voxel_ = static_cast<float>(1.0 / options_.voxel_size_m);
  slots_.assign(1024, Slot{kEmpty, 0});
  mask_ = slots_.size() - 1;
}

std::size_t PointCloudMap::slotOf(std::uint64_t key) const {
  std::size_t slot = mix(key) & mask_;
  while (slots_[slot].key != key && slots_[slot].key != kEmpty) slot = (slot + 1) & mask_;
  return slot;
}

void PointCloudMap::grow() {
  slots_.assign(slots_.size() * 2, Slot{kEmpty, 0});
  mask_ = slots_.size() - 1;
  for (std::size_t v = 0; v < voxel_keys_.size(); ++v) {
    const std::size_t slot = slotOf(voxel_keys_[v]);
    slots_[slot] = {voxel_keys_[v], static_cast<std::uint32_t>(v)};
  }
}

std::size_t PointCloudMap::insert(const std::vector<Eigen::Vector3f>& points_map) {
  const std::size_t before = voxels_.size();
  const float voxel = static_cast<float>(options_.voxel_size_m);
  const float limit = static_cast<float>(kBias - 1);
  // First the voxel key of every point (kEmpty: skipped), so that the hash slots of points a
  // few ahead can be prefetched: on a large map nearly every probe misses the cache.
  std::vector<std::uint64_t>& keys = scratch_keys_;
  keys.resize(points_map.size());
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    const Eigen::Vector3f q = points_map[i] * inv_voxel_;
    if (!q.allFinite() || q.cwiseAbs().maxCoeff() >= limit) {
      keys[i] = kEmpty;
      continue;
    }
    keys[i] = pack(static_cast<std::int64_t>(std::floor(q.x())),
                   static_cast<std::int64_t>(std::floor(q.y())),
                   static_cast<std::int64_t>(std::floor(q.z())));
  }
  // Consecutive points of a revolution often share a voxel (neighbouring beams of one ring):
  // a small direct-mapped cache of key -> voxel skips their probes. Voxel indices never
  // change, so the cache only saves time; the sums are added in the same order as without it.
  constexpr int kRecent = 64;
  std::uint64_t recent_key[kRecent];
  std::uint32_t recent_voxel[kRecent];
  std::fill(std::begin(recent_key), std::end(recent_key), kEmpty);
  // Two prefetch stages: the slot of the point kSlotAhead ahead, then, once that slot is
  // likely in cache, the voxel it points to for the point kVoxelAhead ahead.
  constexpr std::size_t kSlotAhead = 16, kVoxelAhead = 8;
  const std::size_t n = keys.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i + kSlotAhead < n && keys[i + kSlotAhead] != kEmpty) {
      __builtin_prefetch(slots_.data() + (mix(keys[i + kSlotAhead]) & mask_));
    }
    if (i + kVoxelAhead < n && keys[i + kVoxelAhead] != kEmpty) {
      const Slot& ahead = slots_[mix(keys[i + kVoxelAhead]) & mask_];
      if (ahead.key == keys[i + kVoxelAhead]) __builtin_prefetch(voxels_.data() + ahead.voxel);
    }
    const std::uint64_t key = keys[i];
    if (key == kEmpty) continue;
    const int r = static_cast<int>((key ^ (key >> kBits) ^ (key >> (2 * kBits))) & (kRecent - 1));
    std::uint32_t v;
    if (recent_key[r] == key) {
      v = recent_voxel[r];
    } else {
      std::size_t slot = slotOf(key);
      if (slots_[slot].key == key) {
        v = slots_[slot].voxel;
      } else {
        if (voxels_.size() >= static_cast<std::size_t>(options_.max_points)) {
          ++dropped_;
          continue;
        }
        if ((voxels_.size() + 1) * 2 > slots_.size()) {
          grow();
          slot = slotOf(key);
        }
        v = static_cast<std::uint32_t>(voxels_.size());
        slots_[slot] = {key, v};
        voxel_keys_.push_back(key);
        voxels_.push_back({Eigen::Vector3f::Zero(), 0});
      }
      recent_key[r] = key;
      recent_voxel[r] = v;
    }
    Voxel& vox = voxels_[v];
    vox.sum += points_map[i] - voxelCentre(key, voxel);
    ++vox.count;
  }
  return voxels_.size() - before;
}

std::vector<Eigen::Vector3f> PointCloudMap::points() const {
  std::vector<Eigen::Vector3f> out(voxels_.size());
  const float voxel = static_cast<float>(options_.voxel_size_m);
  for (std::size_t v = 0; v < voxels_.size(); ++v) {
    out[v] =
        voxelCentre(voxel_keys_[v], voxel) + voxels_[v].sum / static_cast<float>(voxels_[v].count);
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
  // The same bytes as separate arrays of keys (8), slot voxel indices (4), sums (12) and
  // counts (4) would hold.
  return slots_.capacity() * sizeof(Slot) + voxels_.capacity() * sizeof(Voxel) +
         voxel_keys_.capacity() * sizeof(std::uint64_t);
}

}  // namespace roomscout
