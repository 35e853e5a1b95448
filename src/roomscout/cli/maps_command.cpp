// `roomscout maps`: topology and rooms of an existing occupancy map (slam_toolbox,
// Cartographer, or one saved by `explore`).

#include <chrono>
#include <cstdio>
#include <memory>

#include "roomscout/cli/map_commands.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/io/options_yaml.hpp"
#include "roomscout/io/semantic_io.hpp"
#include "roomscout/io/topology_io.hpp"
#include "roomscout/maps/grid_image.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace roomscout::cli {
namespace {

struct MapsArgs {
  std::string map;
  std::string out;
  std::string config;
};

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

int runMaps(const MapsArgs& args) {
  const OccupancyGrid grid = io::loadOccupancyMap(args.map);
  RoomSegmenterOptions seg_options;
  TopologyBuilderOptions topo_options;
  if (!args.config.empty()) {
    std::vector<ParameterGroup> groups{{"segmentation", seg_options.parameters()},
                                       {"topology", topo_options.parameters()}};
    io::applyConfigFile(args.config, groups);
  }
  const RoomSegmenter segmenter(seg_options);
  const TopologyBuilder builder(topo_options);
  io::OutputDirectory out(args.out);  // removed again if the command fails and it is empty

  const cv::Mat states = maps::stateImage(grid);
  auto t0 = std::chrono::steady_clock::now();
  const RoomSegmentation seg = segmenter.segment(states, grid.geometry().resolution_m());
  SemanticMap semantic;
  semantic.update(grid.geometry(), seg.labels, states);
  const double semantic_ms = msSince(t0);
  t0 = std::chrono::steady_clock::now();
  const TopologicalMap topology = builder.build(states, grid.geometry(), &semantic);
  const double topology_ms = msSince(t0);

  io::writeTopologicalMap(args.out, topology, grid);
  io::writeSemanticMap(args.out, semantic, grid);
  std::printf("%s: %zu rooms (%.1f ms), %zu nodes, %zu edges (%.1f ms) -> %s\n", args.map.c_str(),
              semantic.regions().size(), semantic_ms, topology.nodes().size(),
              topology.edges().size(), topology_ms, args.out.c_str());
  out.keep();
  return 0;
}

}  // namespace

Subcommand addMapsCommand(CLI::App& app) {
  auto args = std::make_shared<MapsArgs>();
  CLI::App* cmd =
      app.add_subcommand("maps", "Build topological and semantic maps of an occupancy map");
  cmd->add_option("--map", args->map, "map_server YAML (PGM/PNG image beside it)")->required();
  cmd->add_option("--out", args->out, "output directory")->required();
  cmd->add_option("--config", args->config, "YAML file with groups 'segmentation' and 'topology'");
  return {cmd, [args] { return runMaps(*args); }};
}

}  // namespace roomscout::cli
