// roomscout command line: one binary, one subcommand per job.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "roomscout/cli/bench_commands.hpp"
#include "roomscout/cli/map_commands.hpp"
#include "roomscout/cli/options_command.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/experiment/recorded_episode.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/pcd_io.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"

namespace roomscout::cli {
namespace {

/// A one-line progress bar on a terminal; silent when stderr is not a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(std::string label)
      : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) != 0) {}
  void update(double time_s, double max_time_s, double rate) {
    if (!enabled_) return;
    const int width = 30;
    const int filled = static_cast<int>(std::min(1.0, rate) * width);
    std::fprintf(stderr, "\r%s [%.*s%*s] explored %5.1f %%  sim %6.0f s / %.0f s", label_.c_str(),
                 filled, "##############################", width - filled, "", rate * 100.0, time_s,
                 max_time_s);
    std::fflush(stderr);
    drawn_ = true;
  }
  ~ProgressBar() {
    if (drawn_) std::fprintf(stderr, "\n");
  }

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
};

struct ExploreArgs {
  std::string world;
  std::string method = "nearest_frontier";
  std::uint64_t seed = 1;
  std::string out;
  std::string config;
  std::optional<double> max_time_s;
  std::string start;
  std::string room_labels;
  std::string pcd_format = "binary_compressed";
  double pcd_precision_m = 0.005;
  bool remove_floor = false;
};

Pose2 parseStart(const std::string& text) {
  std::stringstream s(text);
  Pose2 p;
  char c1 = 0, c2 = 0;
  if (!(s >> p.x_m >> c1 >> p.y_m >> c2 >> p.yaw_rad) || c1 != ',' || c2 != ',' || !s.eof() ||
      !std::isfinite(p.x_m) || !std::isfinite(p.y_m) || !std::isfinite(p.yaw_rad)) {
    throw OptionError("--start: expected X,Y,YAW (metres, metres, radians), got '" + text + "'");
  }
  return p;
}

int runExplore(const ExploreArgs& args) {
  // Fail before simulating anything when the output cannot be written; a run that fails
  // leaves no empty directory behind.
  io::OutputDirectory out(args.out);
  experiment::RunSettings settings;
  settings.pcd_format = io::parsePcdFormat(args.pcd_format);
  settings.pcd_precision_m = args.pcd_precision_m;
  settings.config_file = args.config;
  settings.max_time_s = args.max_time_s;
  settings.remove_floor = args.remove_floor;
  // One episode: the maps the strategy does not read are built beside it, on a second core.
  settings.background_maps = std::thread::hardware_concurrency() > 1;
  settings.validate();

  std::optional<std::filesystem::path> labels;
  if (!args.room_labels.empty()) labels = args.room_labels;
  sim::World world = sim::loadWorld(args.world, labels);
  if (!args.start.empty()) {
    world.start = parseStart(args.start);
    world.start_given = true;
  }

  experiment::EpisodeSetup setup = experiment::makeEpisodeSetup(args.method, args.seed, settings);
  for (const std::string& w : setup.warnings) std::cerr << "roomscout: warning: " << w << "\n";
  const sim::WorldModel model(world, setup.config.world);
  experiment::RecordedEpisode recorded;
  {
    ProgressBar bar(world.name + " " + args.method);
    recorded = experiment::runRecordedEpisode(
        model, setup, settings, args.out,
        [&](double t, double max_t, double rate) { bar.update(t, max_t, rate); });
  }
  const sim::EpisodeResult& result = recorded.result;

  auto fmt = [](const std::optional<double>& v, const char* unit) {
    if (!v) return std::string("never");
    return formatString("%.1f %s", *v, unit);
  };
  const std::string revisits = result.room_truth ? std::to_string(result.revisits) + " revisits"
                                                 : std::string("no ground-truth rooms");
  std::printf("%s %s seed %llu: explored %.1f %%, T98 %s, L98 %s, done %s, %s, %.2f s wall -> %s\n",
              world.name.c_str(), args.method.c_str(), static_cast<unsigned long long>(args.seed),
              result.exploration_rate * 100.0, fmt(result.t98_s, "s").c_str(),
              fmt(result.l98_m, "m").c_str(),
              result.timed_out ? "timed out" : fmt(result.t_done_s, "s").c_str(), revisits.c_str(),
              result.wall_time_s, args.out.c_str());
  out.keep();
  return 0;
}

