#include "roomscout/planning/path_progress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomscout {

void PathProgress::reset(const Path& path) {
  path_ = path;
  arc_length_m_.resize(path_.waypoints_m.size());
  double s_m = 0.0;
  for (std::size_t i = 0; i < path_.waypoints_m.size(); ++i) {
    if (i > 0) s_m += (path_.waypoints_m[i] - path_.waypoints_m[i - 1]).norm();
    arc_length_m_[i] = s_m;
  }
  index_ = 0;
  segment_ = 0;
  progress_m_ = 0.0;
}

void PathProgress::update(const Vec2& robot_m) {
  const std::vector<Vec2>& w = path_.waypoints_m;
  if (w.size() < 2) return;
  // Only segments starting within the window past the current progress are candidates, so
  // that a later part of the path passing close by (a U-turn) cannot pull the progress ahead,
  // while a hairpin the robot turned back on before its tip is still picked up.
  const double window_end_m = progress_m_ + window_m_;
  double best_distance_m = std::numeric_limits<double>::infinity();
  std::size_t best_segment = segment_;
  double best_t = 0.0;
  for (std::size_t i = segment_; i + 1 < w.size() && arc_length_m_[i] <= window_end_m; ++i) {
    const Vec2 d = w[i + 1] - w[i];
    const double length2 = d.squaredNorm();
    if (!(length2 > 0.0)) continue;
    // On the current segment only the part beyond the progress point counts; otherwise a
    // robot turning back at a hairpin would stay matched to the leg it came along.
    const double t_min =
        i == segment_ ? std::clamp((progress_m_ - arc_length_m_[i]) / std::sqrt(length2), 0.0, 1.0)
                      : 0.0;
    const double t = std::clamp((robot_m - w[i]).dot(d) / length2, t_min, 1.0);
    const double distance_m = (robot_m - (w[i] + t * d)).norm();
    if (distance_m < best_distance_m) {
      best_distance_m = distance_m;
      best_segment = i;
      best_t = t;
    }
  }
  segment_ = best_segment;
  const double s_m =
      arc_length_m_[segment_] + best_t * (arc_length_m_[segment_ + 1] - arc_length_m_[segment_]);
  progress_m_ = std::max(progress_m_, s_m);
  index_ = std::max(index_, best_t < 0.5 ? segment_ : segment_ + 1);
}

double PathProgress::remaining_m(const Vec2& robot_m) const {
  const std::vector<Vec2>& w = path_.waypoints_m;
  if (w.empty()) return 0.0;
  const std::size_t from = std::min(index_, w.size() - 1);
  double length = (w[from] - robot_m).norm();
  for (std::size_t i = from + 1; i < w.size(); ++i) length += (w[i] - w[i - 1]).norm();
  return length;
}

}  // namespace roomscout
