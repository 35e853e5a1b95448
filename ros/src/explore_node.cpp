// roomscout_explore_node: the library's Explorer on a ROS 1 robot. It reads the map a SLAM
// package publishes and the robot's pose from tf, sends the goals the Explorer picks to
// move_base, and publishes the rooms, the skeleton graph, the frontier candidates, the goal
// and a status. When exploration ends it saves the four maps. A thin adapter: everything it
// decides, the library decides; a ROS 2 port would keep this shape.
//
// Topics, services and parameters: docs/ros.md.

#include <atomic>
#include <cmath>
#include <csignal>
#include <deque>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/client/simple_action_client.h>
#include <map_msgs/OccupancyGridUpdate.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>
#include <std_msgs/Time.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>
#include <Eigen/Geometry>
#include <boost/make_shared.hpp>
#include <nlohmann/json.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"
#include "roomscout/explorer/explorer.hpp"
#include "roomscout/io/explorer_config.hpp"
#include "roomscout/mapping/keyframe_selector.hpp"
#include "roomscout/mapping/point_cloud_map.hpp"
#include "roomscout_ros/grid_conversions.hpp"
#include "roomscout_ros/map_markers.hpp"
#include "roomscout_ros/map_saver.hpp"
#include "roomscout_ros/node_params.hpp"

namespace roomscout::ros1 {
namespace {

std::atomic<bool> g_stop{false};
void onSignal(int /*signal*/) { g_stop = true; }

/// The node's own parameters (private namespace); the Explorer's come from `config`.
struct ExploreNodeParams {
  std::string method = "semantic";  ///< a strategy name (roomscout methods lists them)
  std::string config;               ///< YAML options file, as `roomscout explore --config`
  int seed = 1;                     ///< seeds the strategy's random choices
  std::string map_frame = "map";
  std::string base_frame = "base_link";
  std::string save_dir = "roomscout_maps";  ///< where the maps go at the end; "" = not saved
  std::string move_base = "move_base";      ///< the MoveBase action's name
  double cycle_period_s = 0.05;    ///< explore cycle period (also on every map and goal result) [s]
  double progress_timeout_s = -1;  ///< a goal whose path has not shrunk this long fails [s];
                                   ///< < 0: the config's explorer.no_progress_timeout_s
  std::string map_source = "map_server";  ///< the map's value convention (MapConvention)
  MapConvention map_convention;           ///< the source's, or ~free/occupied_threshold's
  double marker_period_s = 1.0;           ///< frontier and status publishing period [s]
  std::string plan_topic;  ///< the driver's plan (nav_msgs/Path), e.g. move_base/NavfnROS/plan:
                           ///< progress is measured along it; "" = along the Explorer's path
  double transform_tolerance_s = 0.3;  ///< an older robot pose is not used [s]
  double cloud_wait_s = 1.0;           ///< how long a point cloud waits for its transform [s]
  bool autostart = true;               ///< explore from the start; else wait for ~start or ~resume
  bool return_to_start = false;        ///< when done, drive back to where exploration started
  bool exit_when_done = false;         ///< exit (status 0) once done and the maps saved
  std::vector<std::string> warnings;   ///< former parameter names in use

