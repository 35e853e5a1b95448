// The two nodes over a real rosmaster: roomscout_sim_node stands in for robot, SLAM and
// move_base; roomscout_explore_node explores with the library. Each test starts its own
// master on a free port and stops every process it started, whatever happens.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
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

TEST(RosSystem, SemanticExploresSmallHouseOverRosAsInProcess) {
  RosMaster master;
  // The simulator's options (a map grown as SLAM grows it), and the robot's: the Explorer
  // configured as the simulator configures its own, stall threshold included.
  const std::filesystem::path options = master.dir() / "options.yaml";
  const std::filesystem::path robot_options = master.dir() / "robot.yaml";
  {
    std::FILE* f = std::fopen(options.c_str(), "w");
    std::fprintf(f, "episode:\n  map_mode: growing\n");
    std::fclose(f);
    sim::EpisodeConfig config;
    const sim::WorldModel model(sim::loadWorld("small_house", std::nullopt), config.world);
    const double stall = sim::explorerOptionsFor(model, config).goals.stall_min_new_area_m2;
    f = std::fopen(robot_options.c_str(), "w");
    std::fprintf(f, "explorer:\n  stall_min_new_area_m2: %.17g\n", stall);
    std::fclose(f);
  }
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
                          "_points:=true", "_config:=" + options.string()});
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
  // The round trip over ROS (lockstep) explores as the in-process episode does. The runs are
  // not identical: the nodes' messages may arrive a step apart, and a run diverges from there
  // (within 3 % on seeds 1-3 on a quiet machine, up to 17 % with other tests running beside
  // it; scripts/ros_vs_inprocess.sh measures it). Without the lockstep the gap is 33-50 %:
  // this bound catches that, not the 10 % target.
  const double t98 = truth["t98_s"].get<double>(), l98 = truth["l98_m"].get<double>();
  std::printf("in-process: T98 %.1f s, L98 %.1f m; over ROS: T98 %.1f s, L98 %.1f m, wall %.1f s\n",
              *reference.t98_s, *reference.l98_m, t98, l98, wall_s);
  EXPECT_NEAR(t98, *reference.t98_s, 0.3 * *reference.t98_s);
  EXPECT_NEAR(l98, *reference.l98_m, 0.3 * *reference.l98_m);
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
                          "_abort_goals_near:=[4.0, 4.0, 1.6]"});
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
  EXPECT_GE((*sim_status.last())["rate"].get<double>(), 0.9);
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
