#pragma once
// The cells a ray crosses on a grid, in order (Amanatides and Woo, "A fast voxel traversal
// algorithm", 1987): the simulated laser, the simulated lidar and the oracle tour's visibility
// all walk rays with it.
//
// Positions are in cells (cell (i, j) covers [i, i + 1) x [j, j + 1)) and the direction has unit
// length, so the ray parameter t is the distance travelled, in cells. The walk is unbounded:
// callers stop it at their range or at the grid's edge.

#include <cmath>
#include <limits>

#include "roomscout/core/geometry.hpp"

namespace roomscout {

class GridRay {
 public:
  /// A ray from `origin_cells` along the unit direction (dx, dy); a zero component never steps.
  GridRay(const Vec2& origin_cells, double dx, double dy)
      : x_(static_cast<int>(std::floor(origin_cells.x()))),
        y_(static_cast<int>(std::floor(origin_cells.y()))),
        step_x_(dx > 0 ? 1 : -1),
        step_y_(dy > 0 ? 1 : -1),
        t_delta_x_(dx != 0 ? std::abs(1.0 / dx) : kInf),
        t_delta_y_(dy != 0 ? std::abs(1.0 / dy) : kInf),
        t_max_x_(dx != 0 ? (step_x_ > 0 ? (x_ + 1 - origin_cells.x()) : (origin_cells.x() - x_)) *
                               t_delta_x_
                         : kInf),
        t_max_y_(dy != 0 ? (step_y_ > 0 ? (y_ + 1 - origin_cells.y()) : (origin_cells.y() - y_)) *
                               t_delta_y_
                         : kInf) {}

  /// The current cell (the origin's at first).
  int x() const { return x_; }
  int y() const { return y_; }
  int stepX() const { return step_x_; }
  int stepY() const { return step_y_; }

  /// True when the ray leaves the current cell across a vertical side (its next step is in x).
  bool leavesAlongX() const { return t_max_x_ < t_max_y_; }
  /// The parameter at which the ray leaves the current cell.
  double exitT() const { return leavesAlongX() ? t_max_x_ : t_max_y_; }

  /// Moves into the next cell; returns the parameter at which the ray enters it.
  double step() {
    double t_enter;
    if (t_max_x_ < t_max_y_) {
      t_enter = t_max_x_;
      t_max_x_ += t_delta_x_;
      x_ += step_x_;
    } else {
      t_enter = t_max_y_;
      t_max_y_ += t_delta_y_;
      y_ += step_y_;
    }
    return t_enter;
  }

  /// The steps `jump` took, and the parameter at which the ray left the square.
  struct Jump {
    double t_out;
    int x_steps;
    int y_steps;
  };
  /// Takes at once every step up to and including the first that is the kx-th step in x or the
  /// ky-th in y (kx, ky >= 1): the ray leaves a square of cells known to hold nothing. The
  /// parameters advance by the same additions in the same order, and which step comes first is
  /// decided by the same comparison (an x-step i precedes a y-step j iff X_i < Y_j), so the ray
  /// ends in the same cell with the same parameters as after as many step() calls.
  Jump jump(int kx, int ky) {
    double x_last = t_max_x_, y_last = t_max_y_;  // parameters of the kx-th x-step, ky-th y-step
    for (int i = 1; i < kx; ++i) x_last += t_delta_x_;
    for (int j = 1; j < ky; ++j) y_last += t_delta_y_;
    Jump j{0.0, 0, 0};
    if (x_last < y_last) {  // leaves along x; the y-steps before are those with Y_j <= x_last
      while (t_max_y_ <= x_last) {
        t_max_y_ += t_delta_y_;
        ++j.y_steps;
      }
      j.t_out = x_last;
      j.x_steps = kx;
      t_max_x_ = x_last + t_delta_x_;
    } else {  // leaves along y; the x-steps before are those with X_i < y_last
      while (t_max_x_ < y_last) {
        t_max_x_ += t_delta_x_;
        ++j.x_steps;
      }
      j.t_out = y_last;
      j.y_steps = ky;
      t_max_y_ = y_last + t_delta_y_;
    }
    x_ += j.x_steps * step_x_;
    y_ += j.y_steps * step_y_;
    return j;
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  int x_, y_;
  int step_x_, step_y_;
  double t_delta_x_, t_delta_y_;
  double t_max_x_, t_max_y_;
};

}  // namespace roomscout
