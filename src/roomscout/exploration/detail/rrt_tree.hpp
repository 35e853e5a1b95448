#pragma once
// The rapidly-exploring random tree that RRT-based frontier detectors grow over an occupancy
// grid (Umari & Mukhopadhyay, IROS 2017, rrt_exploration; SMMR-Explore's rrt node): nearest
// node, steer by a fixed step, and an edge check that walks the segment and stops at the first
// unknown cell (a detected frontier point). Where the samples come from is the caller's choice
// (an injectable sampler), so uniform, map-box and room-biased samplers share one tree.

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout {

/// What an edge check found along a segment of the grid.
enum class EdgeStatus : std::uint8_t {
  kFree,      ///< every cell along the segment is known free
  kFrontier,  ///< the walk reached an unknown cell (and no occupied cell before it)
  kObstacle,  ///< the segment crosses an occupied cell (or leaves the grid)
};

/// Result of one edge check: the status and where the walk ended [m] (the segment's end when
/// free, the first unknown point when a frontier, the first occupied point when an obstacle).
struct EdgeCheck {
  EdgeStatus status = EdgeStatus::kFree;
  Vec2 end_m = Vec2::Zero();
};

/// Walks the segment `from_m` -> `to_m` in steps of a fifth of a cell (rrt_exploration's
/// ObstacleFree), as in the original: the walk stops at the first unknown cell; an occupied
/// cell met before it makes the edge an obstacle. Points outside the grid count as occupied.
EdgeCheck checkEdge(const OccupancyGrid& grid, const Vec2& from_m, const Vec2& to_m);

/// The outcome of one tree extension.
struct RrtExtension {
  EdgeStatus status = EdgeStatus::kObstacle;
  std::size_t nearest = 0;    ///< index of the node the edge starts from
  Vec2 new_m = Vec2::Zero();  ///< steered point, truncated at the frontier when one was met
  bool added = false;         ///< true when `new_m` became a node (free edges only)
};

/// A random tree of points in the map frame with a bucket index for nearest-node queries
/// (O(nodes in nearby buckets) instead of O(all nodes)). Not thread-safe.
class RrtTree {
 public:
  /// Returns a sample point in the map frame [m]; gets the tree's random generator.
  using Sampler = std::function<Vec2(std::mt19937_64& rng)>;

  /// @param eta_m steering step: new nodes lie at most this far from their parent [m], > 0
  /// @param min_m, max_m the box nodes are expected in (the grid's extent) [m]; nodes outside
  ///        it are still stored and found, in the border buckets
  /// @param bucket_m side of an index bucket [m], > 0
  RrtTree(double eta_m, const Vec2& min_m, const Vec2& max_m, double bucket_m = 0.5);

  /// Removes every node and roots the tree at `root_m`.
  void reset(const Vec2& root_m);

  std::size_t size() const { return nodes_.size(); }
  bool empty() const { return nodes_.empty(); }
  const Vec2& node(std::size_t i) const { return nodes_[i]; }
  /// Parent of node `i` (the root is its own parent).
  std::size_t parent(std::size_t i) const { return parents_[i]; }
  double eta_m() const { return eta_m_; }

  /// Index of the node nearest to `p_m` (ties: the earliest node). The tree must not be empty.
  std::size_t nearest(const Vec2& p_m) const;

  /// The point at most `eta_m` from `from_m` toward `toward_m` (rrt_exploration's Steer).
  static Vec2 steer(const Vec2& from_m, const Vec2& toward_m, double eta_m);

  /// One RRT iteration toward `sample_m`: nearest node, steer, edge check; a free edge adds
  /// the new node. The tree must not be empty.
  RrtExtension extend(const OccupancyGrid& grid, const Vec2& sample_m);

  /// One iteration with a sample drawn from `sampler`.
  RrtExtension grow(const OccupancyGrid& grid, const Sampler& sampler, std::mt19937_64& rng) {
    return extend(grid, sampler(rng));
  }

  /// Appends a node without checks (used by tests and by callers that know the edge is free).
  std::size_t add(const Vec2& p_m, std::size_t parent);

  /// Re-indexes the tree for the box [min_m, max_m] (the grid grew or moved, as a SLAM map
  /// does) and keeps only the nodes `keep` accepts (e.g. those still on the grid), in their
  /// order. A kept node whose parent was dropped hangs from its nearest kept ancestor, or is a
  /// root (its own parent) when it has none. Returns the number of nodes kept; with none the
  /// tree is empty and must be reset() before it grows again.
  std::size_t rebound(const Vec2& min_m, const Vec2& max_m,
                      const std::function<bool(const Vec2&)>& keep);

 private:
  /// Sizes an empty index for the box [min_m, max_m].
  void layBuckets(const Vec2& min_m, const Vec2& max_m);
  int bucketX(double x_m) const;
  int bucketY(double y_m) const;

  double eta_m_;
  Vec2 min_m_;
  double bucket_m_;
  int buckets_x_ = 1, buckets_y_ = 1;
  std::vector<std::vector<std::uint32_t>> buckets_;
  // Bounding box of non-empty buckets, to stop ring searches early.
  int used_min_x_ = 0, used_min_y_ = 0, used_max_x_ = -1, used_max_y_ = -1;
  std::vector<Vec2> nodes_;
  std::vector<std::size_t> parents_;
};

/// A sampler drawing uniformly from the box [min_m, max_m].
RrtTree::Sampler uniformBoxSampler(const Vec2& min_m, const Vec2& max_m);

}  // namespace roomscout
