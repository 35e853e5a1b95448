#pragma once
// `roomscout bench`: every (world, method, seed) episode of a plan, several at a time, each
// appended to DIR/results.jsonl as it finishes. A rerun with the same arguments skips the
// episodes already recorded, so an interrupted bench resumes where it stopped.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "roomscout/experiment/bench_plan.hpp"
#include "roomscout/experiment/episode_key.hpp"
#include "roomscout/experiment/episode_setup.hpp"

namespace roomscout::experiment {

struct BenchOptions {
  std::vector<std::string> worlds;   ///< built-in names, world/map_server YAML files, folders
  std::vector<std::string> methods;  ///< registered strategy names
  SeedRange seeds;                   ///< the seeds of every world x method
  int jobs = 1;                      ///< episodes run at a time (each on one thread)
  std::filesystem::path out;         ///< bench directory: results.jsonl, runs/, tables
  Shard shard;                       ///< the slice of the episode list this process runs
  RunSettings settings;              ///< config file, time limit, PCD options of every episode
  bool random_starts = false;        ///< each seed starts where sim::randomStartPose() puts it
                                     ///< (the same pose for every method); false: the world's
                                     ///< own start. A results file holds one kind only.
};

/// How far a bench has come, for a progress display.
struct BenchProgress {
  std::size_t planned = 0;  ///< episodes of this shard
  std::size_t skipped = 0;  ///< already in results.jsonl when the bench started
  std::size_t done = 0;     ///< finished by this bench
  std::size_t running = 0;  ///< being simulated now
  double elapsed_s = 0.0;   ///< wall time since this bench started
  /// Estimated wall time until every pending episode is done, from the rate at which
  /// episodes finished so far; nullopt before the first one finishes.
  std::optional<double> remaining_s;
};

struct BenchSummary {
  BenchProgress progress;
  std::filesystem::path results;  ///< DIR/results.jsonl
  bool dropped_truncated_line = false;
};

/// Runs the episodes of `options` that results.jsonl does not hold yet, `jobs` at a time.
/// Each episode is independent and single-threaded: worlds are loaded once and their models
/// shared read-only by the episodes that run on them; each record depends only on its inputs
/// and seed, so results do not depend on `jobs`. The lowest seed (1) of each world x method
/// keeps the full outputs of `explore` in DIR/runs/<world>/<method>/seed1/; other episodes
/// write theirs to a scratch folder (for the file sizes) that is removed.
/// `on_progress` is called on the caller's thread about once a second and after every
/// episode. The first error of an episode (e.g. a malformed world file) stops the bench:
/// episodes already running finish and are recorded, then the error is rethrown. Bad options
/// throw OptionError/InputError before any episode runs.
BenchSummary runBench(const BenchOptions& options,
                      const std::function<void(const BenchProgress&)>& on_progress = {});

}  // namespace roomscout::experiment
