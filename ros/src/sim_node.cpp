// roomscout_sim_node: the project's simulator as a ROS 1 node. It stands in for the robot, its
// SLAM and move_base, so that an explorer node runs over ROS on a laptop without Gazebo.
//
// One thread runs the episode loop of sim/episode.cpp with ROS in place of the in-process
// Explorer: each step publishes /clock, tf (map -> odom identity, odom -> base the true pose)
// and odom; at the laser's rate a simulated scan is mapped into the full-world grid and
// published; the map is published as a SLAM package grows it; the exploration rate against
// ground truth is published on ~status. Goals arrive through a move_base action server that
// plans with the library's A* over its costmap and drives with its path follower.
//
// Lockstep (~goal_wait_s): while no goal is active, simulated time is held for a while, so
// that an explorer's thinking costs no simulated time however fast the clock runs. With
// ~sync_topic, the clock also waits after each step until the explorer says it caught up
// with it (roomscout_explore_node's ~cycle), as a simulator in synchronous mode does. The node
// itself runs on wall time whatever /use_sim_time says: it is the clock.
//
// Stamps are the simulated time plus kClockOffset_s (ROS reads a zero stamp as "latest" or
// "no clock yet"); ~status reports the simulated time itself, as runEpisode does.

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <actionlib/server/action_server.h>
#include <geometry_msgs/TransformStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <std_msgs/String.h>
#include <std_msgs/Time.h>
#include <tf2_msgs/TFMessage.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/planning/costmap.hpp"
#include "roomscout/planning/detail/path_blocking.hpp"
#include "roomscout/planning/path_follower.hpp"
#include "roomscout/sim/column_world.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/lidar_simulator.hpp"
#include "roomscout/sim/robot.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"
#include "roomscout_ros/grid_conversions.hpp"
#include "roomscout_ros/node_params.hpp"

namespace roomscout::ros1 {
namespace {

/// Added to the simulated time for every stamp and /clock, so that no stamp is zero [s].
constexpr double kClockOffset_s = 1e-3;
/// Speed of the back-off after the robot was blocked, as the episode's recovery [m/s].
constexpr double kBackOffSpeed_mps = -0.1;
/// Tolerance of the schedules (scan, lidar, metrics, map) against the accumulated time [s].
constexpr double kScheduleSlack_s = 1e-9;
/// Falling this far behind the real-time factor's schedule restarts the schedule rather than
/// catching up with a burst of steps [wall s].
constexpr double kMaxPacingLag_s = 0.5;
/// How long one wait for callbacks lasts while simulated time is held [wall s].
constexpr double kHoldPoll_s = 0.002;

/// Set by SIGINT/SIGTERM: the loop aborts the active goal and leaves.
std::atomic<bool> g_stop_requested{false};

void requestStop(int) { g_stop_requested = true; }

/// Goals within `radius_m` of `center_m` (map frame) are aborted at once (fault injection).
struct AbortZone {
  Vec2 center_m = Vec2::Zero();
  double radius_m = 0.0;
};

/// The node's private parameters.
struct NodeParameters {
  std::string world = "small_house";
  std::string room_labels;
  std::string config;
  std::uint64_t seed = 1;
  double real_time_factor = 0.0;  ///< 0 = as fast as possible
  double map_period_s = 0.0;      ///< simulated; 0 = every scan
  double goal_wait_s = 2.0;       ///< wall; 0 = no lockstep
  std::string sync_topic;         ///< std_msgs/Time up to which an explorer caught up; "" = off
  double sync_timeout_s = 1.0;    ///< wall: longest wait for it per step
  bool points = false;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::optional<AbortZone> abort_zone;
};

/// A number as a person writes it (no trailing zeros).
std::string formatNumber(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

double nonNegativeParam(const ros::NodeHandle& pnh, const std::string& name, double fallback) {
  const double value = typedParam(pnh, name, fallback);
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw OptionError("~" + name + " must be a finite number >= 0, not " + formatNumber(value));
  }
  return value;
}

/// Numbers of a list written as text, "[1.0, 2, 0.5]" (a launch file's <param value=...>).
std::vector<double> parseNumberList(std::string text) {
  for (char& c : text) {
    if (c == '[' || c == ']' || c == ',') c = ' ';
  }
  std::istringstream in(text);
  std::vector<double> numbers;
  double v = 0.0;
  while (in >> v) numbers.push_back(v);
  if (!in.eof()) throw OptionError("~abort_goals_near must be a list of numbers [x, y, radius]");
  return numbers;
}

/// ~abort_goals_near as [x, y, radius]; an empty list or no parameter turns it off.
std::optional<AbortZone> readAbortZone(const ros::NodeHandle& pnh) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam("abort_goals_near", value)) return std::nullopt;
  std::vector<double> numbers;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeArray) {
    for (int i = 0; i < value.size(); ++i) {
      XmlRpc::XmlRpcValue& v = value[i];
      if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
        numbers.push_back(static_cast<int>(v));
      } else if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
        numbers.push_back(static_cast<double>(v));
      } else {
        throw OptionError("~abort_goals_near must be a list of numbers [x, y, radius]");
      }
    }
  } else if (value.getType() == XmlRpc::XmlRpcValue::TypeString) {
    numbers = parseNumberList(static_cast<std::string>(value));
  } else {
    throw OptionError("~abort_goals_near must be a list of numbers [x, y, radius]");
  }
  if (numbers.empty()) return std::nullopt;
  if (numbers.size() != 3) {
    throw OptionError("~abort_goals_near must be [x, y, radius] (3 numbers), not " +
                      std::to_string(numbers.size()) + " numbers");
  }
  for (double n : numbers) {
    if (!std::isfinite(n)) throw OptionError("~abort_goals_near: every number must be finite");
  }
  if (numbers[2] < 0.0) throw OptionError("~abort_goals_near: the radius must be >= 0");
  return AbortZone{Vec2(numbers[0], numbers[1]), numbers[2]};
}

