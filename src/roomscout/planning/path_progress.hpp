#pragma once
// How far along a path the robot has come: its projection on the path, which only moves
// forward. The follower steers from it; the explorer's no-progress watchdog measures the
// path left from it.

#include <cstddef>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/planning/path.hpp"

namespace roomscout {

class PathProgress {
 public:
  /// @param window_m only segments starting within this arc length past the current progress
  ///        are candidates for the robot's projection [m]
  explicit PathProgress(double window_m = 0.7) : window_m_(window_m) {}

  /// Starts over on `path` (progress at its first waypoint).
  void reset(const Path& path);
  /// Moves the progress forward to the robot's projection on the path (never backwards).
  void update(const Vec2& robot_m);

  const Path& path() const { return path_; }
  bool empty() const { return path_.waypoints_m.empty(); }
  /// Index of the waypoint nearest the robot's projection, never decreasing.
  std::size_t index() const { return index_; }
  /// Segment (from waypoint segment()) the robot's projection lies on.
  std::size_t segment() const { return segment_; }
  /// Arc length of the robot's projection from the first waypoint [m].
  double progress_m() const { return progress_m_; }
  /// Arc length of each waypoint from the first [m].
  const std::vector<double>& arcLength_m() const { return arc_length_m_; }
  /// Distance from the robot to the waypoint at index(), plus the path beyond it [m].
  double remaining_m(const Vec2& robot_m) const;

 private:
  double window_m_;
  Path path_;
  std::vector<double> arc_length_m_;
  std::size_t index_ = 0;
  std::size_t segment_ = 0;
  double progress_m_ = 0.0;
};

}  // namespace roomscout