  static ExploreNodeParams load(const ros::NodeHandle& pn) {
    ExploreNodeParams p;
    p.method = typedParam(pn, "method", p.method);
    p.config = typedParam(pn, "config", p.config);
    p.seed = typedParam(pn, "seed", p.seed);
    p.map_frame = typedParam(pn, "map_frame", p.map_frame);
    p.base_frame = typedParam(pn, "base_frame", p.base_frame);
    p.save_dir = typedParam(pn, "save_dir", p.save_dir);
    p.move_base = typedParam(pn, "move_base_action", p.move_base);
    p.cycle_period_s = typedParam(pn, "cycle_period_s", p.cycle_period_s);
    p.progress_timeout_s = typedParam(pn, "progress_timeout_s", p.progress_timeout_s);
    p.map_source = typedParam(pn, "map_source", p.map_source);
    p.map_convention = MapConvention::named(p.map_source);
    // Each threshold by its name, or by its former name (a whole percentage) with a warning.
    struct Threshold {
      const char* name;
      const char* former;
      double* value;
    };
    for (const Threshold& t :
         {Threshold{"free_threshold", "free_percent", &p.map_convention.free_max},
          Threshold{"occupied_threshold", "occupied_percent", &p.map_convention.occupied_min}}) {
      if (pn.hasParam(t.former)) {
        *t.value = typedParam(pn, t.former, 0);
        p.warnings.push_back(std::string("~") + t.former + " is a former name: use ~" + t.name);
      }
      *t.value = typedParam(pn, t.name, *t.value);
    }
    p.marker_period_s = typedParam(pn, "marker_period_s", p.marker_period_s);
    p.plan_topic = typedParam(pn, "plan_topic", p.plan_topic);
    p.transform_tolerance_s = typedParam(pn, "transform_tolerance", p.transform_tolerance_s);
    p.cloud_wait_s = typedParam(pn, "cloud_wait_s", p.cloud_wait_s);
    p.autostart = typedParam(pn, "autostart", p.autostart);
    p.return_to_start = typedParam(pn, "return_to_start", p.return_to_start);
    p.exit_when_done = typedParam(pn, "exit_when_done", p.exit_when_done);
    if (p.seed < 0) throw OptionError("~seed must be >= 0, not " + std::to_string(p.seed));
    if (!(p.cycle_period_s > 0.0)) throw OptionError("~cycle_period_s must be > 0");
    if (!(p.marker_period_s > 0.0)) throw OptionError("~marker_period_s must be > 0");
    if (!(p.transform_tolerance_s > 0.0)) throw OptionError("~transform_tolerance must be > 0");
    if (!(p.cloud_wait_s >= 0.0)) throw OptionError("~cloud_wait_s must be >= 0");
    p.map_convention.validate();
    return p;
  }
};

using MoveBaseClient = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;

class ExploreNode {
 public:
  ExploreNode(const ExploreNodeParams& params, io::ExplorerConfig config)
      : params_(params),
        explorer_(std::make_unique<Explorer>(std::move(config.strategy),
                                             explorerOptions(params_, config.explorer))),
        tf_listener_(tf_),
        move_base_(params_.move_base, false),
        cloud_(config.cloud_map),
        keyframes_(config.keyframes) {
    ros::NodeHandle nh, pn("~");
    map_sub_ =
        nh.subscribe("map", 1, &ExploreNode::onMap, this, ros::TransportHints().tcpNoDelay());
    map_updates_sub_ = nh.subscribe("map_updates", 10, &ExploreNode::onMapUpdate, this,
                                    ros::TransportHints().tcpNoDelay());
    // roscpp reads /clock on a thread of its own; this subscription only wakes the loop below
    // at each tick, so that with a simulator's clock every cycle comes when due.
    clock_sub_ = nh.subscribe<rosgraph_msgs::Clock>(
        "/clock", 1, [](const rosgraph_msgs::Clock::ConstPtr&) {}, ros::VoidConstPtr(),
        ros::TransportHints().tcpNoDelay());
    points_sub_ = nh.subscribe("points", 10, &ExploreNode::onPoints, this);
    resume_sub_ = pn.subscribe<std_msgs::Bool>(
        "resume", 10, [this](const std_msgs::Bool::ConstPtr& m) { m->data ? resume() : pause(); });
    if (!params_.plan_topic.empty())
      plan_sub_ = nh.subscribe(params_.plan_topic, 1, &ExploreNode::onPlan, this);
    rooms_pub_ = pn.advertise<visualization_msgs::MarkerArray>("rooms", 1, true);
    room_grid_pub_ = pn.advertise<nav_msgs::OccupancyGrid>("room_grid", 1, true);
    skeleton_pub_ = pn.advertise<visualization_msgs::MarkerArray>("skeleton", 1, true);
    frontier_pub_ = pn.advertise<visualization_msgs::Marker>("frontiers", 1, true);
    goal_pub_ = pn.advertise<visualization_msgs::Marker>("goal", 1, true);
    status_pub_ = pn.advertise<std_msgs::String>("status", 1, true);
    // Latched: a simulator that subscribes late still learns how far the explorer caught up.
    cycle_pub_ = pn.advertise<std_msgs::Time>("cycle", 10, true);
    save_srv_ = pn.advertiseService("save_maps", &ExploreNode::onSaveMaps, this);
    start_srv_ = pn.advertiseService("start", &ExploreNode::onStart, this);
    pause_srv_ = pn.advertiseService("pause", &ExploreNode::onPause, this);
    stop_srv_ = pn.advertiseService("stop", &ExploreNode::onStop, this);
    state_ = params_.autostart ? State::kExploring : State::kWaiting;
  }

