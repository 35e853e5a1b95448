#include "roomscout/exploration/detail/rrt_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/random.hpp"

namespace roomscout {

EdgeCheck checkEdge(const OccupancyGrid& grid, const Vec2& from_m, const Vec2& to_m) {
  const GridGeometry& g = grid.geometry();
  const double step_m = 0.2 * g.resolution_m();
  const Vec2 delta = to_m - from_m;
  const double length_m = delta.norm();
  const int steps = static_cast<int>(std::ceil(length_m / step_m));
  bool obstacle = false;
  Vec2 obstacle_at = to_m;
  for (int i = 1; i <= steps; ++i) {
    const Vec2 p = i == steps ? to_m : Vec2(from_m + delta * (i * step_m / length_m));
    const Cell c = g.cellOf(p);
    if (!g.contains(c)) {
      if (!obstacle) obstacle_at = p;
      obstacle = true;
      break;
    }
    const CellState s = grid.state(g.index(c));
    if (s == CellState::kOccupied && !obstacle) {
      obstacle = true;
      obstacle_at = p;
    } else if (s == CellState::kUnknown) {
      if (obstacle) break;
      return {EdgeStatus::kFrontier, p};
    }
  }
  if (obstacle) return {EdgeStatus::kObstacle, obstacle_at};
  return {EdgeStatus::kFree, to_m};
}

RrtTree::RrtTree(double eta_m, const Vec2& min_m, const Vec2& max_m, double bucket_m)
    : eta_m_(eta_m), min_m_(min_m), bucket_m_(bucket_m) {
  if (!(eta_m > 0.0) || !(bucket_m > 0.0))
    throw InvalidArgument("RrtTree: eta_m and bucket_m must be > 0");
  layBuckets(min_m, max_m);
}

void RrtTree::layBuckets(const Vec2& min_m, const Vec2& max_m) {
  if (!(max_m.x() >= min_m.x() && max_m.y() >= min_m.y()))
    throw InvalidArgument("RrtTree: empty box");
  min_m_ = min_m;
  buckets_x_ = std::max(1, static_cast<int>(std::ceil((max_m.x() - min_m.x()) / bucket_m_)));
  buckets_y_ = std::max(1, static_cast<int>(std::ceil((max_m.y() - min_m.y()) / bucket_m_)));
  buckets_.assign(static_cast<std::size_t>(buckets_x_) * buckets_y_, {});
  used_min_x_ = used_min_y_ = 0;
  used_max_x_ = used_max_y_ = -1;
}

std::size_t RrtTree::rebound(const Vec2& min_m, const Vec2& max_m,
                             const std::function<bool(const Vec2&)>& keep) {
  constexpr std::size_t kDropped = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> new_index(nodes_.size(), kDropped);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (keep(nodes_[i])) new_index[i] = kept++;
  }
  std::vector<Vec2> nodes;
  std::vector<std::size_t> parents;
  nodes.reserve(kept);
  parents.reserve(kept);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (new_index[i] == kDropped) continue;
    std::size_t a = i;  // up to the nearest kept ancestor, or a root
    while (parents_[a] != a && new_index[parents_[a]] == kDropped) a = parents_[a];
    const bool orphan = parents_[a] == a;
    nodes.push_back(nodes_[i]);
    parents.push_back(orphan ? new_index[i] : new_index[parents_[a]]);
  }
  layBuckets(min_m, max_m);
  nodes_.clear();
  parents_.clear();
  for (std::size_t i = 0; i < nodes.size(); ++i) add(nodes[i], parents[i]);
  parents_ = std::move(parents);  // add() makes node 0 a root; a kept node 0 may have a parent
  return kept;
}

int RrtTree::bucketX(double x_m) const {
  return std::clamp(static_cast<int>(std::floor((x_m - min_m_.x()) / bucket_m_)), 0,
                    buckets_x_ - 1);
}
int RrtTree::bucketY(double y_m) const {
  return std::clamp(static_cast<int>(std::floor((y_m - min_m_.y()) / bucket_m_)), 0,
                    buckets_y_ - 1);
}

void RrtTree::reset(const Vec2& root_m) {
  // Only the used part of the index holds nodes.
  for (int by = used_min_y_; by <= used_max_y_; ++by) {
    for (int bx = used_min_x_; bx <= used_max_x_; ++bx)
      buckets_[static_cast<std::size_t>(by) * buckets_x_ + bx].clear();
  }
  used_min_x_ = used_min_y_ = 0;
  used_max_x_ = used_max_y_ = -1;
  nodes_.clear();
  parents_.clear();
  add(root_m, 0);
}

