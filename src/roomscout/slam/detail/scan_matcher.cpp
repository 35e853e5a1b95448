#include "roomscout/slam/detail/scan_matcher.hpp"

#include <ceres/ceres.h>
#include <ceres/cubic_interpolation.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/slam/detail/pose_ops.hpp"

namespace roomscout::slam::detail {
namespace {

using Interpolator = ceres::BiCubicInterpolator<ProbabilityGrid>;

/// Residuals per point: how far the point lies outside the wall cell it was paired with, times
/// `scale` / cell size. A wall's surface lies somewhere in the cell the map marked, so every
/// position inside is equally right: the cost is flat there and the prior decides, with no
/// pull towards the cell's centre. Where the cell's wall runs straight, only the distance
/// across the wall counts (point to line): a point between two sparse hits of one wall, or
/// past the end of the stretch the submap has seen, is not pulled along the wall.
struct WallCellCost {
  struct Pair {
    Vec2 point;   ///< sensor frame
    Vec2 centre;  ///< of the paired cell, grid frame
    Vec2 normal;  ///< across the wall (unit), or zero where the wall's direction is unclear
  };
  const std::vector<Pair>& pairs;
  double half_cell;
  double scale;

  template <typename T>
  static T outside(const T& d, double half) {
    if (d > half) return d - half;
    if (d < -half) return d + half;
    return T(0.0);
  }

  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    const T c = ceres::cos(pose[2]);
    const T s = ceres::sin(pose[2]);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const Pair& pair = pairs[i];
      const Vec2& p = pair.point;
      const T dx = pose[0] + c * p.x() - s * p.y() - pair.centre.x();
      const T dy = pose[1] + s * p.x() + c * p.y() - pair.centre.y();
      if (pair.normal.isZero()) {
        residuals[2 * i] = scale * outside(dx, half_cell);
        residuals[2 * i + 1] = scale * outside(dy, half_cell);
      } else {
        // The cell's extent across the wall: half a cell projected on the normal.
        const double half = half_cell * (std::abs(pair.normal.x()) + std::abs(pair.normal.y()));
        residuals[2 * i] = scale * outside(dx * pair.normal.x() + dy * pair.normal.y(), half);
        residuals[2 * i + 1] = T(0.0);
      }
    }
    return true;
  }
};

/// The direction across the wall through cell `c`, from the wall cells round it (their
/// principal axis); zero where they do not line up (a corner, a lone cell).
Vec2 wallNormal(const ProbabilityGrid& grid, Cell c) {
  constexpr int kRadius = 2;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> cells;
  for (int dy = -kRadius; dy <= kRadius; ++dy)
    for (int dx = -kRadius; dx <= kRadius; ++dx)
      if (grid.at(c.x + dx, c.y + dy) > 0.5) {
        cells.emplace_back(dx, dy);
        mean += cells.back();
      }
  if (cells.size() < 3) return Vec2::Zero();
  mean /= static_cast<double>(cells.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& v : cells) scatter += (v - mean) * (v - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  // A line: the spread across it is small against the spread along it.
  if (eigen.eigenvalues()(0) > 0.1 * eigen.eigenvalues()(1)) return Vec2::Zero();
  return eigen.eigenvectors().col(0).normalized();
}

/// Pairs each point (at `pose`) with the nearest cell more likely occupied than not within
/// `reach` cells; points with none are left out.
std::vector<WallCellCost::Pair> pairWithWalls(const ProbabilityGrid& grid,
                                              const std::vector<Vec2>& points, const Pose2& pose,
                                              int reach) {
  std::vector<WallCellCost::Pair> pairs;
  pairs.reserve(points.size());
  const GridGeometry& g = grid.geometry();
  const double half = 0.5 * g.resolution_m();
  for (const Vec2& p : points) {
    const Vec2 q = apply(pose, p);
    const Cell c = g.cellOf(q);
    double best = std::numeric_limits<double>::infinity();
    Cell best_cell{};
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        if (grid.at(c.x + dx, c.y + dy) <= 0.5) continue;
        const Vec2 centre = g.centerOf(Cell{c.x + dx, c.y + dy});
        const double ox = std::max(0.0, std::abs(q.x() - centre.x()) - half);
        const double oy = std::max(0.0, std::abs(q.y() - centre.y()) - half);
        const double d = ox * ox + oy * oy;
        if (d < best) {
          best = d;
          best_cell = Cell{c.x + dx, c.y + dy};
        }
      }
    }
    if (!std::isfinite(best)) continue;
    const Vec2 normal = wallNormal(grid, best_cell);
    // Where the wall's direction is unclear (its end, a corner), only a point close to the
    // cell is paired: one further off is more likely on a stretch the submap has not seen.
    if (normal.isZero() && best > half * half) continue;
    pairs.push_back({p, g.centerOf(best_cell), normal});
  }
  return pairs;
}