int runWorlds() {
  std::printf("%-16s %10s %6s  %s\n", "world", "free m^2", "rooms", "description");
  for (const std::string& name : sim::builtinWorldNames()) {
    const sim::World world = sim::loadBuiltinWorld(name);
    const sim::WorldModel model(world);
    std::printf("%-16s %10.1f %6zu  %s\n", name.c_str(), model.freeArea_m2(), world.rooms.size(),
                world.description.c_str());
  }
  return 0;
}

}  // namespace
}  // namespace roomscout::cli

int main(int argc, char** argv) {
  using namespace roomscout;
  CLI::App app{"roomscout: semantic-region-aware exploration of indoor buildings"};
  app.require_subcommand(1);

  cli::ExploreArgs explore;
  auto* explore_cmd =
      app.add_subcommand("explore", "Explore one world with one method and write its maps");
  explore_cmd
      ->add_option("--world", explore.world, "built-in world name, world YAML, or map_server YAML")
      ->required();
  explore_cmd
      ->add_option("--method", explore.method, "exploration method (see `roomscout methods`)")
      ->capture_default_str();
  explore_cmd->add_option("--seed", explore.seed, "seed of every random choice (an integer >= 0)")
      ->check(CLI::Validator(
          [](std::string& text) {
            // CLI11 would wrap a negative number round into a huge unsigned seed.
            return text.find('-') == std::string::npos ? std::string()
                                                       : "must be an integer >= 0, got " + text;
          },
          "INT>=0"))
      ->capture_default_str();
  explore_cmd->add_option("--out", explore.out, "output directory")->required();
  explore_cmd->add_option("--config", explore.config,
                          "YAML file of options (see `roomscout options`)");
  explore_cmd->add_option("--max-time", explore.max_time_s, "simulated time limit [s]");
  explore_cmd->add_option("--start", explore.start,
                          "start pose X,Y,YAW [m, m, rad] for map_server worlds");
  explore_cmd->add_option("--room-labels", explore.room_labels,
                          "room label image for a map_server world");
  explore_cmd
      ->add_option("--pcd-format", explore.pcd_format,
                   "pointcloud.pcd encoding: ascii, binary, binary_compressed")
      ->capture_default_str();
  explore_cmd
      ->add_option("--pcd-precision", explore.pcd_precision_m,
                   "pointcloud.pcd coordinates rounded to multiples of this [m]; 0 = exact")
      ->capture_default_str();
  explore_cmd->add_flag(
      "--pointcloud-remove-floor", explore.remove_floor,
      "leave the floor and ceiling out of pointcloud.pcd (kept by default, as in LIO-SAM)");

  auto* worlds_cmd = app.add_subcommand("worlds", "List the built-in worlds");
  auto* methods_cmd = app.add_subcommand("methods", "List the exploration methods");
  const cli::Subcommand maps_cmd = cli::addMapsCommand(app);
  const cli::Subcommand segment_eval_cmd = cli::addSegmentEvalCommand(app);
  const cli::Subcommand slam_cmd = cli::addSlamCommand(app);
  const cli::Subcommand bench_cmd = cli::addBenchCommand(app);
  const cli::Subcommand report_cmd = cli::addReportCommand(app);
  const cli::Subcommand options_cmd = cli::addOptionsCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (explore_cmd->parsed()) return cli::runExplore(explore);
    if (worlds_cmd->parsed()) return cli::runWorlds();
    if (maps_cmd.app->parsed()) return maps_cmd.run();
    if (segment_eval_cmd.app->parsed()) return segment_eval_cmd.run();
    if (slam_cmd.app->parsed()) return slam_cmd.run();
    if (bench_cmd.app->parsed()) return bench_cmd.run();
    if (report_cmd.app->parsed()) return report_cmd.run();
    if (options_cmd.app->parsed()) return options_cmd.run();
    if (methods_cmd->parsed()) {
      for (const StrategyEntry& e : strategyRegistry())
        std::printf("%-18s %s\n", e.name.c_str(), e.description.c_str());
      return 0;
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "roomscout: error: %s\n", e.what());
    return 2;
  } catch (const OptionError& e) {
    std::fprintf(stderr, "roomscout: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomscout: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
