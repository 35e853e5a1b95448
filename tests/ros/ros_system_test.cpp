// The two nodes over a real rosmaster: roomscout_sim_node stands in for robot, SLAM and
// move_base; roomscout_explore_node explores with the library. Each test starts its own
// master on a free port and stops every process it started, whatever happens.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>
#include <std_srvs/Trigger.h>
#include <visualization_msgs/MarkerArray.h>
#include <nlohmann/json.hpp>

#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/io/pcd_io.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/world_source.hpp"
#include "ros_test_support.hpp"

namespace roomscout::ros1::test {
namespace {

using std::chrono::seconds;

/// The latest JSON status a node published on `topic`.
class StatusListener {
 public:
  explicit StatusListener(const std::string& topic) {
    ros::NodeHandle nh;
    sub_ = nh.subscribe<std_msgs::String>(topic, 10, [this](const std_msgs::String::ConstPtr& m) {
      last_ = nlohmann::json::parse(m->data);
    });
  }
  const std::optional<nlohmann::json>& last() const { return last_; }
  bool is(const char* key, bool value) const {
    return last_ && last_->contains(key) && (*last_)[key].is_boolean() &&
           (*last_)[key].get<bool>() == value;
  }

 private:
  ros::Subscriber sub_;
  std::optional<nlohmann::json> last_;
};

std::string simNode() { return std::string(ROOMSCOUT_ROS_PACKAGE_DIR) + "/bin/roomscout_sim_node"; }
std::string exploreNode() {
  return std::string(ROOMSCOUT_ROS_PACKAGE_DIR) + "/bin/roomscout_explore_node";
}

/// The in-process episode of `method` on small_house with the options of `config`.
sim::EpisodeResult inProcess(const std::string& method, std::uint64_t seed,
                             const std::filesystem::path& config) {
  experiment::RunSettings settings;
  settings.config_file = config;
  experiment::EpisodeSetup setup = experiment::makeEpisodeSetup(method, seed, settings);
  const sim::WorldModel model(sim::loadWorld("small_house", std::nullopt), setup.config.world);
  Explorer explorer(*setup.strategy, sim::explorerOptionsFor(model, setup.config));
  return sim::runEpisode(model, setup.config, explorer, seed);
}

/// Writes the simulator's options (a map grown as a SLAM package grows it) and the robot's (the
/// Explorer configured as the simulator configures its own, stall threshold included) into
/// `dir`; returns their paths.
std::pair<std::filesystem::path, std::filesystem::path> writeOptionFiles(
    const std::filesystem::path& dir) {
  const std::filesystem::path options = dir / "options.yaml", robot = dir / "robot.yaml";
  std::FILE* f = std::fopen(options.c_str(), "w");
  std::fprintf(f, "episode:\n  map_mode: growing\n");
  std::fclose(f);
  sim::EpisodeConfig config;
  const sim::WorldModel model(sim::loadWorld("small_house", std::nullopt), config.world);
  f = std::fopen(robot.c_str(), "w");
  std::fprintf(f, "explorer:\n  stall_min_new_area_m2: %.17g\n",
               sim::explorerOptionsFor(model, config).goals.stall_min_new_area_m2);
  std::fclose(f);
  return {options, robot};
}

TEST(RosSystem, SemanticExploresSmallHouseOverRosAsInProcess) {
  RosMaster master;
  const auto option_files = writeOptionFiles(master.dir());
  const std::filesystem::path& options = option_files.first;
  const std::filesystem::path& robot_options = option_files.second;
  const sim::EpisodeResult reference = inProcess("semantic", 1, options);
  ASSERT_TRUE(reference.t98_s && reference.l98_m);
  master.initClient("ros_system_test");
  ros::NodeHandle nh;
  ros::param::set("/use_sim_time", true);
  StatusListener sim_status("/sim/status"), explore_status("/explore/status");
  int room_labels = 0;
  ros::Subscriber rooms = nh.subscribe<visualization_msgs::MarkerArray>(
      "/explore/rooms", 10, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        int labels = 0;
        for (const auto& marker : m->markers) labels += marker.ns == "room_label";
        room_labels = std::max(room_labels, labels);
      });
  const std::filesystem::path maps = master.dir() / "maps";
  const auto wall_start = std::chrono::steady_clock::now();
  auto sim = master.node(simNode(), "sim",
                         {"_world:=small_house", "_seed:=1", "_sync_topic:=/explore/cycle",
                          "_sync_timeout_s:=0", "_points:=true", "_config:=" + options.string()});
  auto explore = master.node(exploreNode(), "explore",
                             {"_method:=semantic", "_seed:=1", "_save_dir:=" + maps.string(),
                              "_config:=" + robot_options.string()});
  const bool done = spinUntil([&] { return explore_status.is("done", true); }, seconds(400),
                              [&] { return !sim->poll() && !explore->poll(); });
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  ASSERT_TRUE(done) << "exploration did not end\n--- sim node ---\n"
                    << sim->output() << "\n--- explore node ---\n"
                    << explore->output();
  // The simulator's truth: the rate it last sampled, and when it first reached 98 %.
  spinUntil([&] { return false; }, seconds(2));
  ASSERT_TRUE(sim_status.last().has_value());
  const nlohmann::json& truth = *sim_status.last();
  EXPECT_GE(truth["rate"].get<double>(), 0.98);
  ASSERT_FALSE(truth["t98_s"].is_null());
  // The round trip over ROS explores as the in-process episode does. The lockstep waits for
  // the explorer at every step however long it takes (~sync_timeout_s 0), so the machine's
  // load cannot break it. The runs are still not identical: a goal and the explorer's report
  // that it caught up travel on different connections, so a new goal may start a step late,
  // and a map may reach the explorer after its report; a run diverges from there
  // (scripts/ros_vs_inprocess.sh measures it). Over 12 runs, quiet or beside a bench, T98 over
  // ROS came within -12 % and +12 % of the in-process 437 s (386-491 s), with the rooms updated
  // incrementally or whole alike; hence 20 %. Without the lockstep the gap is 33-50 %.
  const double t98 = truth["t98_s"].get<double>(), l98 = truth["l98_m"].get<double>();
  std::printf("in-process: T98 %.1f s, L98 %.1f m; over ROS: T98 %.1f s, L98 %.1f m, wall %.1f s\n",
              *reference.t98_s, *reference.l98_m, t98, l98, wall_s);
  EXPECT_NEAR(t98, *reference.t98_s, 0.2 * *reference.t98_s);
  EXPECT_NEAR(l98, *reference.l98_m, 0.2 * *reference.l98_m);
  for (const char* file :
       {"occupancy.pgm", "occupancy.yaml", "pointcloud.pcd", "topology.json", "topology.png",
        "semantic.json", "semantic.png", "semantic_labels.png"}) {
    EXPECT_TRUE(std::filesystem::exists(maps / file)) << file;
  }
  EXPECT_GE(room_labels, 2) << "room markers with labels were published";
  // The 3D map from the simulated VLP-16's points: walls up to the ceiling (2.5 m).
  const std::vector<Eigen::Vector3f> cloud = io::readPcd(maps / "pointcloud.pcd");
  EXPECT_GT(cloud.size(), 10000u);
  float top = 0.0f;
  for (const Eigen::Vector3f& p : cloud) top = std::max(top, p.z());
  EXPECT_NEAR(top, 2.5f, 0.1f);
  // ~save_maps writes them again on request.
  std::filesystem::remove(maps / "semantic.json");
  std_srvs::Trigger save;
  ASSERT_TRUE(ros::service::call("/explore/save_maps", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  EXPECT_TRUE(std::filesystem::exists(maps / "semantic.json"));
  // Stopped on request, the nodes exit cleanly.
  EXPECT_EQ(explore->stop(), 0) << explore->output();
  EXPECT_EQ(sim->stop(), 0) << sim->output();
}

TEST(RosSystem, GoalsAbortedNearOneSpotAreGivenUp) {
  RosMaster master;
  master.initClient("ros_abort_test");
  ros::NodeHandle nh;
  ros::param::set("/use_sim_time", true);
  StatusListener sim_status("/sim/status"), explore_status("/explore/status");
  // move_base refuses every goal within 1.6 m of a spot in small_house's living room (wide
  // enough that some goal of the run falls in it whatever the timing of the two nodes).
  auto sim = master.node(simNode(), "sim",
                         {"_world:=small_house", "_seed:=2", "_sync_topic:=/explore/cycle",
                          "_sync_timeout_s:=0", "_abort_goals_near:=[4.0, 4.0, 1.6]"});
  auto explore =
      master.node(exploreNode(), "explore", {"_method:=nearest_frontier", "_save_dir:="});
  const bool done = spinUntil([&] { return explore_status.is("done", true); }, seconds(400),
                              [&] { return !sim->poll() && !explore->poll(); });
  ASSERT_TRUE(done) << "--- sim node ---\n"
                    << sim->output() << "\n--- explore node ---\n"
                    << explore->output();
  spinUntil([&] { return false; }, seconds(2));
  ASSERT_TRUE(sim_status.last().has_value());
  EXPECT_GE((*sim_status.last())["goals_aborted"].get<int>(), 1)
      << "no goal came near the spot: move it";
  EXPECT_GE((*explore_status.last())["goal_failures"].get<int>(), 1);
  // The refused spot lies in an open room the laser sees from outside the refused disc, so
  // giving its goals up costs nothing of the map: the run still reaches 98 % (0.999 measured).
  EXPECT_GE((*sim_status.last())["rate"].get<double>(), 0.98);
}

TEST(RosSystem, StoppingTheExplorerCancelsItsGoal) {
  RosMaster master;
  master.initClient("ros_cancel_test");
  ros::NodeHandle nh;
  ros::param::set("/use_sim_time", true);
  StatusListener sim_status("/sim/status");
  auto sim = master.node(simNode(), "sim", {"_world:=small_house", "_real_time_factor:=1"});
  auto explore =
      master.node(exploreNode(), "explore", {"_method:=nearest_frontier", "_save_dir:="});
  auto field = [&](const char* key) {
    return sim_status.last() ? (*sim_status.last())[key].get<int>() : 0;
  };
  ASSERT_TRUE(spinUntil([&] { return field("goals_received") >= 1; }, seconds(60)))
      << sim->output() << explore->output();
  // At real time the first goal takes seconds to reach: it is still active when the node stops.
  const int canceled = field("goals_canceled");
  EXPECT_EQ(explore->stop(), 0) << explore->output();
  EXPECT_TRUE(spinUntil([&] { return field("goals_canceled") > canceled; }, seconds(10)))
      << sim->output();
}

TEST(RosSystem, SimNodeHonoursTheConfigsNoiseAndMapMode) {
  RosMaster master;
  master.initClient("ros_config_test");
  ros::NodeHandle nh;
  const std::filesystem::path options = master.dir() / "options.yaml";
  std::FILE* f = std::fopen(options.c_str(), "w");
  std::fputs("noise:\n  profile: harsh\nepisode:\n  map_mode: growing\n", f);
  std::fclose(f);
  std::vector<std::vector<float>> scans;
  std::optional<nav_msgs::OccupancyGrid::ConstPtr> map;
  ros::Subscriber scan_sub = nh.subscribe<sensor_msgs::LaserScan>(
      "/scan", 10, [&](const sensor_msgs::LaserScan::ConstPtr& m) { scans.push_back(m->ranges); });
  ros::Subscriber map_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; });
  // No explorer: the robot stands still while the clock runs.
  auto sim = master.node(simNode(), "sim",
                         {"_world:=small_house", "_goal_wait_s:=0", "_real_time_factor:=5",
                          "_config:=" + options.string()});
  ASSERT_TRUE(spinUntil([&] { return scans.size() >= 3 && map; }, seconds(60),
                        [&] { return !sim->poll(); }))
      << sim->output();
  // Range noise: a robot standing still sees a little differently each time.
  EXPECT_NE(scans[1], scans[2]);
  // A growing map: the known area and its margin, far less than the 188 m^2 house's extent.
  const nav_msgs::MapMetaData& info = (*map)->info;
  EXPECT_LT(info.width * info.height * info.resolution * info.resolution, 150.0)
      << info.width << " x " << info.height;
  EXPECT_EQ(sim->stop(), 0) << sim->output();
}

/// Calls the Trigger service `name`; returns its message after checking it succeeded.
std::string trigger(const std::string& name) {
  std_srvs::Trigger call;
  EXPECT_TRUE(ros::service::waitForService(name, ros::Duration(30.0))) << name;
  EXPECT_TRUE(ros::service::call(name, call)) << name;
  EXPECT_TRUE(call.response.success) << name << ": " << call.response.message;
  return call.response.message;
}

TEST(RosSystem, PauseResumeStopAndStartAgain) {
  RosMaster master;
  master.initClient("ros_pause_test");
  ros::NodeHandle nh;
  ros::param::set("/use_sim_time", true);
  StatusListener sim_status("/sim/status"), explore_status("/explore/status");
  ros::Publisher resume = nh.advertise<std_msgs::Bool>("/explore/resume", 1, true);
  auto sim = master.node(
      simNode(), "sim",
      {"_world:=small_house", "_seed:=1", "_sync_topic:=/explore/cycle", "_sync_timeout_s:=0"});
  // Not started: no goal until asked.
  auto explore = master.node(exploreNode(), "explore",
                             {"_method:=nearest_frontier", "_save_dir:=", "_autostart:=false"});
  auto dead = [&] { return !sim->poll() || !explore->poll(); };
  auto field = [&](const char* key) {
    return sim_status.last() ? (*sim_status.last())[key].get<int>() : 0;
  };
  auto mode = [&] {
    return explore_status.last() ? (*explore_status.last())["mode"].get<std::string>() : "";
  };
  auto simTime = [&] {
    return sim_status.last() ? (*sim_status.last())["time_s"].get<double>() : 0;
  };
  ASSERT_TRUE(spinUntil([&] { return simTime() > 5.0; }, seconds(60), dead)) << sim->output();
  EXPECT_EQ(field("goals_received"), 0) << "a goal before ~start";
  EXPECT_EQ(trigger("/explore/start"), "exploring");
  ASSERT_TRUE(spinUntil([&] { return field("goals_received") >= 3; }, seconds(120), dead))
      << explore->output();

  // Paused: the active goal is cancelled at once, and none follows while simulated time runs.
  resume.publish([] {
    std_msgs::Bool b;
    b.data = false;
    return b;
  }());
  ASSERT_TRUE(spinUntil([&] { return mode() == "paused"; }, seconds(30), dead));
  const int received = field("goals_received");
  const double paused_at = simTime();
  ASSERT_TRUE(spinUntil([&] { return simTime() > paused_at + 20.0; }, seconds(120), dead));
  EXPECT_EQ(field("goals_received"), received) << "a goal was sent while paused";
  EXPECT_GE(field("goals_canceled"), 1);
  resume.publish([] {
    std_msgs::Bool b;
    b.data = true;
    return b;
  }());
  ASSERT_TRUE(spinUntil([&] { return field("goals_received") > received; }, seconds(60), dead))
      << "no goal after resuming";

  // Stopped, then started again on the map so far: a new exploration that ends with the house
  // mapped.
  EXPECT_EQ(trigger("/explore/stop"), "stopped");
  EXPECT_EQ(trigger("/explore/start"), "exploring");
  ASSERT_TRUE(spinUntil([&] { return explore_status.is("done", true); }, seconds(400), dead))
      << explore->output();
  spinUntil([&] { return false; }, seconds(2));
  EXPECT_GE((*sim_status.last())["rate"].get<double>(), 0.98);
  EXPECT_EQ(mode(), "done");
  EXPECT_EQ(explore->stop(), 0) << explore->output();
  EXPECT_EQ(sim->stop(), 0) << sim->output();
}

TEST(RosSystem, ReturnsToTheStartThenSavesTheMaps) {
  RosMaster master;
  master.initClient("ros_return_test");
  ros::param::set("/use_sim_time", true);
  StatusListener sim_status("/sim/status"), explore_status("/explore/status");
  const std::filesystem::path maps = master.dir() / "maps";
  auto sim = master.node(
      simNode(), "sim",
      {"_world:=small_house", "_seed:=1", "_sync_topic:=/explore/cycle", "_sync_timeout_s:=0"});
  auto explore = master.node(
      exploreNode(), "explore",
      {"_method:=nearest_frontier", "_save_dir:=" + maps.string(), "_return_to_start:=true"});
  auto dead = [&] { return !sim->poll() || !explore->poll(); };
  ASSERT_TRUE(spinUntil([&] { return sim_status.last().has_value(); }, seconds(60), dead));
  const auto start = (*sim_status.last())["pose"];
  bool returning = false;
  ASSERT_TRUE(spinUntil(
      [&] {
        returning =
            returning || (explore_status.last() && (*explore_status.last())["mode"] == "returning");
        return explore_status.is("done", true);
      },
      seconds(400), dead))
      << explore->output();
  spinUntil([&] { return false; }, seconds(2));
  EXPECT_TRUE(returning) << "never reported returning";
  const auto end = (*sim_status.last())["pose"];
  const double dx = end[0].get<double>() - start[0].get<double>();
  const double dy = end[1].get<double>() - start[1].get<double>();
  EXPECT_LT(std::hypot(dx, dy), 0.5) << "ended at " << end << ", started at " << start;
  EXPECT_GE((*sim_status.last())["rate"].get<double>(), 0.98);
  for (const char* file : {"occupancy.pgm", "semantic.json", "topology.json"})
    EXPECT_TRUE(std::filesystem::exists(maps / file)) << file;
  EXPECT_EQ(explore->stop(), 0) << explore->output();
  EXPECT_EQ(sim->stop(), 0) << sim->output();
}

TEST(RosSystem, CartographersMapConventionExploresAsMapServers) {
  // The sim node publishes its map as Cartographer does (occupancy probabilities x 100) and the
  // explorer reads it with the thresholds a Cartographer user sets (~map_source); then the same
  // run in map_server's convention (0 / 100 / -1). Both must reach 98 %. Their T98 should agree
  // within 10 %, but runs over ROS of this setting still vary from run to run: a map message
  // may reach the explorer after its report that it caught up with the step, and the explorer
  // then decides on the previous map. Measured T98 of either convention: 399 to 539 s, seed 1
  // (the setting with the point cloud, RosSystem.SemanticExplores..., where the simulator's
  // slower steps leave the map time to arrive, stays within 1 % of the in-process run). So
  // the bound here is 50 %: with the 98 % above, it catches a convention read wrongly (most
  // free space unknown), not the 10 % target.
  RosMaster master;
  master.initClient("ros_cartographer_test");
  ros::param::set("/use_sim_time", true);
  const auto option_files = writeOptionFiles(master.dir());
  const std::filesystem::path& options = option_files.first;
  const std::filesystem::path& robot_options = option_files.second;
  auto t98In = [&](const std::string& source) {
    StatusListener sim_status("/" + source + "_sim/status"),
        explore_status("/" + source + "_explore/status");
    auto sim = master.node(
        simNode(), source + "_sim",
        {"_world:=small_house", "_seed:=1", "_sync_topic:=/" + source + "_explore/cycle",
         "_sync_timeout_s:=0", "_map_source:=" + source, "_config:=" + options.string()});
    auto explore =
        master.node(exploreNode(), source + "_explore",
                    {"_method:=semantic", "_seed:=1", "_save_dir:=", "_map_source:=" + source,
                     "_config:=" + robot_options.string()});
    const bool done = spinUntil([&] { return explore_status.is("done", true); }, seconds(400),
                                [&] { return !sim->poll() && !explore->poll(); });
    EXPECT_TRUE(done) << source << "\n" << explore->output();
    spinUntil([&] { return false; }, seconds(2));
    const nlohmann::json truth = sim_status.last().value_or(nlohmann::json::object());
    EXPECT_GE(truth.value("rate", 0.0), 0.98) << source;
    EXPECT_EQ(explore->stop(), 0) << explore->output();
    EXPECT_EQ(sim->stop(), 0) << sim->output();
    return truth.contains("t98_s") && truth["t98_s"].is_number() ? truth["t98_s"].get<double>()
                                                                 : -1.0;
  };
  const double cartographer = t98In("cartographer");
  const double map_server = t98In("map_server");
  std::printf("T98 over ROS: %.1f s in Cartographer's convention, %.1f s in map_server's\n",
              cartographer, map_server);
  ASSERT_GT(map_server, 0.0);
  EXPECT_NEAR(cartographer, map_server, 0.5 * map_server);
}

/// Runs a node that must refuse to start; returns its output after checking it exited with 1.
/// Each gets a name of its own: `_name:=value` arguments stay on the parameter server.
std::string refusedStart(const RosMaster& master, const std::string& binary,
                         std::vector<std::string> args) {
  static int count = 0;
  auto node = master.node(binary, "refused" + std::to_string(++count), std::move(args));
  const std::optional<int> status = node->wait(seconds(30));
  EXPECT_TRUE(status.has_value()) << "the node did not exit";
  EXPECT_EQ(status.value_or(-1), 1);
  return node->output();
}

TEST(RosSystem, NodesRefuseBadParametersWithAClearMessage) {
  RosMaster master;
  EXPECT_NE(refusedStart(master, exploreNode(), {"_config:=/no/such/roomscout.yaml"})
                .find("/no/such/roomscout.yaml"),
            std::string::npos);
  EXPECT_NE(refusedStart(master, exploreNode(), {"_method:=no_such_method"}).find("no_such_method"),
            std::string::npos);
  const std::filesystem::path bad = master.dir() / "bad.yaml";
  std::FILE* f = std::fopen(bad.c_str(), "w");
  std::fputs("costmap:\n  inflation_margin_m: -3\n", f);
  std::fclose(f);
  const std::string out = refusedStart(master, exploreNode(), {"_config:=" + bad.string()});
  EXPECT_NE(out.find(bad.string() + ": costmap.inflation_margin_m"), std::string::npos) << out;
  EXPECT_NE(refusedStart(master, simNode(), {"_world:=no_such_world"}).find("no_such_world"),
            std::string::npos);
  // An unknown map source: the known ones listed.
  const std::string source = refusedStart(master, exploreNode(), {"_map_source:=hector"});
  EXPECT_NE(source.find("hector"), std::string::npos) << source;
  EXPECT_NE(source.find("cartographer"), std::string::npos) << source;
  EXPECT_NE(refusedStart(master, exploreNode(), {"_free_threshold:=70.0"}).find("free_threshold"),
            std::string::npos);
  EXPECT_NE(refusedStart(master, simNode(), {"_map_source:=costmap"}).find("costmap"),
            std::string::npos);
  // A parameter of the wrong type is refused, not replaced by its default.
  EXPECT_NE(refusedStart(master, exploreNode(), {"_seed:=abc"}).find("~seed must be an integer"),
            std::string::npos);
}

/// Output of a command run to its end (stdout and stderr).
std::string commandOutput(const std::string& command) {
  std::string out;
  if (std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    ::pclose(pipe);
  }
  return out;
}

TEST(RosSystem, SimExploreLaunchEndsByItselfOnceExplorationIsDone) {
  RosMaster master;
  std::map<std::string, std::string> env = master.env();
  env["ROS_PACKAGE_PATH"] = std::filesystem::path(ROOMSCOUT_ROS_PACKAGE_DIR).parent_path().string();
  const std::filesystem::path maps = master.dir() / "maps";
  ChildProcess launch(
      {"/usr/bin/roslaunch", "roomscout", "sim_explore.launch", "world:=small_house",
       "method:=nearest_frontier", "points:=false", "save_dir:=" + maps.string()},
      env, master.dir() / "roslaunch.log");
  const std::optional<int> status = launch.wait(seconds(600));
  ASSERT_TRUE(status.has_value()) << "the launch did not end\n" << launch.output();
  EXPECT_EQ(*status, 0) << launch.output();
  EXPECT_TRUE(std::filesystem::exists(maps / "occupancy.pgm")) << launch.output();
}

TEST(RosSystem, LaunchFileStartsBothNodesFromThePackageFolder) {
  const std::string env = "ROS_PACKAGE_PATH=" +
                          std::filesystem::path(ROOMSCOUT_ROS_PACKAGE_DIR).parent_path().string() +
                          " ROS_HOME=" + std::filesystem::temp_directory_path().string() + " ";
  const std::string nodes =
      commandOutput(env + "/usr/bin/roslaunch --nodes roomscout sim_explore.launch");
  EXPECT_NE(nodes.find("/sim"), std::string::npos) << nodes;
  EXPECT_NE(nodes.find("/explore"), std::string::npos) << nodes;
  const std::string args =
      commandOutput(env + "/usr/bin/roslaunch --args /explore roomscout sim_explore.launch");
  EXPECT_NE(args.find(exploreNode()), std::string::npos) << args;
  const std::string robot =
      commandOutput(env + "/usr/bin/roslaunch --nodes roomscout explore.launch");
  EXPECT_NE(robot.find("/explore"), std::string::npos) << robot;
  EXPECT_EQ(robot.find("/sim"), std::string::npos) << robot;
}

}  // namespace
}  // namespace roomscout::ros1::test
