#pragma once
// One episode run to the end with every output file of `roomscout explore` written (DESIGN
// "Outputs of one run"). `explore` writes one; `bench` one per (world, method, seed).

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::experiment {

struct RecordedEpisode {
  sim::EpisodeResult result;
  nlohmann::json metrics;                            ///< the content of metrics.json
  std::map<std::string, std::uintmax_t> file_bytes;  ///< size of every output file, by file name
};

/// Runs one episode of `setup` on `model` (shared read-only; it must have been built with
/// setup.config.world) and writes occupancy.pgm/.yaml, pointcloud.pcd/.png, topology.*,
/// semantic.*, trajectory.csv, run.png and, last, metrics.json into `directory` (created if
/// needed). The strategy in `setup` is used up. Calls on distinct setups and directories may
/// run in parallel threads. Throws InputError naming a file that cannot be written.
RecordedEpisode runRecordedEpisode(const sim::WorldModel& model, EpisodeSetup& setup,
                                   const RunSettings& settings,
                                   const std::filesystem::path& directory,
                                   const sim::EpisodeProgress& progress = {});

}  // namespace roomscout::experiment
