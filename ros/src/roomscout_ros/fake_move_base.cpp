#include "roomscout_ros/fake_move_base.hpp"

#include <cmath>

#include "roomscout/planning/path_blocking.hpp"
#include "roomscout_ros/grid_conversions.hpp"

namespace roomscout::ros1 {
namespace {

/// Tolerance of the back-off's end against the accumulated time [s].
constexpr double kScheduleSlack_s = 1e-9;

const char* planStatusText(PlanStatus status) {
  switch (status) {
    case PlanStatus::kFound:
      return "path found";
    case PlanStatus::kStartBlocked:
      return "the robot's cell is blocked";
    case PlanStatus::kGoalBlocked:
      return "the goal is blocked";
    case PlanStatus::kNoPath:
      return "no path";
  }
  return "no path";
}

/// A frame name without the leading slash tf1 allowed.
std::string bareFrame(const std::string& frame) {
  return !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
}

}  // namespace

FakeMoveBase::FakeMoveBase(ros::NodeHandle& nh, const FakeMoveBaseOptions& options, Hooks hooks)
    : options_(options),
      hooks_(std::move(hooks)),
      server_(
          nh, "move_base", [this](GoalHandle h) { onGoal(h); },
          [this](GoalHandle h) { onCancel(h); }, false),
      plan_pub_(nh.advertise<nav_msgs::Path>("move_base/NavfnROS/plan", 1)),
      follower_(options_.follower),
      costmap_(options_.costmap),
      planner_(options_.planner) {}

VelocityCommand FakeMoveBase::command(const Pose2& robot) {
  robot_ = robot;
  if (!goal_) return {};
  if (goal_->back_off_until_s) return backOffCommand();
  return follower_.compute(robot);
}

void FakeMoveBase::monitor(const OccupancyGrid& grid, const CellRect& changed, const Pose2& robot,
                           double t_s, const std::optional<ros::Time>& scan_stamp) {
  grid_ = &grid;
  robot_ = robot;
  costmap_stale_.unite(changed);
  if (lethal_disc_resolution_m_ != grid.geometry().resolution_m()) {
    lethal_disc_ = discOffsets(options_.costmap.lethalRadius_m() / grid.geometry().resolution_m());
    lethal_disc_resolution_m_ = grid.geometry().resolution_m();
  }
  if (!goal_) return;
  std::string why;
  if (goal_->back_off_until_s) {
    if (t_s < *goal_->back_off_until_s - kScheduleSlack_s) return;
    goal_->back_off_until_s.reset();
    if (!replan(why)) endGoal(GoalEnd::kAborted, "blocked, and after backing off " + why);
    return;
  }
  if (!changed.empty() && pathBlocked() && !replan(why)) {
    endGoal(GoalEnd::kAborted, "path blocked by a newly seen obstacle, " + why);
    return;
  }
  if (follower_.reached(robot)) {
    endGoal(GoalEnd::kSucceeded, "goal reached");
    return;
  }
  if (scan_stamp) publishFeedback(robot, *scan_stamp);
}

void FakeMoveBase::onBlocked(double t_s) {
  if (!goal_) return;
  if (goal_->recovered) {
    endGoal(GoalEnd::kAborted, "robot blocked again after a back-off");
    return;
  }
  // Back off for a while, then plan afresh from there.
  goal_->recovered = true;
  goal_->back_off_until_s = t_s + options_.recovery_time_s;
  follower_.clear();
  ROS_INFO("roomscout_sim_node: robot blocked; backing off for %.1f s", options_.recovery_time_s);
}

void FakeMoveBase::abort(const std::string& why) {
  if (goal_) endGoal(GoalEnd::kAborted, why);
}

void FakeMoveBase::onGoal(GoalHandle handle) {
  ++counts_.received;
  handle.setAccepted();
  if (goal_) {
    // A new goal preempts the old one, as move_base does.
    goal_->handle.setCanceled(move_base_msgs::MoveBaseResult(), "preempted by a new goal");
    ++counts_.canceled;
    goal_.reset();
    follower_.clear();
  }
  const move_base_msgs::MoveBaseGoal& goal = *handle.getGoal();
  const geometry_msgs::Point& p = goal.target_pose.pose.position;
  goal_.emplace();
  goal_->handle = handle;
  goal_->target_m = Vec2(p.x, p.y);
  if (const std::optional<Refusal> r = refusal(goal)) {
    endGoal(GoalEnd::kAborted, r->text, !r->logged);
    return;
  }
  std::string why;
  if (!replan(why)) {
    endGoal(GoalEnd::kAborted, why);
    return;
  }
  if (hooks_.goal_started) hooks_.goal_started();
  ROS_DEBUG("roomscout_sim_node: driving to (%.2f, %.2f)", p.x, p.y);
}

void FakeMoveBase::onCancel(GoalHandle handle) {
  if (goal_ && goal_->handle == handle) endGoal(GoalEnd::kCanceled, "canceled");
}

std::optional<FakeMoveBase::Refusal> FakeMoveBase::refusal(
    const move_base_msgs::MoveBaseGoal& goal) const {
  if (refusing_) return Refusal{*refusing_};
  if (grid_ == nullptr) return Refusal{"no map yet"};
  const std::string frame = bareFrame(goal.target_pose.header.frame_id);
  if (!frame.empty() && frame != options_.map_frame) {
    return Refusal{"goal frame \"" + goal.target_pose.header.frame_id +
                   "\" is not the map frame \"" + options_.map_frame + "\""};
  }
  const geometry_msgs::Point& p = goal.target_pose.pose.position;
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return Refusal{"goal position is not finite"};
  const std::optional<AbortZone>& zone = options_.abort_zone;
  if (zone && (Vec2(p.x, p.y) - zone->center_m).norm() <= zone->radius_m) {
    ROS_WARN(
        "roomscout_sim_node: aborting the goal (%.2f, %.2f): within %.2f m of (%.2f, %.2f) "
        "(~abort_goals_near)",
        p.x, p.y, zone->radius_m, zone->center_m.x(), zone->center_m.y());
    return Refusal{"goal inside the ~abort_goals_near zone (fault injection)", true};
  }
  return std::nullopt;
}

bool FakeMoveBase::replan(std::string& why) {
  if (!costmap_built_ || !costmap_stale_.empty()) {
    costmap_.update(*grid_, costmap_stale_);  // the first call builds it from the whole grid
    costmap_built_ = true;
    costmap_stale_ = CellRect{};
  }
  const PlanResult plan = planner_.plan(costmap_, robot_.position(), goal_->target_m);
  if (plan.status != PlanStatus::kFound) {
    why = std::string("no path to the goal: ") + planStatusText(plan.status);
    return false;
  }
  follower_.setPath(plan.path);
  nav_msgs::Path msg;
  msg.header.frame_id = options_.map_frame;
  msg.header.stamp = ros::Time::now();
  for (const Vec2& w : plan.path.waypoints_m) {
    geometry_msgs::PoseStamped pose;
    pose.header = msg.header;
    pose.pose.position.x = w.x();
    pose.pose.position.y = w.y();
    pose.pose.orientation.w = 1.0;
    msg.poses.push_back(pose);
  }
  plan_pub_.publish(msg);
  return true;
}

bool FakeMoveBase::pathBlocked() const {
  if (!follower_.hasPath()) return false;
  const double horizon_m =
      blockingHorizon_m(options_.sensor_range_m, options_.costmap.lethalRadius_m());
  return pathBlockedAhead(*grid_, follower_.path().waypoints_m, follower_.progressIndex(),
                          robot_.position(), horizon_m, lethal_disc_);
}

void FakeMoveBase::publishFeedback(const Pose2& robot, const ros::Time& stamp) {
  move_base_msgs::MoveBaseFeedback feedback;
  feedback.base_position.header.stamp = stamp;
  feedback.base_position.header.frame_id = options_.map_frame;
  feedback.base_position.pose = toPoseMsg(robot);
  goal_->handle.publishFeedback(feedback);
}

void FakeMoveBase::endGoal(GoalEnd end, const std::string& text, bool log) {
  const move_base_msgs::MoveBaseResult result;
  switch (end) {
    case GoalEnd::kSucceeded:
      goal_->handle.setSucceeded(result, text);
      ++counts_.succeeded;
      ROS_DEBUG("roomscout_sim_node: goal reached");
      break;
    case GoalEnd::kAborted:
      goal_->handle.setAborted(result, text);
      ++counts_.aborted;
      if (log)
        ROS_INFO("roomscout_sim_node: goal (%.2f, %.2f) aborted: %s", goal_->target_m.x(),
                 goal_->target_m.y(), text.c_str());
      break;
    case GoalEnd::kCanceled:
      goal_->handle.setCanceled(result, text);
      ++counts_.canceled;
      break;
  }
  goal_.reset();
  follower_.clear();
  if (hooks_.goal_ended) hooks_.goal_ended();
}

}  // namespace roomscout::ros1
