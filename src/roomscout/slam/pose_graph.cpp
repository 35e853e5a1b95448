#include "roomscout/slam/pose_graph.hpp"

#include <ceres/ceres.h>

#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout::slam {
namespace {

template <typename T>
T wrap(const T& a) {
  // atan2(sin, cos) keeps derivatives smooth through the wrap.
  return ceres::atan2(ceres::sin(a), ceres::cos(a));
}

/// (inverse(from) * to - measured) / sd, the angle wrapped.
struct RelativePoseCost {
  Pose2 measured;
  double inv_sd_m, inv_sd_rad;
  template <typename T>
  bool operator()(const T* const a, const T* const b, T* r) const {
    const T c = ceres::cos(a[2]), s = ceres::sin(a[2]);
    const T dx = b[0] - a[0], dy = b[1] - a[1];
    const T x = c * dx + s * dy;
    const T y = -s * dx + c * dy;
    r[0] = (x - measured.x_m) * inv_sd_m;
    r[1] = (y - measured.y_m) * inv_sd_m;
    r[2] = wrap(b[2] - a[2] - measured.yaw_rad) * inv_sd_rad;
    return true;
  }
};

}  // namespace

int PoseGraph::addPose(const Pose2& initial) {
  poses_.push_back(initial);
  fixed_.push_back(false);
  return static_cast<int>(poses_.size()) - 1;
}

void PoseGraph::addConstraint(const PoseGraphConstraint& c) {
  const int n = static_cast<int>(poses_.size());
  if (c.from < 0 || c.from >= n || c.to < 0 || c.to >= n || c.from == c.to) {
    throw InvalidArgument("pose graph: a constraint joins unknown or identical poses");
  }
  if (!isFinite(c.measured)) {
    throw InvalidArgument("pose graph: a constraint's measurement is not finite");
  }
  if (!(c.sd_m > 0.0 && c.sd_rad > 0.0 && std::isfinite(c.sd_m) && std::isfinite(c.sd_rad))) {
    throw InvalidArgument("pose graph: a constraint's standard deviations must be > 0");
  }
  constraints_.push_back(c);
}

void PoseGraph::fix(int id) { fixed_.at(static_cast<std::size_t>(id)) = true; }

bool PoseGraph::optimise() {
  if (constraints_.empty()) return true;
  std::vector<double> values(3 * poses_.size());
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    values[3 * i] = poses_[i].x_m;
    values[3 * i + 1] = poses_[i].y_m;
    values[3 * i + 2] = poses_[i].yaw_rad;
  }
  ceres::Problem problem;
  for (const PoseGraphConstraint& c : constraints_) {
    ceres::LossFunction* loss = c.robust ? new ceres::HuberLoss(options_.huber_scale) : nullptr;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RelativePoseCost, 3, 3, 3>(
                                 new RelativePoseCost{c.measured, 1.0 / c.sd_m, 1.0 / c.sd_rad}),
                             loss, &values[3 * static_cast<std::size_t>(c.from)],
                             &values[3 * static_cast<std::size_t>(c.to)]);
  }
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    if (fixed_[i] && problem.HasParameterBlock(&values[3 * i])) {
      problem.SetParameterBlockConstant(&values[3 * i]);
    }
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = options_.max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return false;
  std::vector<Pose2> solved(poses_.size());
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    solved[i] = {values[3 * i], values[3 * i + 1], wrapAngle(values[3 * i + 2])};
    if (!isFinite(solved[i])) return false;
  }
  poses_ = std::move(solved);
  return true;
}

}  // namespace roomscout::slam