/// The pose staying near the prediction: (pose - prediction) / sd per axis.
struct PriorCost {
  Pose2 prediction;
  double inv_sd_m, inv_sd_rad;
  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    r[0] = (pose[0] - prediction.x_m) * inv_sd_m;
    r[1] = (pose[1] - prediction.y_m) * inv_sd_m;
    r[2] = (pose[2] - prediction.yaw_rad) * inv_sd_rad;
    return true;
  }
};

}  // namespace

double scoreAt(const ProbabilityGrid& grid, const std::vector<Vec2>& points, const Pose2& pose) {
  if (points.empty()) return 0.0;
  double sum = 0.0;
  for (const Vec2& p : points) sum += grid.atPoint(apply(pose, p));
  return sum / static_cast<double>(points.size());
}

ScanMatch matchScan(const ProbabilityGrid& grid, const std::vector<Vec2>& points,
                    const Pose2& prediction, double sd_m, double sd_rad,
                    const ScanMatchOptions& options) {
  return matchScan(grid, points, prediction, prediction, sd_m, sd_rad, options);
}

ScanMatch matchScan(const ProbabilityGrid& grid, const std::vector<Vec2>& points,
                    const Pose2& initial, const Pose2& prediction, double sd_m, double sd_rad,
                    const ScanMatchOptions& options) {
  ScanMatch result;
  result.pose = prediction;
  if (points.empty()) return result;
  const Interpolator interpolator(grid);
  const double res = grid.geometry().resolution_m();
  constexpr int kReach = 3;  ///< cells searched round a point for its wall cell

  // Pair points with wall cells, solve, pair again from the solution (as ICP does).
  double pose[3] = {initial.x_m, initial.y_m, initial.yaw_rad};
  for (int round = 0; round < 3; ++round) {
    const std::vector<WallCellCost::Pair> pairs =
        pairWithWalls(grid, points, Pose2{pose[0], pose[1], pose[2]}, kReach);
    if (pairs.size() < static_cast<std::size_t>(options.min_points_on_walls)) return result;
    ceres::Problem problem;
    const double scale =
        options.occupied_weight / (res * std::sqrt(static_cast<double>(pairs.size())));
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<WallCellCost, ceres::DYNAMIC, 3>(
            new WallCellCost{pairs, 0.5 * res, scale}, static_cast<int>(2 * pairs.size())),
        nullptr, pose);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorCost, 3, 3>(
                                 new PriorCost{prediction, 1.0 / sd_m, 1.0 / sd_rad}),
                             nullptr, pose);
    ceres::Solver::Options solver_options;
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.max_num_iterations = options.max_iterations;
    solver_options.num_threads = 1;
    solver_options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
  }
  Pose2 refined{pose[0], pose[1], wrapAngle(pose[2])};
  if (!isFinite(refined)) return result;

  // Information of the point term about the translation, at the refined pose: the sum of
  // g g^T over the points' probability gradients g.
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  int on_walls = 0;
  const Vec2 origin = grid.geometry().origin_m();
  for (const Vec2& p : points) {
    const Vec2 q = apply(refined, p);
    double value, d_row, d_col;
    interpolator.Evaluate((q.y() - origin.y()) / res - 0.5, (q.x() - origin.x()) / res - 0.5,
                          &value, &d_row, &d_col);
    const Eigen::Vector2d g(d_col / res, d_row / res);
    information += g * g.transpose();
    if (grid.atPoint(q) > 0.5) ++on_walls;
  }
  result.points_on_walls = on_walls;
  if (on_walls < options.min_points_on_walls) return result;

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(information);
  const Eigen::Vector2d lambda = eigen.eigenvalues();  // ascending
  if (!(lambda(1) > 0.0)) return result;
  if (lambda(0) < options.min_direction_ratio * lambda(1)) {
    // Walls along one direction only: keep the prediction along them.
    const Eigen::Vector2d weak = eigen.eigenvectors().col(0);
    const Eigen::Vector2d shift(refined.x_m - prediction.x_m, refined.y_m - prediction.y_m);
    const Eigen::Vector2d kept = shift - weak * weak.dot(shift);
    refined.x_m = prediction.x_m + kept.x();
    refined.y_m = prediction.y_m + kept.y();
    result.degenerate = true;
  }
  result.pose = refined;
  result.accepted = true;
  result.score = scoreAt(grid, points, refined);
  return result;
}

}  // namespace roomscout::slam::detail