std::string frameParam(const ros::NodeHandle& pnh, const std::string& name,
                       const std::string& fallback) {
  const std::string frame = typedParam(pnh, name, fallback);
  if (frame.empty()) throw OptionError("~" + name + " must not be empty");
  return frame;
}

/// Reads and checks every private parameter; throws OptionError naming the bad one.
NodeParameters readParameters(const ros::NodeHandle& pnh) {
  NodeParameters p;
  p.world = typedParam(pnh, "world", p.world);
  p.room_labels = typedParam(pnh, "room_labels", p.room_labels);
  p.config = typedParam(pnh, "config", p.config);
  const int seed = typedParam(pnh, "seed", 1);
  if (seed < 0) throw OptionError("~seed must be >= 0, not " + std::to_string(seed));
  p.seed = static_cast<std::uint64_t>(seed);
  p.real_time_factor = nonNegativeParam(pnh, "real_time_factor", p.real_time_factor);
  p.map_period_s = nonNegativeParam(pnh, "map_period_s", p.map_period_s);
  p.goal_wait_s = nonNegativeParam(pnh, "goal_wait_s", p.goal_wait_s);
  p.sync_topic = typedParam(pnh, "sync_topic", p.sync_topic);
  p.sync_timeout_s = nonNegativeParam(pnh, "sync_timeout_s", p.sync_timeout_s);
  p.points = typedParam(pnh, "points", p.points);
  p.map_frame = frameParam(pnh, "map_frame", p.map_frame);
  p.odom_frame = frameParam(pnh, "odom_frame", p.odom_frame);
  p.base_frame = frameParam(pnh, "base_frame", p.base_frame);
  p.abort_zone = readAbortZone(pnh);
  return p;
}

/// What the parameters name, loaded and checked before anything is advertised.
struct Scenario {
  std::unique_ptr<const sim::WorldModel> model;
  sim::EpisodeConfig config;  ///< resolved and validated
  sim::LidarOptions lidar;    ///< the config's "lidar" group
};

/// Loads the world and the config; throws OptionError naming the parameter at fault.
Scenario loadScenario(const NodeParameters& p) {
  Scenario s;
  try {
    // The same resolution as `roomscout explore --config`; the method only selects which
    // strategy group is used, and the node uses none.
    experiment::RunSettings settings;
    settings.config_file = p.config;
    const experiment::EpisodeSetup setup =
        experiment::makeEpisodeSetup("nearest_frontier", p.seed, settings);
    s.config = setup.config;
    s.lidar = setup.cloud.lidar;
  } catch (const std::exception& e) {
    // Messages about an option's value do not name the file; those about the file do.
    const std::string what = e.what();
    const bool names_file = p.config.empty() || what.rfind(p.config, 0) == 0;
    throw OptionError("~config" + (names_file ? std::string() : " " + p.config) + ": " + what);
  }
  try {
    std::optional<std::filesystem::path> labels;
    if (!p.room_labels.empty()) labels = p.room_labels;
    const sim::World world = sim::loadWorld(p.world, labels);
    s.model = std::make_unique<const sim::WorldModel>(world, s.config.world);
  } catch (const std::exception& e) {
    throw OptionError((p.room_labels.empty() ? "~world: " : "~world/~room_labels: ") +
                      std::string(e.what()));
  }
  return s;
}

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

/// The simulated robot, mapper and move_base behind the node's topics and action server.
class SimNode {
 public:
  SimNode(const NodeParameters& params, Scenario scenario);

  /// Runs the episode until SIGINT/SIGTERM or ROS shuts down; aborts the active goal then.
  void run();

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