std::size_t RrtTree::add(const Vec2& p_m, std::size_t parent) {
  const std::size_t index = nodes_.size();
  nodes_.push_back(p_m);
  parents_.push_back(nodes_.size() == 1 ? 0 : parent);
  const int bx = bucketX(p_m.x()), by = bucketY(p_m.y());
  buckets_[static_cast<std::size_t>(by) * buckets_x_ + bx].push_back(
      static_cast<std::uint32_t>(index));
  if (used_max_x_ < used_min_x_) {
    used_min_x_ = used_max_x_ = bx;
    used_min_y_ = used_max_y_ = by;
  } else {
    used_min_x_ = std::min(used_min_x_, bx);
    used_max_x_ = std::max(used_max_x_, bx);
    used_min_y_ = std::min(used_min_y_, by);
    used_max_y_ = std::max(used_max_y_, by);
  }
  return index;
}

std::size_t RrtTree::nearest(const Vec2& p_m) const {
  if (nodes_.empty()) throw InvalidArgument("RrtTree::nearest on an empty tree");
  const int qx = bucketX(p_m.x()), qy = bucketY(p_m.y());
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  auto scan = [&](int bx, int by) {
    if (bx < used_min_x_ || bx > used_max_x_ || by < used_min_y_ || by > used_max_y_) return;
    for (const std::uint32_t i : buckets_[static_cast<std::size_t>(by) * buckets_x_ + bx]) {
      const double d2 = (nodes_[i] - p_m).squaredNorm();
      if (d2 < best_d2 || (d2 == best_d2 && i < best)) {
        best_d2 = d2;
        best = i;
      }
    }
  };
  const int max_ring =
      std::max({qx - used_min_x_, used_max_x_ - qx, qy - used_min_y_, used_max_y_ - qy, 0});
  for (int r = 0; r <= max_ring; ++r) {
    if (r == 0) {
      scan(qx, qy);
    } else {
      for (int bx = qx - r; bx <= qx + r; ++bx) {
        scan(bx, qy - r);
        scan(bx, qy + r);
      }
      for (int by = qy - r + 1; by <= qy + r - 1; ++by) {
        scan(qx - r, by);
        scan(qx + r, by);
      }
    }
    // Every node not yet seen lies outside the square of rings 0..r: at least `clear` away.
    const double left = min_m_.x() + (qx - r) * bucket_m_,
                 right = min_m_.x() + (qx + r + 1) * bucket_m_;
    const double bottom = min_m_.y() + (qy - r) * bucket_m_,
                 top = min_m_.y() + (qy + r + 1) * bucket_m_;
    const double clear =
        std::min({p_m.x() - left, right - p_m.x(), p_m.y() - bottom, top - p_m.y()});
    if (clear > 0.0 && best_d2 <= clear * clear) break;
  }
  return best;
}

Vec2 RrtTree::steer(const Vec2& from_m, const Vec2& toward_m, double eta_m) {
  const Vec2 d = toward_m - from_m;
  const double n = d.norm();
  if (n <= eta_m) return toward_m;
  return from_m + d * (eta_m / n);
}

RrtExtension RrtTree::extend(const OccupancyGrid& grid, const Vec2& sample_m) {
  RrtExtension out;
  out.nearest = nearest(sample_m);
  const Vec2 steered = steer(nodes_[out.nearest], sample_m, eta_m_);
  const EdgeCheck check = checkEdge(grid, nodes_[out.nearest], steered);
  out.status = check.status;
  out.new_m = check.status == EdgeStatus::kFrontier ? check.end_m : steered;
  if (check.status == EdgeStatus::kFree) {
    add(steered, out.nearest);
    out.added = true;
  }
  return out;
}

RrtTree::Sampler uniformBoxSampler(const Vec2& min_m, const Vec2& max_m) {
  return [min_m, max_m](std::mt19937_64& rng) {
    const double u = unitDouble(rng);
    const double v = unitDouble(rng);
    return Vec2(min_m.x() + u * (max_m.x() - min_m.x()), min_m.y() + v * (max_m.y() - min_m.y()));
  };
}

}  // namespace roomscout
