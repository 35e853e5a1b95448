// roomscout_sim_node: the project's simulator as a ROS 1 node. It stands in for the robot, its
// SLAM and move_base, so that an explorer node runs over ROS on a laptop without Gazebo.
//
// One thread steps a sim::Simulation (the loop `roomscout explore` runs, with the same config
// groups: noise, slam and episode.map_mode included) with ROS in place of the in-process
// Explorer: each step publishes /clock, tf (map -> odom from the SLAM estimate, identity
// without SLAM; odom -> base the wheel odometry) and odom; each scan is published; the map is
// published as the simulation publishes it; the exploration rate against ground truth is
// published on ~status. Goals arrive through a FakeMoveBase: the move_base action over the
// library's costmap, A* and path follower.
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
#include "roomscout/sim/column_world.hpp"
#include "roomscout/sim/lidar_simulator.hpp"
#include "roomscout/sim/simulation.hpp"
#include "roomscout/sim/simulator_config.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"
#include "roomscout_ros/fake_move_base.hpp"
#include "roomscout_ros/grid_conversions.hpp"
#include "roomscout_ros/node_params.hpp"

namespace roomscout::ros1 {
namespace {

/// Added to the simulated time for every stamp and /clock, so that no stamp is zero [s].
constexpr double kClockOffset_s = 1e-3;
/// Tolerance of the schedules (lidar, map) against the accumulated time [s].
constexpr double kScheduleSlack_s = 1e-9;
/// Falling this far behind the real-time factor's schedule restarts the schedule rather than
/// catching up with a burst of steps [wall s].
constexpr double kMaxPacingLag_s = 0.5;
/// How long one wait for callbacks lasts while simulated time is held [wall s].
constexpr double kHoldPoll_s = 0.002;

/// Set by SIGINT/SIGTERM: the loop aborts the active goal and leaves.
std::atomic<bool> g_stop_requested{false};

void requestStop(int) { g_stop_requested = true; }

/// The node's private parameters.
struct NodeParameters {
  std::string world = "small_house";
  std::string room_labels;
  std::string config;
  std::uint64_t seed = 1;
  double real_time_factor = 0.0;          ///< 0 = as fast as possible
  double map_period_s = 0.0;              ///< simulated; 0 = every scan
  std::string map_source = "map_server";  ///< the value convention of the published map
  double goal_wait_s = 2.0;               ///< wall; 0 = no lockstep
  std::string sync_topic;       ///< std_msgs/Time up to which an explorer caught up; "" = off
  double sync_timeout_s = 1.0;  ///< wall: longest wait for it per step; 0 = no limit
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
  p.map_source = typedParam(pnh, "map_source", p.map_source);
  MapConvention::named(p.map_source);  // a known source, or the list of them
  if (p.map_source == "costmap") {
    throw OptionError(
        "~map_source: the sim node publishes a SLAM map (map_server, cartographer, "
        "slam_toolbox or gmapping), not a costmap");
  }
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
  sim::RangeNoise lidar_noise;
};

/// Loads the world and the config; throws OptionError naming the parameter at fault.
Scenario loadScenario(const NodeParameters& p) {
  Scenario s;
  try {
    // The file `roomscout explore --config` reads, resolved as it resolves it.
    const sim::SimulatorConfig config = sim::loadSimulatorConfig(p.config);
    s.config = config.episode;
    for (const std::string& w : config.warnings) ROS_WARN("%s", w.c_str());
    s.lidar = config.cloud.lidar;
    s.lidar_noise = config.cloud.lidar_noise;
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

/// The simulation, its lidar and the fake move_base behind the node's topics.
class SimNode {
 public:
  SimNode(const NodeParameters& params, Scenario scenario);

  /// Runs until SIGINT/SIGTERM or ROS shuts down; aborts the active goal then.
  void run();

 private:
  /// Everything observable at the current time: clock, pose, scan, point cloud, status, map;
  /// then the fake move_base checks its goal against what the scan showed.
  void sense();
  /// Drives for one step and advances the clock; reports a blocked robot to move_base.
  void act();
  /// Stops the robot, aborts the goal and reports the final rate once the time limit is passed.
  void timeOut();
  /// After the time limit: simulated time runs at real time with the robot standing still.
  void idle();
  /// Aborts the active goal on the way out, and gives the result time to leave.
  void shutdown();

  // Publishing.
  ros::Time stamp() const { return ros::Time(kClockOffset_s + idle_s_ + sim_.time_s()); }
  /// map -> odom (the SLAM's correction of the odometry) and odom -> base (the odometry).
  tf2_msgs::TFMessage transforms(const ros::Time& stamp) const;
  void publishClockAndPose(const ros::Time& stamp);
  void publishScan(const LaserScan& scan, const ros::Time& stamp);
  void publishPoints(const ros::Time& stamp);
  void publishMap(const ros::Time& stamp);
  void publishStatus();

  // Lockstep and pacing.
  void beginHold();
  void endHold();
  /// True while simulated time is held for an explorer's next goal (ends the hold on timeout).
  bool holding();
  /// True while simulated time waits for an explorer to say on ~sync_topic that it caught up
  /// with the last step (up to ~sync_timeout_s of wall time per step, or for as long as it
  /// takes when that is 0).
  bool awaitingExplorer();
  void resetPacing();
  /// Waits, serving callbacks, until the wall clock catches up with the real-time factor.
  void pace();
  double now_s() const { return idle_s_ + sim_.time_s(); }

  NodeParameters params_;
  std::unique_ptr<const sim::WorldModel> model_;
  sim::Simulation sim_;

  // ROS interfaces.
  ros::NodeHandle nh_;
  ros::NodeHandle pnh_{"~"};
  ros::Publisher clock_pub_, odom_pub_, scan_pub_, map_pub_, status_pub_, points_pub_;
  ros::Publisher
      tf_pub_;  ///< /tf, as tf2_ros::TransformBroadcaster, plus a catch-up for new subscribers
  FakeMoveBase move_base_;

  std::unique_ptr<sim::ColumnWorld> columns_;  ///< only with ~points
  std::unique_ptr<sim::LidarSimulator> lidar_;

  double next_lidar_s_ = 0.0, next_map_s_ = 0.0;
  double idle_s_ = 0.0;       ///< time run after the time limit, the robot standing still [s]
  VelocityCommand velocity_;  ///< commanded over the last step
  CellRect changed_since_monitor_;
  bool t98_logged_ = false;

  // Lockstep and pacing.
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

FakeMoveBaseOptions moveBaseOptions(const NodeParameters& params, const sim::Simulation& sim) {
  FakeMoveBaseOptions o;
  const ExplorerOptions explorer = sim.explorerOptions();
  o.costmap = explorer.costmap;
  o.planner = explorer.planner;
  o.follower = sim.config().follower;
  o.sensor_range_m = explorer.goals.sensor_range_m;
  o.recovery_time_s = explorer.goals.recovery_time_s;
  o.map_frame = params.map_frame;
  o.abort_zone = params.abort_zone;
  return o;
}

SimNode::SimNode(const NodeParameters& params, Scenario scenario)
    : params_(params),
      model_(std::move(scenario.model)),
      sim_(*model_, scenario.config, params_.seed),
      move_base_(nh_, moveBaseOptions(params_, sim_),
                 FakeMoveBase::Hooks{[this] { endHold(); },
                                     [this] {
                                       velocity_ = {};
                                       // The goal counts at once (time may be held).
                                       publishStatus();
                                       beginHold();
                                     }}) {
  if (params_.points) {
    columns_ = std::make_unique<sim::ColumnWorld>(*model_);
    lidar_ = std::make_unique<sim::LidarSimulator>(
        *columns_, scenario.lidar, params_.seed ^ 0x5851F42D4C957F2Dull, scenario.lidar_noise);
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
  move_base_.start();
  const sim::World& world = model_->world();
  const std::string pacing = params_.real_time_factor > 0.0
                                 ? "real-time factor " + formatNumber(params_.real_time_factor)
                                 : "as fast as possible";
  ROS_INFO(
      "roomscout_sim_node: world %s (%s), reachable %.1f m^2, time limit %.0f s, step %g s, %s, "
      "goal wait %g s, noise %s, slam %s, map %s",
      world.name.c_str(), world.source.c_str(), sim_.reachableArea_m2(), sim_.maxTime_s(),
      sim_.config().episode.dt_s, pacing.c_str(), params_.goal_wait_s,
      sim_.config().noise.profile.c_str(), sim_.config().slam.mode.c_str(),
      sim_.config().episode.map_mode.c_str());
  sense();  // the state at time 0, for the explorer's first goal
  beginHold();
  resetPacing();
  ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
  while (ros::ok() && !g_stop_requested) {
    queue.callAvailable(ros::WallDuration(hold_since_ || sync_since_ ? kHoldPoll_s : 0.0));
    if (g_stop_requested || !ros::ok()) break;
    if (sim_.timedOut()) {
      idle();
      continue;
    }
    if (holding() || awaitingExplorer()) continue;
    act();
    if (sim_.timedOut()) {
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
  const sim::Sensed sensed = sim_.sense();
  publishClockAndPose(now);
  changed_since_monitor_.unite(sensed.changed);
  if (sensed.scan) publishScan(*sensed.scan, now);
  if (lidar_ && sim_.time_s() >= next_lidar_s_ - kScheduleSlack_s) {
    publishPoints(now);
    next_lidar_s_ += 1.0 / lidar_->options().rate_hz;
  }
  if (sensed.sampled) {
    if (sim_.t98_s() && !t98_logged_) {
      t98_logged_ = true;
      ROS_INFO(
          "roomscout_sim_node: exploration rate %.1f %% reached at %.1f s simulated, %.1f m "
          "driven",
          100.0 * sim_.rate(), *sim_.t98_s(), *sim_.l98_m());
    }
    publishStatus();
  }
  const bool map_due = params_.map_period_s > 0.0 ? sim_.time_s() >= next_map_s_ - kScheduleSlack_s
                                                  : sensed.scan.has_value();
  if (map_due) {
    publishMap(now);
    // Skip missed periods rather than publishing a burst (a period shorter than the step).
    while (params_.map_period_s > 0.0 && next_map_s_ <= sim_.time_s() + kScheduleSlack_s)
      next_map_s_ += params_.map_period_s;
  }
  move_base_.monitor(sim_.grid(), changed_since_monitor_, sim_.estimate(), sim_.time_s(),
                     sensed.scan ? std::optional<ros::Time>(now) : std::nullopt);
  changed_since_monitor_ = CellRect{};
  sync_stamp_ = now;
}

void SimNode::act() {
  velocity_ = move_base_.command(sim_.estimate());
  const bool blocked = sim_.act(velocity_);
  sim_.step();
  if (blocked) move_base_.onBlocked(sim_.time_s());
}

void SimNode::timeOut() {
  hold_since_.reset();
  move_base_.refuseGoals("simulated time limit reached");
  move_base_.abort("simulated time limit reached");
  velocity_ = {};
  sim_.finish();
  publishStatus();
  publishClockAndPose(stamp());
  ROS_INFO(
      "roomscout_sim_node: time limit %.0f s reached at %.1f m driven, exploration rate %.1f %%; "
      "the robot stands still and /clock runs at real time",
      sim_.maxTime_s(), sim_.odometer_m(), 100.0 * sim_.rate());
  resetPacing();
}

void SimNode::idle() {
  const double dt = sim_.config().episode.dt_s;
  ros::WallDuration(dt).sleep();
  idle_s_ += dt;
  publishClockAndPose(stamp());
}

void SimNode::shutdown() {
  move_base_.refuseGoals("simulator shutting down");
  if (move_base_.active()) {
    move_base_.abort("simulator shutting down");
    // The result and the status go out on roscpp's own threads; give them a moment before
    // shutting down.
    ros::WallDuration(0.2).sleep();
  }
  ROS_INFO("roomscout_sim_node: shutting down at %.1f s simulated, exploration rate %.1f %%",
           now_s(), 100.0 * sim_.rate());
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
  odom.pose.pose = toPoseMsg(sim_.odometryPose());
  odom.twist.twist.linear.x = velocity_.linear_mps;
  odom.twist.twist.angular.z = velocity_.angular_radps;
  odom_pub_.publish(odom);
}

/// The rigid transform of a planar pose.
Eigen::Isometry2d isometry(const Pose2& pose) {
  return Eigen::Translation2d(pose.x_m, pose.y_m) * Eigen::Rotation2Dd(pose.yaw_rad);
}

tf2_msgs::TFMessage SimNode::transforms(const ros::Time& stamp) const {
  // T_map_odom = T_map_base (the estimate) * T_odom_base^-1 (the odometry): the identity
  // without SLAM, where both are the true pose.
  const Pose2& odometry = sim_.odometryPose();
  const Eigen::Isometry2d T_map_odom =
      sim_.hasSlam() ? isometry(sim_.estimate()) * isometry(odometry).inverse()
                     : Eigen::Isometry2d::Identity();
  const Pose2 map_odom_pose{T_map_odom.translation().x(), T_map_odom.translation().y(),
                            std::atan2(T_map_odom.linear()(1, 0), T_map_odom.linear()(0, 0))};
  tf2_msgs::TFMessage msg;
  msg.transforms.resize(2);
  geometry_msgs::TransformStamped& map_odom = msg.transforms[0];
  map_odom.header.stamp = stamp;
  map_odom.header.frame_id = params_.map_frame;
  map_odom.child_frame_id = params_.odom_frame;
  map_odom.transform.translation.x = map_odom_pose.x_m;
  map_odom.transform.translation.y = map_odom_pose.y_m;
  map_odom.transform.rotation = toPoseMsg(map_odom_pose).orientation;
  geometry_msgs::TransformStamped& odom_base = msg.transforms[1];
  odom_base.header.stamp = stamp;
  odom_base.header.frame_id = params_.odom_frame;
  odom_base.child_frame_id = params_.base_frame;
  odom_base.transform.translation.x = odometry.x_m;
  odom_base.transform.translation.y = odometry.y_m;
  odom_base.transform.rotation = toPoseMsg(odometry).orientation;
  return msg;
}

void SimNode::publishScan(const LaserScan& scan, const ros::Time& stamp) {
  sensor_msgs::LaserScan msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.base_frame;
  msg.angle_min = static_cast<float>(scan.angle_min_rad);
  msg.angle_increment = static_cast<float>(scan.angle_increment_rad);
  const std::size_t n = scan.ranges_m.size();
  msg.angle_max =
      static_cast<float>(scan.angle_min_rad + scan.angle_increment_rad * (n > 0 ? n - 1 : 0));
  msg.time_increment = 0.0f;
  msg.scan_time = static_cast<float>(1.0 / sim_.config().laser.rate_hz);
  msg.range_min = static_cast<float>(scan.range_min_m);
  msg.range_max = static_cast<float>(scan.range_max_m);
  msg.ranges = scan.ranges_m;
  scan_pub_.publish(msg);
}

void SimNode::publishPoints(const ros::Time& stamp) {
  // A revolution costs milliseconds: cast only when someone listens.
  if (points_pub_.getNumSubscribers() == 0) return;
  // The lidar sees from the true pose; its points go out in the robot's frame.
  const Pose2& pose = sim_.robotPose();
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
  const sim::PublishedMap map = sim_.publishMap();
  nav_msgs::OccupancyGrid msg;
  // Cartographer publishes probabilities; map_server, slam_toolbox and gmapping 0, 100 and -1.
  if (params_.map_source == "cartographer") {
    toProbabilityMsg(map.grid, msg);
  } else {
    toMsg(map.grid, msg);
  }
  msg.header.stamp = stamp;
  msg.header.frame_id = params_.map_frame;
  msg.info.map_load_time = stamp;
  map_pub_.publish(msg);
}

void SimNode::publishStatus() {
  auto optional = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  const FakeMoveBase::Counts& goals = move_base_.counts();
  const nlohmann::json status = {
      {"time_s", now_s()},
      {"length_m", sim_.odometer_m()},
      {"rate", sim_.rate()},
      {"t98_s", optional(sim_.t98_s())},
      {"l98_m", optional(sim_.l98_m())},
      {"reachable_area_m2", sim_.reachableArea_m2()},
      {"max_time_s", sim_.maxTime_s()},
      {"timed_out", sim_.timedOut()},
      {"goals_received", goals.received},
      {"goals_succeeded", goals.succeeded},
      {"goals_aborted", goals.aborted},
      {"goals_canceled", goals.canceled},
      {"pose", {sim_.robotPose().x_m, sim_.robotPose().y_m, sim_.robotPose().yaw_rad}},
  };
  std_msgs::String msg;
  msg.data = status.dump();
  status_pub_.publish(msg);
}

void SimNode::beginHold() {
  if (params_.goal_wait_s > 0.0 && !sim_.timedOut()) hold_since_ = ros::WallTime::now();
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
  if (params_.sync_timeout_s <= 0.0 || (now - *sync_since_).toSec() < params_.sync_timeout_s)
    return true;
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
  pace_t_ = now_s();
}

void SimNode::pace() {
  if (params_.real_time_factor <= 0.0) return;
  const ros::WallTime due =
      pace_wall_ + ros::WallDuration((now_s() - pace_t_) / params_.real_time_factor);
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