  /// Runs until the node is asked to stop; exploration ending does not stop it (the maps
  /// stay published and ~save_maps keeps working).
  void run() {
    ros::CallbackQueue& queue = *ros::getGlobalCallbackQueue();
    ros::WallTime next_wait_log = ros::WallTime::now();
    while (ros::ok() && !g_stop && !move_base_.isServerConnected()) {
      queue.callAvailable(ros::WallDuration(0.05));
      if (ros::WallTime::now() >= next_wait_log) {
        ROS_INFO("waiting for the %s action server", params_.move_base.c_str());
        next_wait_log = ros::WallTime::now() + ros::WallDuration(5.0);
      }
    }
    while (ros::ok() && !g_stop) {
      queue.callAvailable(ros::WallDuration(0.01));
      const ros::Time now = ros::Time::now();
      const double t = now.toSec();
      insertPointClouds(now);
      if (state_ == State::kExploring && t > 0.0 && map_msg_ &&
          (event_ || t - last_cycle_s_ >= params_.cycle_period_s - 1e-9)) {
        try {
          cycle(t);
        } catch (const std::exception& e) {
          // A bad input (e.g. a pose or time the library refuses) costs one cycle, not the node.
          ROS_ERROR_THROTTLE(5.0, "explore cycle failed: %s", e.what());
        }
      }
      caughtUp(now);
    }
    if (goal_active_) {
      move_base_.cancelGoal();
      ros::WallDuration(0.2).sleep();  // let the cancel go out before the connection closes
      ROS_INFO("cancelled the current goal");
    }
  }

 private:
  static ExplorerOptions explorerOptions(const ExploreNodeParams& params, ExplorerOptions options) {
    if (params.progress_timeout_s >= 0.0)
      options.goals.no_progress_timeout_s = params.progress_timeout_s;
    options.all_maps = true;
    options.background_maps = false;  // markers read the maps on this thread
    options.validate();
    return options;
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    if (!params_.map_frame.empty() && !msg->header.frame_id.empty() &&
        msg->header.frame_id != params_.map_frame) {
      ROS_ERROR_THROTTLE(10.0, "map in frame '%s', expected '%s' (~map_frame): ignored",
                         msg->header.frame_id.c_str(), params_.map_frame.c_str());
      return;
    }
    map_msg_ = msg;
    map_new_ = true;
    event_ = true;
  }

  /// A patch of the last map (map_updates): applied to a copy of it, which becomes the map.
  void onMapUpdate(const map_msgs::OccupancyGridUpdate::ConstPtr& msg) {
    if (!map_msg_) return;  // nothing to patch yet
    if (!msg->header.frame_id.empty() && msg->header.frame_id != map_msg_->header.frame_id) {
      ROS_ERROR_THROTTLE(10.0, "map update in frame '%s', the map in '%s': ignored",
                         msg->header.frame_id.c_str(), map_msg_->header.frame_id.c_str());
      return;
    }
    auto patched = boost::make_shared<nav_msgs::OccupancyGrid>(*map_msg_);
    try {
      applyUpdate(*patched, *msg);
    } catch (const InvalidArgument& e) {
      ROS_ERROR_THROTTLE(10.0, "%s: ignored", e.what());
      return;
    }
    map_msg_ = patched;
    map_new_ = true;
    event_ = true;
  }

  void onPoints(const sensor_msgs::PointCloud2::ConstPtr& msg) {
    constexpr std::size_t kMaxWaiting = 50;
    pending_clouds_.push_back(msg);
    if (pending_clouds_.size() > kMaxWaiting) {
      pending_clouds_.pop_front();
      ++clouds_dropped_;
    }
  }

