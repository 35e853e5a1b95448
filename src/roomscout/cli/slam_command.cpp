// `roomscout slam`: a SLAM over a recorded laser log (MRPT rawlog), with the map it makes
// beside the one odometry alone makes.

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "roomscout/cli/map_commands.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/experiment/rawlog_slam.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::cli {
namespace {

struct SlamArgs {
  std::string rawlog;
  std::string out;
  std::string config;
  std::string mode;
  std::uint64_t seed = 1;
};

int runSlam(const SlamArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  slam::SlamOptions slam_options;
  OccupancyGridOptions grid_options;
  std::vector<ParameterGroup> groups{{"slam", slam_options.parameters()},
                                     {"mapping", grid_options.parameters()}};
  if (!args.config.empty()) {
    io::applyConfigFile(args.config, groups);
    try {
      slam_options.validate();
      grid_options.validate();
    } catch (const OptionError& e) {
      throw OptionError(args.config + ": " + e.what());
    }
  }
  if (!args.mode.empty()) {
    slam_options.mode = args.mode;
    try {
      slam_options.validate();
    } catch (const OptionError& e) {
      throw OptionError(std::string("--mode: ") + e.what());
    }
  }
  if (slam_options.mode == "none") {
    throw OptionError(
        "roomscout slam needs a SLAM: give --mode or slam.mode in --config "
        "(`roomscout options` lists the modes)");
  }
  io::OutputDirectory out(args.out);  // removed again if the command fails and it is empty

  experiment::RawlogRunInfo info;
  info.rawlog = args.rawlog;
  info.seed = args.seed;
  for (const ParameterGroup& g : groups) info.options[g.name] = io::parametersToJson(g.parameters);
  const slam::Rawlog log = slam::readRawlog(args.rawlog);
  info.read_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const experiment::RawlogSlamResult result =
      experiment::runRawlogSlam(log, slam_options, grid_options, args.seed, args.rawlog);
  info.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  experiment::writeRawlogOutputs(args.out, info, log, result);

  auto metres = [](const slam::MapConsistency& c) {
    return c.mean_distance_m ? formatString("%.3f m", *c.mean_distance_m) : std::string("n/a");
  };
  std::printf(
      "%s %s seed %llu: %zu scans, %.1f s wall, update median %.2f ms p95 %.2f ms, "
      "consistency %s (odometry %s) -> %s\n",
      args.rawlog.c_str(), result.mode.c_str(), static_cast<unsigned long long>(args.seed),
      log.scans.size(), info.wall_time_s, result.update.median_ms, result.update.p95_ms,
      metres(result.slam_map.consistency).c_str(), metres(result.odometry_map.consistency).c_str(),
      args.out.c_str());
  out.keep();
  return 0;
}

}  // namespace

Subcommand addSlamCommand(CLI::App& app) {
  auto args = std::make_shared<SlamArgs>();
  CLI::App* cmd = app.add_subcommand("slam", "Run a SLAM over a recorded laser log (MRPT rawlog)");
  cmd->add_option("--rawlog", args->rawlog, "MRPT rawlog, gzip-compressed or not")->required();
  cmd->add_option("--out", args->out, "output directory")->required();
  cmd->add_option("--config", args->config, "YAML file with groups 'slam' and 'mapping'");
  cmd->add_option("--mode", args->mode, "slam.mode, over the config's (e.g. icp, rbpf)");
  cmd->add_option("--seed", args->seed, "seed of the SLAM's random choices (an integer >= 0)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  return {cmd, [args] { return runSlam(*args); }};
}

}  // namespace roomscout::cli
