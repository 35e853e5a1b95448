#include "roomscout/slam/detail/scan_matcher.hpp"

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace roomscout::slam::detail {
namespace {

/// A scan point paired with a wall: its distance to the wall's line (normal set) or to the
/// wall point (normal zero).
struct WallPair {
  Vec2 point;  ///< sensor frame
  Vec2 wall;   ///< a point of the wall, submap frame
  Vec2 normal;
};

/// Per pair: the point's distance to its wall's line, in cells, times `scale`.
struct WallCost {
  const std::vector<WallPair>& pairs;
  double scale;

  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    const T c = ceres::cos(pose[2]);
    const T s = ceres::sin(pose[2]);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const WallPair& pair = pairs[i];
      const Vec2& p = pair.point;
      const T x = pose[0] + c * p.x() - s * p.y();
      const T y = pose[1] + s * p.x() + c * p.y();
      residuals[i] =
          scale * ((x - pair.wall.x()) * pair.normal.x() + (y - pair.wall.y()) * pair.normal.y());
    }
    return true;
  }
};

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

/// A wall cell seen from the side the beam `beam` comes from.
bool isWall(const ProbabilityGrid& grid, const WallPoints& walls, int x, int y, const Vec2& beam) {
  return walls.count(x, y) > 0 && grid.at(x, y) > 0.5 && walls.beams(x, y).dot(beam) > 0.0;
}

/// The wall through cell `c`: the line fitted to the wall points round it (weighted by their
/// returns), within a window wide enough for returns with range noise `sd_m` to line up; none
/// (zero normal) where they do not: a corner, a lone wall point.
WallPair wallAt(const ProbabilityGrid& grid, const WallPoints& walls, Cell c, const Vec2& point,
                const Vec2& beam, double sd_m) {
  const double res = walls.geometry().resolution_m();
  const int radius = std::clamp(static_cast<int>(std::ceil(3.0 * sd_m / res)), 3, 8);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double weight = 0.0;
  int cells = 0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (isWall(grid, walls, c.x + dx, c.y + dy, beam)) {
        const double w = walls.count(c.x + dx, c.y + dy);
        sum += w * walls.mean(c.x + dx, c.y + dy);
        weight += w;
        ++cells;
      }
  if (cells < 3) return {point, Vec2::Zero(), Vec2::Zero()};
  const Eigen::Vector2d centroid = sum / weight;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (isWall(grid, walls, c.x + dx, c.y + dy, beam)) {
        const Eigen::Vector2d d = walls.mean(c.x + dx, c.y + dy) - centroid;
        scatter += walls.count(c.x + dx, c.y + dy) * d * d.transpose();
      }
  scatter /= weight;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  const double across = eigen.eigenvalues()(0), along = eigen.eigenvalues()(1);
  // A line: spread along it, and across it no more than a small part of that or than the
  // range noise explains.
  const bool noisy = sd_m > 0.0 && across <= 4.0 * sd_m * sd_m;
  const bool line = along >= (noisy ? 2.0 : 4.0) * across && (across <= 0.15 * along || noisy);
  if (!line) return {point, Vec2::Zero(), Vec2::Zero()};
  return {point, centroid, eigen.eigenvectors().col(0).normalized()};
}

/// Pairs each point (at `pose`) with the nearest wall point within `reach` cells; points with
/// none are left out (ground the submap has not seen has nothing to match).
std::vector<WallPair> pairWithWalls(const ProbabilityGrid& grid, const WallPoints& walls,
                                    const std::vector<Vec2>& points, const Pose2& pose, int reach,
                                    double range_sd_fraction) {
  std::vector<WallPair> pairs;
  pairs.reserve(points.size());
  const GridGeometry& g = walls.geometry();
  for (const Vec2& p : points) {
    const Vec2 q = transformPoint(pose, p);
    const Vec2 beam = q - pose.position();
    const Cell c = g.cellOf(q);
    double best = std::numeric_limits<double>::infinity();
    Cell best_cell{};
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        if (!isWall(grid, walls, c.x + dx, c.y + dy, beam)) continue;
        const double d = (walls.mean(c.x + dx, c.y + dy) - q).squaredNorm();
        if (d < best) {
          best = d;
          best_cell = Cell{c.x + dx, c.y + dy};
        }
      }
    }
    if (!std::isfinite(best)) continue;
    // Only walls that run straight are matched: a lone wall point (seen through sparse grazing
    // beams, the end of what the submap has seen, a corner) would pull the scan along a wall.
    const WallPair pair = wallAt(grid, walls, best_cell, p, beam, range_sd_fraction * p.norm());
    if (!pair.normal.isZero()) pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace

double scoreAt(const ProbabilityGrid& grid, const std::vector<Vec2>& points, const Pose2& pose) {
  if (points.empty()) return 0.0;
  double sum = 0.0;
  for (const Vec2& p : points) sum += grid.atPoint(transformPoint(pose, p));
  return sum / static_cast<double>(points.size());
}

ScanMatch matchScan(const ProbabilityGrid& grid, const WallPoints& walls,
                    const std::vector<Vec2>& points, const Pose2& initial, const Pose2& prediction,
                    double sd_m, double sd_rad, const ScanMatchOptions& options) {
  ScanMatch result;
  result.pose = prediction;
  if (points.empty()) return result;
  const double res = walls.geometry().resolution_m();
  constexpr int kReach = 3;  ///< cells searched round a point for its wall

  // Pair points with walls, solve, pair again from the solution (as ICP does).
  double pose[3] = {initial.x_m, initial.y_m, initial.yaw_rad};
  std::vector<WallPair> pairs;
  for (int round = 0; round < 3; ++round) {
    pairs = pairWithWalls(grid, walls, points, Pose2{pose[0], pose[1], pose[2]}, kReach,
                          options.range_sd_fraction);
    if (pairs.size() < static_cast<std::size_t>(options.min_points_on_walls)) return result;
    ceres::Problem problem;
    const double scale =
        options.occupied_weight / (res * std::sqrt(static_cast<double>(pairs.size())));
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<WallCost, ceres::DYNAMIC, 3>(
                                 new WallCost{pairs, scale}, static_cast<int>(pairs.size())),
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

  // Information of the pairs about the translation: n n^T per line.
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  for (const WallPair& pair : pairs) information += pair.normal * pair.normal.transpose();
  result.points_on_walls = static_cast<int>(pairs.size());
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