  /// Inserts the waiting point clouds whose transforms have arrived, in order; drops those
  /// that waited longer than ~cloud_wait_s (one warning a minute, with the count).
  void insertPointClouds(const ros::Time& now) {
    while (!pending_clouds_.empty()) {
      const sensor_msgs::PointCloud2::ConstPtr msg = pending_clouds_.front();
      const ros::Time stamp = msg->header.stamp;
      if (tf_.canTransform(params_.map_frame, params_.base_frame, stamp) &&
          tf_.canTransform(params_.map_frame, msg->header.frame_id, stamp)) {
        pending_clouds_.pop_front();
        insertPointCloud(*msg);
        continue;
      }
      if ((now - stamp).toSec() <= params_.cloud_wait_s) break;  // its transform may come
      pending_clouds_.pop_front();
      ++clouds_dropped_;
    }
    if (clouds_dropped_ > clouds_dropped_reported_) {
      ROS_WARN_THROTTLE(60.0,
                        "%ld point clouds dropped so far: no transform to '%s' within "
                        "~cloud_wait_s (%.2f s)",
                        clouds_dropped_, params_.map_frame.c_str(), params_.cloud_wait_s);
      clouds_dropped_reported_ = clouds_dropped_;
    }
  }

  void insertPointCloud(const sensor_msgs::PointCloud2& cloud) {
    Pose2 base;
    geometry_msgs::TransformStamped sensor;
    try {
      base = toPose2(
          tf_.lookupTransform(params_.map_frame, params_.base_frame, cloud.header.stamp).transform);
      sensor = tf_.lookupTransform(params_.map_frame, cloud.header.frame_id, cloud.header.stamp);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(60.0, "point cloud skipped: %s", e.what());
      return;
    }
    if (!keyframes_.accept(base)) return;
    const auto& tr = sensor.transform.translation;
    const auto& q = sensor.transform.rotation;
    const Eigen::Isometry3f T =
        Eigen::Translation3f(tr.x, tr.y, tr.z) *
        Eigen::Quaternionf(static_cast<float>(q.w), static_cast<float>(q.x),
                           static_cast<float>(q.y), static_cast<float>(q.z));
    scratch_points_.clear();
    scratch_points_.reserve(static_cast<std::size_t>(cloud.width) * cloud.height);
    sensor_msgs::PointCloud2ConstIterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
    for (; x != x.end(); ++x, ++y, ++z) scratch_points_.push_back(T * Eigen::Vector3f(*x, *y, *z));
    cloud_.insert(scratch_points_);
    cloud_top_m_ = std::max(cloud_top_m_, static_cast<double>(tr.z));
  }

  /// The driver's plan to the goal it was sent.
  void onPlan(const nav_msgs::Path::ConstPtr& msg) {
    if (!msg->header.frame_id.empty() && msg->header.frame_id != params_.map_frame) {
      ROS_ERROR_THROTTLE(10.0, "plan in frame '%s', expected '%s' (~map_frame): ignored",
                         msg->header.frame_id.c_str(), params_.map_frame.c_str());
      return;
    }
    driver_path_.waypoints_m.clear();
    for (const geometry_msgs::PoseStamped& p : msg->poses)
      driver_path_.waypoints_m.emplace_back(p.pose.position.x, p.pose.position.y);
  }

  /// The driver's plan, if it leads to the goal sent last (within kPlanEndToGoal_m).
  const Path* driverPath() const {
    constexpr double kPlanEndToGoal_m = 0.5;  // a global planner may stop short of the goal
    if (!goal_active_ || !sent_goal_ || driver_path_.waypoints_m.empty()) return nullptr;
    if ((driver_path_.waypoints_m.back() - *sent_goal_).norm() > kPlanEndToGoal_m) return nullptr;
    return &driver_path_;
  }

  void onGoalDone(const actionlib::SimpleClientGoalState& state) {
    goal_active_ = false;
    using S = actionlib::SimpleClientGoalState;
    if (state_ == State::kReturning) {
      ROS_INFO("back at the start: %s", state.toString().c_str());
      complete(ros::Time::now().toSec());
      return;
    }
    if (state == S::SUCCEEDED) {
      pending_outcome_ = GoalOutcome::kReached;
    } else if (state == S::ABORTED || state == S::REJECTED) {
      ROS_INFO("move_base gave up the goal (%s): it counts as failed", state.toString().c_str());
      pending_outcome_ = GoalOutcome::kFailed;
    }
    event_ = true;
  }