  // Steps of the loop.
  /// Everything observable at the current time: clock, pose, scan, point cloud, status, map;
  /// then the goal is checked against what the scan showed.
  void sense();
  /// Drives for one step: back-off, path following or standing still; detects a blocked robot.
  void act();
  /// Stops the robot, aborts the goal and reports the final rate once the time limit is passed.
  void timeOut();
  /// After the time limit: simulated time runs at real time with the robot standing still.
  void idle();
  /// Aborts the active goal on the way out, and gives the result time to leave.
  void shutdown();

  // Publishing.
  ros::Time stamp() const { return ros::Time(kClockOffset_s + t_); }
  /// map -> odom (identity: no odometry drift is simulated) and odom -> base (the true pose).
  tf2_msgs::TFMessage transforms(const ros::Time& stamp) const;
  void publishClockAndPose(const ros::Time& stamp);
  /// Takes a scan, maps it and publishes it; returns the cells the scan may have changed.
  CellRect scanAndMap(const ros::Time& stamp);
  void publishPoints(const ros::Time& stamp);
  void publishMap(const ros::Time& stamp);
  void sampleMetrics();
  void publishStatus();
  void publishFeedback(const ros::Time& stamp);

  // move_base.
  void onGoal(GoalHandle handle);
  void onCancel(GoalHandle handle);
  /// Why a goal is aborted before planning (frame, values, fault zone), or nothing.
  struct Refusal {
    std::string text;
    bool logged = false;  ///< warned about already
  };
  std::optional<Refusal> refusal(const move_base_msgs::MoveBaseGoal& goal) const;
  /// Plans from the robot to the active goal on the current map; false (with `why`) if none.
  bool replan(std::string& why);
  /// True when an occupied cell lies within the lethal radius of a waypoint ahead of the
  /// robot that the laser can have seen (pathBlockedAhead, as the Explorer checks).
  bool pathBlocked() const;
  /// Checks the active goal after a scan: back-off over, path blocked, goal reached.
  void monitorGoal(const CellRect& changed, bool scanned, const ros::Time& stamp);
  void onBlocked();
  /// Ends the active goal; `log` = false when the caller has said why already.
  void endGoal(GoalEnd end, const std::string& text, bool log = true);

  // Lockstep and pacing.
  void beginHold();
  void endHold();
  /// True while simulated time is held for an explorer's next goal (ends the hold on timeout).
  bool holding();
  /// True while simulated time waits for an explorer to say on ~sync_topic that it caught up
  /// with the last step (up to ~sync_timeout_s of wall time per step).
  bool awaitingExplorer();
  void resetPacing();
  /// Waits, serving callbacks, until the wall clock catches up with the real-time factor.
  void pace();

  NodeParameters params_;
  std::unique_ptr<const sim::WorldModel> model_;
  sim::EpisodeConfig config_;

  // ROS interfaces.
  ros::NodeHandle nh_;
  ros::NodeHandle pnh_{"~"};
  ros::Publisher clock_pub_, odom_pub_, scan_pub_, map_pub_, status_pub_, points_pub_;
  ros::Publisher
      tf_pub_;  ///< /tf, as tf2_ros::TransformBroadcaster, plus a catch-up for new subscribers
  Server server_;

  // The simulated world, robot and sensors.
  GridGeometry full_geometry_;
  OccupancyGrid grid_;  ///< the mapper's grid over the whole world
  OccupancyMapper mapper_;
  sim::LaserSimulator laser_;
  sim::Robot robot_;
  std::unique_ptr<sim::ColumnWorld> columns_;  ///< only with ~points
  std::unique_ptr<sim::LidarSimulator> lidar_;

  // move_base's planning and control.
  PathFollower follower_;
  Costmap costmap_;
  AStarPlanner planner_;
  CellRect costmap_stale_;  ///< cells changed since the costmap's last update
  bool costmap_built_ = false;
  std::vector<Cell> lethal_disc_;

  // Ground truth.
  sim::ExplorationTruth truth_;
  sim::ExplorationRateCounter rate_counter_;
  double max_time_s_ = 0.0;

  // Simulated time and schedules.
  double t_ = 0.0;
  double next_scan_s_ = 0.0, next_lidar_s_ = 0.0, next_metrics_s_ = 0.0, next_map_s_ = 0.0;
  VelocityCommand velocity_;  ///< commanded over the last step
  double blocked_for_s_ = 0.0;
  bool timed_out_ = false;

  // The published (growing) map.
  int margin_cells_ = 0;
  CellRect known_cells_;
  CellRect changed_since_map_;
  OccupancyGrid published_;

  // Metrics.
  CellRect changed_since_sample_;
  double rate_ = 0.0;
  std::optional<double> t98_s_, l98_m_;
  int goals_received_ = 0, goals_succeeded_ = 0, goals_aborted_ = 0, goals_canceled_ = 0;

