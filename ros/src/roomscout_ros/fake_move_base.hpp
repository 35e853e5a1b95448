#pragma once
// A stand-in for move_base over the simulator: the move_base action server, planning with the
// library's A* over its costmap and driving with its path follower. Each plan is published on
// move_base/NavfnROS/plan, as move_base's default global planner publishes it. It replans when
// newly mapped obstacles block the path, and when the simulation reports the robot blocked it backs
// off once, then replans, and aborts the goal if the robot is blocked again.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/server/action_server.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/planning/costmap.hpp"
#include "roomscout/planning/path_follower.hpp"

namespace roomscout::ros1 {

/// Goals within `radius_m` of `center_m` (map frame) are aborted at once (fault injection).
struct AbortZone {
  Vec2 center_m = Vec2::Zero();
  double radius_m = 0.0;
};

/// What the fake move_base is made of.
struct FakeMoveBaseOptions {
  CostmapOptions costmap;
  AStarOptions planner;
  PathFollowerOptions follower;
  double sensor_range_m = 3.5;   ///< how far from the robot a new scan can block the path [m]
  double recovery_time_s = 1.5;  ///< how long it backs off when the robot is blocked [s]
  std::string map_frame = "map";
  std::optional<AbortZone> abort_zone;
};

/// Not thread-safe: the action server's callbacks must run on the thread that steps it (the
/// global callback queue, served by the node's loop).
class FakeMoveBase {
 public:
  /// Goal counts, for a status display.
  struct Counts {
    int received = 0, succeeded = 0, aborted = 0, canceled = 0;
  };
  /// Called when a goal starts being driven to, and when a goal ends.
  struct Hooks {
    std::function<void()> goal_started, goal_ended;
  };

  FakeMoveBase(ros::NodeHandle& nh, const FakeMoveBaseOptions& options, Hooks hooks);

  /// Starts serving goals.
  void start() { server_.start(); }
  /// The velocity for the next step of a robot believed at `robot`.
  VelocityCommand command(const Pose2& robot);
  /// On every step, at simulated time `t_s`: the map (cells `changed` since the last call) and
  /// the robot's believed pose; ends a back-off that is over, replans a path that newly mapped
  /// obstacles block, or declares the goal reached. With a scan taken now (`scan_stamp`), the
  /// action's feedback goes out.
  void monitor(const OccupancyGrid& grid, const CellRect& changed, const Pose2& robot, double t_s,
               const std::optional<ros::Time>& scan_stamp);
  /// The simulation reports the robot blocked at `t_s`: back off once (replanning afterwards),
  /// abort the goal the second time.
  void onBlocked(double t_s);
  /// Aborts the active goal, if any (time limit, shutdown).
  void abort(const std::string& why);
  /// Goals are refused with `why` from now on.
  void refuseGoals(const std::string& why) { refusing_ = why; }

  bool active() const { return goal_.has_value(); }
  const Counts& counts() const { return counts_; }

 private:
  using Server = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
  using GoalHandle = Server::GoalHandle;
  enum class GoalEnd { kSucceeded, kAborted, kCanceled };

  /// The goal being driven to.
  struct ActiveGoal {
    GoalHandle handle;
    Vec2 target_m = Vec2::Zero();
    bool recovered = false;                  ///< the one back-off of this goal was spent
    std::optional<double> back_off_until_s;  ///< backing off until then, then replanning
  };
  /// Why a goal is aborted before planning (frame, values, fault zone), or nothing.
  struct Refusal {
    std::string text;
    bool logged = false;  ///< warned about already
  };

  void onGoal(GoalHandle handle);
  void onCancel(GoalHandle handle);
  std::optional<Refusal> refusal(const move_base_msgs::MoveBaseGoal& goal) const;
  /// Plans from the robot to the active goal on the last map; false (with `why`) if none.
  bool replan(std::string& why);
  bool pathBlocked() const;
  void publishFeedback(const Pose2& robot, const ros::Time& stamp);
  /// Ends the active goal; `log` = false when the caller has said why already.
  void endGoal(GoalEnd end, const std::string& text, bool log = true);

  FakeMoveBaseOptions options_;
  Hooks hooks_;
  Server server_;
  ros::Publisher plan_pub_;
  PathFollower follower_;
  Costmap costmap_;
  AStarPlanner planner_;
  std::vector<Cell> lethal_disc_;
  double lethal_disc_resolution_m_ = 0.0;
  const OccupancyGrid* grid_ = nullptr;  ///< the map of the last monitor() call
  Pose2 robot_;                          ///< the robot at the last monitor() or command() call
  CellRect costmap_stale_;               ///< cells changed since the costmap's last update
  bool costmap_built_ = false;
  std::optional<ActiveGoal> goal_;
  std::optional<std::string> refusing_;
  Counts counts_;
};

}  // namespace roomscout::ros1