  // Start, pause, resume, stop.

  /// Starts exploring: resumes a paused exploration, or begins a new one on the current map
  /// (a new Explorer) when none runs: not started yet, stopped or done.
  void resume() {
    switch (state_) {
      case State::kPaused:
        paused_total_s_ += std::max(0.0, ros::Time::now().toSec() - paused_at_s_);
        state_ = paused_from_;
        if (state_ == State::kReturning) sendGoal(*start_pose_);
        event_ = true;
        ROS_INFO("exploration resumed");
        break;
      case State::kWaiting:
      case State::kStopped:
      case State::kDone: {
        if (state_ != State::kWaiting) {
          io::ExplorerConfig config = io::loadExplorerConfig(
              params_.method, static_cast<std::uint64_t>(params_.seed), params_.config);
          explorer_ = std::make_unique<Explorer>(std::move(config.strategy),
                                                 explorerOptions(params_, config.explorer));
          paused_total_s_ = 0.0;
          last_update_s_ = 0.0;
          start_pose_.reset();
          pending_outcome_.reset();
          published_room_updates_ = published_skeleton_updates_ = -1;
        }
        state_ = State::kExploring;
        any_changed_ = true;
        event_ = true;
        ROS_INFO("exploration started");
        break;
      }
      default:
        break;  // already exploring or returning
    }
    publishStatusNow();
  }

  /// Pauses: the current goal is cancelled at once and no new one is sent until resume().
  void pause() {
    if (state_ != State::kExploring && state_ != State::kReturning) return;
    paused_from_ = state_;
    paused_at_s_ = ros::Time::now().toSec();
    state_ = State::kPaused;
    cancelGoal();
    ROS_INFO("exploration paused");
    publishStatusNow();
  }

  /// Stops: the goal is cancelled; start() begins a new exploration.
  void stop() {
    if (state_ == State::kStopped) return;
    cancelGoal();
    state_ = State::kStopped;
    ROS_INFO("exploration stopped");
    publishStatusNow();
  }

  bool onStart(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    return answer(res, [this] { resume(); });
  }
  bool onPause(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    return answer(res, [this] { pause(); });
  }
  bool onStop(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    return answer(res, [this] { stop(); });
  }
  template <class F>
  bool answer(std_srvs::Trigger::Response& res, F action) {
    try {
      action();
      res.success = true;
      res.message = stateName();
    } catch (const std::exception& e) {
      res.success = false;
      res.message = e.what();
    }
    return true;
  }

  const char* stateName() const {
    switch (state_) {
      case State::kWaiting:
        return "waiting";
      case State::kExploring:
        return "exploring";
      case State::kPaused:
        return "paused";
      case State::kReturning:
        return "returning";
      case State::kDone:
        return "done";
      case State::kStopped:
        return "stopped";
    }
    return "";
  }

  bool onSaveMaps(std_srvs::Trigger::Request& /*req*/, std_srvs::Trigger::Response& res) {
    try {
      save();
      res.success = true;
      res.message = "maps saved to " + params_.save_dir;
    } catch (const std::exception& e) {
      res.success = false;
      res.message = e.what();
    }
    return true;
  }

  void save() {
    if (!grid_) throw InputError(params_.save_dir, "no map received yet: nothing to save");
    if (params_.save_dir.empty()) throw OptionError("~save_dir is empty: nowhere to save");
    saveMaps(params_.save_dir, *grid_, *explorer_->roomMap(), *explorer_->skeletonMap(),
             cloud_.points(), cloud_top_m_ > 0.0 ? cloud_top_m_ + 1.0 : 2.5);
  }

