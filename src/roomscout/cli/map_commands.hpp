#pragma once
// Subcommands that build or score maps outside an episode: `maps`, `segment-eval` and `slam`.

#include <functional>

#include <CLI/CLI.hpp>

namespace roomscout::cli {

/// A registered subcommand and what to run once it was parsed (errors propagate as the
/// typed exceptions main() reports).
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// `roomscout maps --map FILE.yaml --out DIR`: topological and semantic maps of any
/// map_server occupancy map.
Subcommand addMapsCommand(CLI::App& app);

/// `roomscout segment-eval --dataset DIR --out DIR`: the room segmentation benchmark.
Subcommand addSegmentEvalCommand(CLI::App& app);

/// `roomscout slam --rawlog FILE --out DIR [--config YAML] [--mode M] [--seed N]`: a SLAM over
/// a recorded laser log, its map beside the odometry's, and how well each fits the scans.
Subcommand addSlamCommand(CLI::App& app);

}  // namespace roomscout::cli