  // The goal, lockstep and pacing.
  std::optional<ActiveGoal> goal_;
  std::optional<ros::WallTime> hold_since_;
  // Step lockstep (~sync_topic): the stamp of the last state published, the latest time the
  // explorer says it caught up to, and since when the loop waits for it.
  ros::Subscriber sync_sub_;
  std::optional<ros::Time> sync_stamp_;
  ros::Time acknowledged_;
  std::optional<ros::WallTime> sync_since_;
  ros::WallTime pace_wall_;
  double pace_t_ = 0.0;
};

SimNode::SimNode(const NodeParameters& params, Scenario scenario)
    : params_(params),
      model_(std::move(scenario.model)),
      config_(scenario.config),
      server_(
          nh_, "move_base", [this](GoalHandle h) { onGoal(h); },
          [this](GoalHandle h) { onCancel(h); }, false),
      full_geometry_(sim::mapGeometryFor(*model_, config_.mapping.resolution_m)),
      grid_(full_geometry_, config_.mapping),
      mapper_(grid_),
      laser_(*model_, config_.laser, params_.seed ^ 0x9E3779B97F4A7C15ull),
      robot_(*model_, config_.robot, model_->start()),
      follower_(config_.follower),
      costmap_(config_.explorer.costmap),
      planner_(config_.explorer.planner),
      lethal_disc_(
          discOffsets(config_.explorer.costmap.lethalRadius_m() / full_geometry_.resolution_m())),
      // Reachable = what the robot's navigation footprint can cover, as runEpisode scores it.
      truth_(*model_, full_geometry_, config_.explorer.costmap.lethalRadius_m()),
      rate_counter_(truth_) {
  const sim::EpisodeOptions& episode = config_.episode;
  max_time_s_ =
      episode.max_time_s > 0.0 ? episode.max_time_s : 600.0 + 5.0 * truth_.reachableArea_m2();
  margin_cells_ = static_cast<int>(std::ceil(episode.map_margin_m / full_geometry_.resolution_m()));
  if (params_.points) {
    columns_ = std::make_unique<sim::ColumnWorld>(*model_);
    lidar_ = std::make_unique<sim::LidarSimulator>(*columns_, scenario.lidar,
                                                   params_.seed ^ 0x5851F42D4C957F2Dull);
  }

  // Latched, and the transforms sent to each new /tf subscriber while time is held: a node
  // that starts during a hold learns the time and the robot's pose at once (with sim time,
  // an action client waits for a first clock, and nothing else is published until time runs).
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10, true);
  tf_pub_ = nh_.advertise<tf2_msgs::TFMessage>(
      "/tf", 100, [this](const ros::SingleSubscriberPublisher& subscriber) {
        if (hold_since_) subscriber.publish(transforms(stamp()));
      });
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
  scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
  map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  if (!params_.sync_topic.empty()) {
    sync_sub_ = nh_.subscribe<std_msgs::Time>(
        params_.sync_topic, 10,
        [this](const std_msgs::Time::ConstPtr& m) {
          acknowledged_ = std::max(acknowledged_, m->data);
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
  status_pub_ = pnh_.advertise<std_msgs::String>("status", 1, true);
  if (lidar_) points_pub_ = nh_.advertise<sensor_msgs::PointCloud2>("points", 2);
}

void SimNode::run() {
  server_.start();
  const sim::World& world = model_->world();
  const std::string pacing = params_.real_time_factor > 0.0
                                 ? "real-time factor " + formatNumber(params_.real_time_factor)
                                 : "as fast as possible";
  ROS_INFO(
      "roomscout_sim_node: world %s (%s), reachable %.1f m^2, time limit %.0f s, step %g s, %s, "
      "goal wait %g s",
      world.name.c_str(), world.source.c_str(), truth_.reachableArea_m2(), max_time_s_,
      config_.episode.dt_s, pacing.c_str(), params_.goal_wait_s);
  sense();  // the state at time 0, for the explorer's first goal
  beginHold();
  resetPacing();
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  while (ros::ok() && !g_stop_requested) {
    queue.callAvailable(ros::WallDuration(hold_since_ || sync_since_ ? kHoldPoll_s : 0.0));
    if (g_stop_requested || !ros::ok()) break;
    if (timed_out_) {
      idle();
      continue;
    }
    if (holding() || awaitingExplorer()) continue;
    act();
    t_ += config_.episode.dt_s;
    if (t_ > max_time_s_) {
      timeOut();
      continue;
    }
    sense();
    pace();
  }
  shutdown();
}

void SimNode::sense() {
  const ros::Time now = stamp();
  publishClockAndPose(now);
  CellRect changed;
  const bool scanned = t_ >= next_scan_s_ - kScheduleSlack_s;
  if (scanned) {
    changed = scanAndMap(now);
    next_scan_s_ += 1.0 / config_.laser.rate_hz;
  }
  if (lidar_ && t_ >= next_lidar_s_ - kScheduleSlack_s) {
    publishPoints(now);
    next_lidar_s_ += 1.0 / lidar_->options().rate_hz;
  }
  if (t_ >= next_metrics_s_ - kScheduleSlack_s) {
    sampleMetrics();
    publishStatus();
    next_metrics_s_ += config_.episode.metrics_period_s;
  }
  const bool map_due = params_.map_period_s > 0.0 ? t_ >= next_map_s_ - kScheduleSlack_s : scanned;
  if (map_due) {
    publishMap(now);
    // Skip missed periods rather than publishing a burst (a period shorter than the step).
    while (params_.map_period_s > 0.0 && next_map_s_ <= t_ + kScheduleSlack_s)
      next_map_s_ += params_.map_period_s;
  }
  monitorGoal(changed, scanned, now);
  sync_stamp_ = now;
}

void SimNode::act() {
  const double dt = config_.episode.dt_s;
  velocity_ = {};
  bool following = false;
  if (goal_ && goal_->back_off_until_s) {
    velocity_.linear_mps = kBackOffSpeed_mps;  // away from whatever the robot is pressed against
  } else if (goal_) {
    velocity_ = follower_.compute(robot_.pose());
    following = true;
  }
  const bool moved = robot_.step(velocity_, dt);
  if (following && velocity_.linear_mps > 0.0 && !moved) {
    blocked_for_s_ += dt;
    if (blocked_for_s_ >= config_.episode.stuck_timeout_s) {
      blocked_for_s_ = 0.0;
      onBlocked();
    }
  } else {
    blocked_for_s_ = 0.0;
  }
}

void SimNode::timeOut() {
  timed_out_ = true;
  hold_since_.reset();
  if (goal_) endGoal(GoalEnd::kAborted, "simulated time limit reached");
  velocity_ = {};
  sampleMetrics();
  publishStatus();
  publishClockAndPose(stamp());
  ROS_INFO(
      "roomscout_sim_node: time limit %.0f s reached at %.1f m driven, exploration rate %.1f %%; "
      "the robot stands still and /clock runs at real time",
      max_time_s_, robot_.odometer_m(), 100.0 * rate_);
  resetPacing();
}

void SimNode::idle() {
  const double dt = config_.episode.dt_s;
  ros::WallDuration(dt).sleep();
  t_ += dt;
  publishClockAndPose(stamp());
}

void SimNode::shutdown() {
  if (goal_) {
    goal_->handle.setAborted(move_base_msgs::MoveBaseResult(), "simulator shutting down");
    ++goals_aborted_;
    goal_.reset();
    publishStatus();
    // The result and the status go out on roscpp's own threads; give them a moment before shutting
    // down.
    ros::WallDuration(0.2).sleep();
  }
  ROS_INFO("roomscout_sim_node: shutting down at %.1f s simulated, exploration rate %.1f %%", t_,
           100.0 * rate_);
  ros::shutdown();
}

void SimNode::publishClockAndPose(const ros::Time& stamp) {
  rosgraph_msgs::Clock clock;
  clock.clock = stamp;
  clock_pub_.publish(clock);

  tf_pub_.publish(transforms(stamp));

  nav_msgs::Odometry odom;
  odom.header.stamp = stamp;
  odom.header.frame_id = params_.odom_frame;
  odom.child_frame_id = params_.base_frame;
  odom.pose.pose = toPoseMsg(robot_.pose());
  odom.twist.twist.linear.x = velocity_.linear_mps;
  odom.twist.twist.angular.z = velocity_.angular_radps;
  odom_pub_.publish(odom);
}

tf2_msgs::TFMessage SimNode::transforms(const ros::Time& stamp) const {
  const Pose2& pose = robot_.pose();
  tf2_msgs::TFMessage msg;
  msg.transforms.resize(2);
  geometry_msgs::TransformStamped& map_odom = msg.transforms[0];
  map_odom.header.stamp = stamp;
  map_odom.header.frame_id = params_.map_frame;
  map_odom.child_frame_id = params_.odom_frame;
  map_odom.transform.rotation.w = 1.0;
  geometry_msgs::TransformStamped& odom_base = msg.transforms[1];
  odom_base.header.stamp = stamp;
  odom_base.header.frame_id = params_.odom_frame;
  odom_base.child_frame_id = params_.base_frame;
  odom_base.transform.translation.x = pose.x_m;
  odom_base.transform.translation.y = pose.y_m;
  odom_base.transform.rotation = toPoseMsg(pose).orientation;
  return msg;
}

CellRect SimNode::scanAndMap(const ros::Time& stamp) {
  // The laser sits on the robot's centre: the sensor pose is the robot pose.
  const LaserScan scan = laser_.scan(robot_.pose());
  const CellRect changed = mapper_.integrate(scan, robot_.pose());
  changed_since_sample_.unite(changed);
  changed_since_map_.unite(changed);
  costmap_stale_.unite(changed);
  // The cells a scan touched are known (a hit or a miss classifies a cell at once).
  known_cells_.unite(changed);

  sensor_msgs::LaserScan msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.base_frame;
  msg.angle_min = static_cast<float>(scan.angle_min_rad);
  msg.angle_increment = static_cast<float>(scan.angle_increment_rad);
  const std::size_t n = scan.ranges_m.size();
  msg.angle_max =
      static_cast<float>(scan.angle_min_rad + scan.angle_increment_rad * (n > 0 ? n - 1 : 0));
  msg.time_increment = 0.0f;
  msg.scan_time = static_cast<float>(1.0 / config_.laser.rate_hz);
  msg.range_min = static_cast<float>(scan.range_min_m);
  msg.range_max = static_cast<float>(scan.range_max_m);
  msg.ranges = scan.ranges_m;
  scan_pub_.publish(msg);
  return changed;
}

void SimNode::publishPoints(const ros::Time& stamp) {
  // A revolution costs milliseconds: cast only when someone listens.
  if (points_pub_.getNumSubscribers() == 0) return;
  const Pose2& pose = robot_.pose();
  const sim::LidarScan scan = lidar_->scan(pose);
  const Eigen::Isometry3d T_map_base = Eigen::Translation3d(pose.x_m, pose.y_m, 0.0) *
                                       Eigen::AngleAxisd(pose.yaw_rad, Eigen::Vector3d::UnitZ());
  const Eigen::Isometry3f T_base_sensor = (T_map_base.inverse() * scan.T_map_sensor).cast<float>();

  sensor_msgs::PointCloud2 msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.base_frame;
  msg.height = 1;
  sensor_msgs::PointCloud2Modifier modifier(msg);
  modifier.setPointCloud2Fields(3, "x", 1, sensor_msgs::PointField::FLOAT32, "y", 1,
                                sensor_msgs::PointField::FLOAT32, "z", 1,
                                sensor_msgs::PointField::FLOAT32);
  modifier.resize(scan.points_sensor.size());
  sensor_msgs::PointCloud2Iterator<float> x(msg, "x"), y(msg, "y"), z(msg, "z");
  for (const Eigen::Vector3f& p_sensor : scan.points_sensor) {
    const Eigen::Vector3f p = T_base_sensor * p_sensor;
    *x = p.x();
    *y = p.y();
    *z = p.z();
    ++x;
    ++y;
    ++z;
  }
  msg.is_dense = true;
  points_pub_.publish(msg);
}

void SimNode::publishMap(const ros::Time& stamp) {
  // As a SLAM package: the known area's bounding box plus the margin, the origin moving as
  // the map grows (episode.cpp's growing mode).
  const GridGeometry g = sim::publishedGeometry(full_geometry_, known_cells_, margin_cells_);
  if (g != published_.geometry()) {
    published_ = grid_.reframed(g);
  } else {
    published_.copyCells(grid_, changed_since_map_);
  }
  changed_since_map_ = CellRect{};
  nav_msgs::OccupancyGrid msg;
  toMsg(published_, msg);
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.map_frame;
  msg.info.map_load_time = stamp;
  map_pub_.publish(msg);
}

void SimNode::sampleMetrics() {
  rate_counter_.update(grid_, changed_since_sample_);
  changed_since_sample_ = CellRect{};
  rate_ = rate_counter_.rate();
  if (!t98_s_ && rate_ >= config_.episode.completion_rate) {
    t98_s_ = t_;
    l98_m_ = robot_.odometer_m();
    ROS_INFO(
        "roomscout_sim_node: exploration rate %.1f %% reached at %.1f s simulated, %.1f m driven",
        100.0 * rate_, t_, robot_.odometer_m());
  }
}

void SimNode::publishStatus() {
  auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  const nlohmann::json status = {
      {"time_s", t_},
      {"length_m", robot_.odometer_m()},
      {"rate", rate_},
      {"t98_s", optional(t98_s_)},
      {"l98_m", optional(l98_m_)},
      {"reachable_area_m2", truth_.reachableArea_m2()},
      {"max_time_s", max_time_s_},
      {"timed_out", timed_out_},
      {"goals_received", goals_received_},
      {"goals_succeeded", goals_succeeded_},
      {"goals_aborted", goals_aborted_},
      {"goals_canceled", goals_canceled_},
  };
  std_msgs::String msg;
  msg.data = status.dump();
  status_pub_.publish(msg);
}

void SimNode::publishFeedback(const ros::Time& stamp) {
  move_base_msgs::MoveBaseFeedback feedback;
  feedback.base_position.header.stamp = stamp;
  feedback.base_position.header.frame_id = params_.map_frame;
  feedback.base_position.pose = toPoseMsg(robot_.pose());
  goal_->handle.publishFeedback(feedback);
}

void SimNode::onGoal(GoalHandle handle) {
  ++goals_received_;
  handle.setAccepted();
  if (goal_) {
    // A new goal preempts the old one, as move_base does.
    goal_->handle.setCanceled(move_base_msgs::MoveBaseResult(), "preempted by a new goal");
    ++goals_canceled_;
    goal_.reset();
    follower_.clear();
  }
  const move_base_msgs::MoveBaseGoal& goal = *handle.getGoal();
  const geometry_msgs::Point& p = goal.target_pose.pose.position;
  goal_.emplace();
  goal_->handle = handle;
  goal_->target_m = Vec2(p.x, p.y);
  blocked_for_s_ = 0.0;
  if (const std::optional<Refusal> r = refusal(goal)) {
    endGoal(GoalEnd::kAborted, r->text, !r->logged);
    return;
  }
  std::string why;
  if (!replan(why)) {
    endGoal(GoalEnd::kAborted, why);
    return;
  }
  endHold();
  ROS_DEBUG("roomscout_sim_node: driving to (%.2f, %.2f)", p.x, p.y);
}

void SimNode::onCancel(GoalHandle handle) {
  if (goal_ && goal_->handle == handle) endGoal(GoalEnd::kCanceled, "canceled");
}

std::optional<SimNode::Refusal> SimNode::refusal(const move_base_msgs::MoveBaseGoal& goal) const {
  if (timed_out_) return Refusal{"simulated time limit reached"};
  if (g_stop_requested) return Refusal{"simulator shutting down"};
  const std::string frame = bareFrame(goal.target_pose.header.frame_id);
  if (!frame.empty() && frame != params_.map_frame) {
    return Refusal{"goal frame \"" + goal.target_pose.header.frame_id +
                   "\" is not the map frame \"" + params_.map_frame + "\""};
  }
  const geometry_msgs::Point& p = goal.target_pose.pose.position;
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return Refusal{"goal position is not finite"};
  if (params_.abort_zone &&
      (Vec2(p.x, p.y) - params_.abort_zone->center_m).norm() <= params_.abort_zone->radius_m) {
    ROS_WARN(
        "roomscout_sim_node: aborting the goal (%.2f, %.2f): within %.2f m of (%.2f, %.2f) "
        "(~abort_goals_near)",
        p.x, p.y, params_.abort_zone->radius_m, params_.abort_zone->center_m.x(),
        params_.abort_zone->center_m.y());
    return Refusal{"goal inside the ~abort_goals_near zone (fault injection)", true};
  }
  return std::nullopt;
}

bool SimNode::replan(std::string& why) {
  if (!costmap_built_ || !costmap_stale_.empty()) {
    costmap_.update(grid_, costmap_stale_);  // the first call builds it from the whole grid
    costmap_built_ = true;
    costmap_stale_ = CellRect{};
  }
  const PlanResult plan = planner_.plan(costmap_, robot_.pose().position(), goal_->target_m);
  if (plan.status != PlanStatus::kFound) {
    why = std::string("no path to the goal: ") + planStatusText(plan.status);
    return false;
  }
  follower_.setPath(plan.path);
  return true;
}

bool SimNode::pathBlocked() const {
  if (!follower_.hasPath()) return false;
  // Beyond the laser's range a new scan cannot have blocked the path.
  const double horizon_m =
      config_.laser.range_max_m + config_.explorer.costmap.lethalRadius_m() + 0.5;
  return pathBlockedAhead(grid_, follower_.path().waypoints_m, follower_.progressIndex(),
                          robot_.pose().position(), horizon_m, lethal_disc_);
}

void SimNode::monitorGoal(const CellRect& changed, bool scanned, const ros::Time& stamp) {
  if (!goal_) return;
  std::string why;
  if (goal_->back_off_until_s) {
    if (t_ < *goal_->back_off_until_s - kScheduleSlack_s) return;
    goal_->back_off_until_s.reset();
    if (!replan(why)) endGoal(GoalEnd::kAborted, "blocked, and after backing off " + why);
    return;
  }
  if (!changed.empty() && pathBlocked() && !replan(why)) {
    endGoal(GoalEnd::kAborted, "path blocked by a newly seen obstacle, " + why);
    return;
  }
  if (follower_.reached(robot_.pose())) {
    endGoal(GoalEnd::kSucceeded, "goal reached");
    return;
  }
  if (scanned) publishFeedback(stamp);
}

void SimNode::onBlocked() {
  if (goal_->recovered) {
    endGoal(GoalEnd::kAborted, "robot blocked again after a back-off");
    return;
  }
  // As the episode's recovery: back off for a while, then plan afresh from there.
  goal_->recovered = true;
  goal_->back_off_until_s = t_ + config_.episode.dt_s + config_.explorer.goals.recovery_time_s;
  follower_.clear();
  ROS_INFO("roomscout_sim_node: robot blocked for %.1f s; backing off for %.1f s",
           config_.episode.stuck_timeout_s, config_.explorer.goals.recovery_time_s);
}

void SimNode::endGoal(GoalEnd end, const std::string& text, bool log) {
  const move_base_msgs::MoveBaseResult result;
  switch (end) {
    case GoalEnd::kSucceeded:
      goal_->handle.setSucceeded(result, text);
      ++goals_succeeded_;
      ROS_DEBUG("roomscout_sim_node: goal reached at %.1f s", t_);
      break;
    case GoalEnd::kAborted:
      goal_->handle.setAborted(result, text);
      ++goals_aborted_;
      if (log)
        ROS_INFO("roomscout_sim_node: goal (%.2f, %.2f) aborted: %s", goal_->target_m.x(),
                 goal_->target_m.y(), text.c_str());
      break;
    case GoalEnd::kCanceled:
      goal_->handle.setCanceled(result, text);
      ++goals_canceled_;
      break;
  }
  goal_.reset();
  follower_.clear();
  velocity_ = {};
  blocked_for_s_ = 0.0;
  publishStatus();  // the goal counts, without waiting for the next sample (time may be held)
  beginHold();
}

void SimNode::beginHold() {
  if (params_.goal_wait_s > 0.0 && !timed_out_) hold_since_ = ros::WallTime::now();
}

void SimNode::endHold() {
  if (!hold_since_) return;
  hold_since_.reset();
  resetPacing();
}

bool SimNode::awaitingExplorer() {
  if (!sync_sub_ || !sync_stamp_ || acknowledged_ >= *sync_stamp_) {
    sync_since_.reset();
    return false;
  }
  const ros::WallTime now = ros::WallTime::now();
  if (!sync_since_) sync_since_ = now;
  if ((now - *sync_since_).toSec() < params_.sync_timeout_s) return true;
  ROS_WARN_THROTTLE(10.0, "no explorer caught up on %s within %g s: running on",
                    params_.sync_topic.c_str(), params_.sync_timeout_s);
  sync_stamp_.reset();  // wait again from the next step on
  sync_since_.reset();
  resetPacing();
  return false;
}

bool SimNode::holding() {
  if (!hold_since_) return false;
  if ((ros::WallTime::now() - *hold_since_).toSec() < params_.goal_wait_s) return true;
  endHold();  // no goal came: run freely until the next one
  return false;
}

void SimNode::resetPacing() {
  pace_wall_ = ros::WallTime::now();
  pace_t_ = t_;
}

void SimNode::pace() {
  if (params_.real_time_factor <= 0.0) return;
  const ros::WallTime due =
      pace_wall_ + ros::WallDuration((t_ - pace_t_) / params_.real_time_factor);
  ros::WallTime now = ros::WallTime::now();
  if ((now - due).toSec() > kMaxPacingLag_s) {
    resetPacing();
    return;
  }
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  while (now < due && ros::ok() && !g_stop_requested) {
    queue.callAvailable(due - now);
    now = ros::WallTime::now();
  }
}

/// Runs the node; returns the process's exit status.
int runSimNode(int argc, char** argv) {
  // This node is the clock: it runs on wall time even when /use_sim_time is set for the
  // others. Following its own /clock, its action server's status timer would stop while
  // simulated time is held, and an explorer waiting for the server would wait out the hold.
  // roscpp reads /use_sim_time through the name remappings, so one pointing it at a name
  // nobody sets does it for this process only.
  std::vector<char*> args(argv, argv + argc);
  std::string wall_time = "/use_sim_time:=/roomscout_sim_node_runs_on_wall_time";
  args.push_back(wall_time.data());
  int arg_count = static_cast<int>(args.size());
  // Our own signal handlers, so that the loop can abort the active goal before ROS shuts down.
  ros::init(arg_count, args.data(), "roomscout_sim", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  try {
    const ros::NodeHandle pnh("~");
    const NodeParameters params = readParameters(pnh);
    Scenario scenario = loadScenario(params);
    SimNode node(params, std::move(scenario));
    node.run();
  } catch (const std::exception& e) {
    // On stderr directly: rosconsole's output of a message logged just before exit is not
    // reliably printed.
    std::cerr << "roomscout_sim_node: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

}  // namespace
}  // namespace roomscout::ros1

int main(int argc, char** argv) { return roomscout::ros1::runSimNode(argc, argv); }