  /// One explore cycle: the latest map and pose to the Explorer, its command to move_base.
  void cycle(double t) {
    event_ = false;
    last_cycle_s_ = t;
    if (map_new_) {
      map_new_ = false;
      try {
        ReceivedGrid received =
            fromMsg(*map_msg_, grid_ ? &*grid_ : nullptr, params_.map_convention);
        if (received.changed) {
          changed_.unite(*received.changed);
        } else {
          any_changed_ = true;
        }
        grid_ = std::move(received.grid);
      } catch (const InvalidArgument& e) {
        ROS_ERROR_THROTTLE(10.0, "%s", e.what());
        return;
      }
    }
    if (!grid_) return;
    Pose2 robot;
    try {
      const geometry_msgs::TransformStamped pose =
          tf_.lookupTransform(params_.map_frame, params_.base_frame, ros::Time(0));
      const double age_s = t - pose.header.stamp.toSec();
      if (age_s > params_.transform_tolerance_s) {
        ROS_WARN_THROTTLE(10.0, "robot pose is %.2f s old (~transform_tolerance %.2f s): waiting",
                          age_s, params_.transform_tolerance_s);
        return;
      }
      robot = toPose2(pose.transform);
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "no robot pose: %s", e.what());
      return;
    }
    if (!start_pose_) start_pose_ = robot;
    // The Explorer's clock leaves out the pauses, so its watchdogs do not count them; a clock
    // reset (e.g. a restarted simulator) never runs it back.
    t = std::max(t - paused_total_s_, last_update_s_);
    if (pending_outcome_) {
      explorer_->report(*pending_outcome_, t);
      pending_outcome_.reset();
    }
    const std::optional<CellRect> hint =
        any_changed_ ? std::nullopt : std::optional<CellRect>(changed_);
    ExplorerInput input(*grid_, robot, t, hint);
    input.driver_path = driverPath();
    const ExplorerCommand command = explorer_->update(input);
    ++cycles_;
    last_update_s_ = t;
    any_changed_ = false;
    changed_ = CellRect{};
    reason_ = std::string(command.reason);

    switch (command.kind) {
      case ExplorerCommand::Kind::kDrive:
        if (!goal_active_ || !sent_goal_ || (*sent_goal_ - command.goal_m).norm() > 1e-6)
          sendGoal(robot, command.goal_m);
        break;
      case ExplorerCommand::Kind::kDone:
        finishExploration(t);
        return;
      default:  // kWait, kBackOff: move_base runs its own recovery behaviours
        cancelGoal();
        break;
    }
    publishMaps(t, robot);
  }

  /// Publishes ~cycle: every cycle due by `now` is done. A simulator may wait for it
  /// (roomscout_sim_node's ~sync_topic) so that its clock never runs ahead of the decisions.
  void caughtUp(const ros::Time& now) {
    // A goal sent in the cycle counts once move_base has taken it: the goal and this report
    // travel on different connections, and a simulator that read the report first would step
    // on without the goal.
    if (goal_active_ && move_base_.getState() == actionlib::SimpleClientGoalState::PENDING) return;
    if (now <= caught_up_) return;
    caught_up_ = now;
    std_msgs::Time msg;
    msg.data = now;
    cycle_pub_.publish(msg);
  }

  /// Sends a goal facing the way from the robot to it.
  void sendGoal(const Pose2& robot, const Vec2& goal_m) {
    const Vec2 d = goal_m - robot.position();
    sendGoal(Pose2{goal_m.x(), goal_m.y(), std::atan2(d.y(), d.x())});
  }

  void sendGoal(const Pose2& target) {
    const Vec2 goal_m = target.position();
    move_base_msgs::MoveBaseGoal goal;
    goal.target_pose.header.frame_id = params_.map_frame;
    goal.target_pose.header.stamp = ros::Time::now();
    goal.target_pose.pose = toPoseMsg(target);
    move_base_.sendGoal(
        goal, [this](const actionlib::SimpleClientGoalState& state,
                     const move_base_msgs::MoveBaseResultConstPtr&) { onGoalDone(state); });
    sent_goal_ = goal_m;
    goal_active_ = true;
    goal_pub_.publish(pointsMarker({goal_m}, "goal", {0.1f, 0.8f, 0.1f, 1.0f}, 0.3,
                                   params_.map_frame, goal.target_pose.header.stamp));
  }

  void cancelGoal() {
    if (!goal_active_) return;
    move_base_.cancelGoal();
    goal_active_ = false;
    sent_goal_.reset();
    goal_pub_.publish(pointsMarker({}, "goal", {}, 0.3, params_.map_frame, ros::Time::now()));
  }

  /// Exploration is over: the final rooms and skeleton, then the way home (~return_to_start)
  /// or at once the maps.
  void finishExploration(double t) {
    cancelGoal();
    explorer_->finish(*grid_);
    ROS_INFO("exploration done after %.1f s: %s", t, reason_.c_str());
    publishRoomsAndSkeleton();
    if (params_.return_to_start && start_pose_) {
      state_ = State::kReturning;
      ROS_INFO("returning to the start (%.2f, %.2f)", start_pose_->x_m, start_pose_->y_m);
      sendGoal(*start_pose_);
      publishStatusNow();
      return;
    }
    complete(t);
  }

  /// Saves the maps and reports the end.
  void complete(double t) {
    state_ = State::kDone;
    if (!params_.save_dir.empty()) {
      try {
        save();
        ROS_INFO("maps saved to %s", params_.save_dir.c_str());
      } catch (const std::exception& e) {
        ROS_ERROR("could not save the maps: %s", e.what());
      }
    }
    publishStatus(t, std::nullopt);
    if (params_.exit_when_done) {
      ROS_INFO("exiting: exploration done (~exit_when_done)");
      g_stop = true;
    }
  }

  void publishStatusNow() {
    if (grid_) publishStatus(ros::Time::now().toSec(), std::nullopt);
  }

  void publishMaps(double t, const Pose2& robot) {
    const int room_updates = static_cast<int>(explorer_->roomMap()->updateTimes_ms().size());
    const int skeleton_updates =
        static_cast<int>(explorer_->skeletonMap()->updateTimes_ms().size());
    if (room_updates != published_room_updates_ ||
        skeleton_updates != published_skeleton_updates_) {
      published_room_updates_ = room_updates;
      published_skeleton_updates_ = skeleton_updates;
      publishRoomsAndSkeleton();
    }
    if (t < next_marker_s_) return;
    next_marker_s_ = t + params_.marker_period_s;
    std::vector<Vec2> candidates = explorer_->strategy().candidateGoals();
    if (candidates.empty() && explorer_->costmap().geometry() == grid_->geometry() &&
        explorer_->costmap().lethalMask().size() == grid_->geometry().cellCount()) {
      // Strategies that keep no candidate list read frontier cells off the map: show those
      // (once the costmap follows this map; it is refreshed when the strategy decides).
      const Vec2 p = robot.position();
      for (const Cell& c : reachableFrontierCells(*grid_, explorer_->costmap(), 4, nullptr, &p)) {
        candidates.push_back(grid_->geometry().centerOf(c));
      }
    }
    const std::size_t stride = candidates.size() / 2000 + 1;
    std::vector<Vec2> shown;
    for (std::size_t i = 0; i < candidates.size(); i += stride) shown.push_back(candidates[i]);
    frontier_pub_.publish(pointsMarker(shown, "frontiers", {0.9f, 0.2f, 0.9f, 0.9f}, 0.12,
                                       params_.map_frame, ros::Time(t)));
    publishStatus(t, robot);
  }

  void publishRoomsAndSkeleton() {
    const ros::Time stamp = ros::Time::now();
    if (const SemanticMap* rooms = explorer_->roomMap()->semanticMap();
        rooms != nullptr && !rooms->labels().empty()) {
      rooms_pub_.publish(roomMarkers(*rooms, params_.map_frame, stamp));
      nav_msgs::OccupancyGrid grid;
      labelsToMsg(rooms->labels(), rooms->geometry(), grid);
      grid.header.frame_id = params_.map_frame;
      grid.header.stamp = stamp;
      room_grid_pub_.publish(grid);
    }
    skeleton_pub_.publish(
        skeletonMarkers(explorer_->skeletonMap()->topologicalMap(), params_.map_frame, stamp));
  }

  void publishStatus(double t, const std::optional<Pose2>& robot) {
    std::size_t known = 0;
    const std::uint8_t* s = grid_->stateBytes();
    const std::size_t n = grid_->geometry().cellCount();
    for (std::size_t i = 0; i < n; ++i) known += s[i] != 0;
    const double res = grid_->geometry().resolution_m();
    const SemanticMap* rooms = explorer_->roomMap()->semanticMap();
    nlohmann::json j = {
        {"time_s", t},
        {"known_area_m2", static_cast<double>(known) * res * res},
        {"current_room", robot && rooms != nullptr ? rooms->roomAt(robot->position()) : 0},
        {"rooms", rooms != nullptr ? rooms->regions().size() : 0},
        {"done", state_ == State::kDone},
        {"mode", stateName()},
        {"state", reason_},
        {"goals", explorer_->stats().goals},
        {"goal_failures", explorer_->stats().goal_failures},
        {"cycles", cycles_},
        {"method", params_.method},
    };
    if (sent_goal_) j["goal"] = {sent_goal_->x(), sent_goal_->y()};
    std_msgs::String msg;
    msg.data = j.dump();
    status_pub_.publish(msg);
  }

  /// What the node does: waits for ~start, explores, is paused, drives back to the start,
  /// is done (maps saved) or stopped.
  enum class State { kWaiting, kExploring, kPaused, kReturning, kDone, kStopped };

  ExploreNodeParams params_;
  std::unique_ptr<Explorer> explorer_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener tf_listener_;
  MoveBaseClient move_base_;
  PointCloudMap cloud_;
  KeyframeSelector keyframes_;
  std::vector<Eigen::Vector3f> scratch_points_;
  double cloud_top_m_ = 0.0;

  ros::Subscriber map_sub_, map_updates_sub_, points_sub_, clock_sub_, plan_sub_, resume_sub_;
  ros::Publisher rooms_pub_, room_grid_pub_, skeleton_pub_, frontier_pub_, goal_pub_, status_pub_,
      cycle_pub_;
  ros::ServiceServer save_srv_, start_srv_, pause_srv_, stop_srv_;

  nav_msgs::OccupancyGrid::ConstPtr map_msg_;
  bool map_new_ = false;
  std::optional<OccupancyGrid> grid_;
  CellRect changed_;
  bool any_changed_ = true;
  bool event_ = false;
  double last_cycle_s_ = 0.0, last_update_s_ = 0.0, next_marker_s_ = 0.0;
  std::optional<GoalOutcome> pending_outcome_;
  bool goal_active_ = false;
  std::optional<Vec2> sent_goal_;
  Path driver_path_;  ///< the driver's last plan (~plan_topic)
  std::string reason_;
  int published_room_updates_ = -1, published_skeleton_updates_ = -1;
  long cycles_ = 0;  ///< Explorer updates so far
  State state_ = State::kExploring;
  State paused_from_ = State::kExploring;
  double paused_at_s_ = 0.0;         ///< when the current pause began (ROS time) [s]
  double paused_total_s_ = 0.0;      ///< pauses of this exploration, left out of its clock [s]
  std::optional<Pose2> start_pose_;  ///< where this exploration began
  std::deque<sensor_msgs::PointCloud2::ConstPtr> pending_clouds_;  ///< waiting for tf
  long clouds_dropped_ = 0, clouds_dropped_reported_ = 0;
  ros::Time caught_up_;  ///< the last time published on ~cycle
};

}  // namespace
}  // namespace roomscout::ros1

int main(int argc, char** argv) {
  using namespace roomscout;
  ros::init(argc, argv, "roomscout_explore", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, ros1::onSignal);
  std::signal(SIGTERM, ros1::onSignal);
  std::unique_ptr<ros1::ExploreNode> node;
  ros1::ExploreNodeParams params;
  try {
    ros::NodeHandle pn("~");
    params = ros1::ExploreNodeParams::load(pn);
    io::ExplorerConfig config = io::loadExplorerConfig(
        params.method, static_cast<std::uint64_t>(params.seed), params.config);
    for (const std::string& w : config.warnings) ROS_WARN("%s", w.c_str());
    for (const std::string& w : params.warnings) ROS_WARN("%s", w.c_str());
    node = std::make_unique<ros1::ExploreNode>(params, std::move(config));
  } catch (const std::exception& e) {
    std::cerr << "roomscout_explore_node: " << e.what() << "\n";
    ROS_FATAL("%s", e.what());
    return 1;
  }
  ROS_INFO("exploring with %s", params.method.c_str());
  node->run();
  node.reset();
  ros::shutdown();
  return 0;
}
