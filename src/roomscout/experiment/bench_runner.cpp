#include "roomscout/experiment/bench_runner.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include <opencv2/core/utility.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/build_info.hpp"
#include "roomscout/experiment/recorded_episode.hpp"
#include "roomscout/experiment/result_record.hpp"
#include "roomscout/experiment/results_file.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/sim/start_pose.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"

namespace roomscout::experiment {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A world's model, built by the first episode that needs it and released after the last;
/// with random starts also one model per seed, started where randomStartPose() puts it.
struct WorldSlot {
  const BenchWorld* world = nullptr;
  std::mutex mutex;
  std::shared_ptr<const sim::WorldModel> model;
  std::map<std::uint64_t, std::shared_ptr<const sim::WorldModel>> started;  ///< by seed
  std::size_t pending = 0;  ///< episodes of this run still to finish on it

  std::shared_ptr<const sim::WorldModel> acquire(const sim::WorldModelOptions& options,
                                                 bool random_start, std::uint64_t seed) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!model) {
      sim::World w = sim::loadWorld(world->spec);
      w.name = world->name;  // a world file is named by its stem in a bench
      model = std::make_shared<const sim::WorldModel>(w, options);
    }
    if (!random_start) return model;
    std::shared_ptr<const sim::WorldModel>& m = started[seed];
    if (!m) {
      sim::World w = model->world();
      w.start = sim::randomStartPose(*model, seed);
      w.start_given = true;
      m = std::make_shared<const sim::WorldModel>(w, options);
    }
    return m;
  }
  void release() {
    const std::lock_guard<std::mutex> lock(mutex);
    if (--pending == 0) {
      model.reset();
      started.clear();
    }
  }
};

/// Sets OpenCV's thread count for the lifetime of the object: bench episodes run one thread
/// each, the parallelism is across episodes.
class OpenCvThreads {
 public:
  explicit OpenCvThreads(int n) : previous_(cv::getNumThreads()) { cv::setNumThreads(n); }
  ~OpenCvThreads() { cv::setNumThreads(previous_); }
  OpenCvThreads(const OpenCvThreads&) = delete;
  OpenCvThreads& operator=(const OpenCvThreads&) = delete;

 private:
  int previous_;
};

void removeEmptyDirectory(const fs::path& p) {
  std::error_code ec;
  fs::remove(p, ec);  // fails, harmlessly, when another episode still uses it
}

/// Removes `root` and the folders below it that hold no file, deepest first.
void removeEmptyFolders(const fs::path& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return;
  std::vector<fs::path> folders;
  for (auto it = fs::recursive_directory_iterator(root, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec)) folders.push_back(it->path());
  }
  for (auto it = folders.rbegin(); it != folders.rend(); ++it) removeEmptyDirectory(*it);
  removeEmptyDirectory(root);
}

}  // namespace

BenchSummary runBench(const BenchOptions& options,
                      const std::function<void(const BenchProgress&)>& on_progress) {
  const Clock::time_point start = Clock::now();
  if (options.jobs < 1)
    throw OptionError("--jobs must be >= 1, got " + std::to_string(options.jobs));
  options.settings.validate();
  const std::vector<BenchWorld> worlds = expandWorlds(options.worlds);
  // Every method and the config file are checked before anything runs.
  for (const std::string& m : options.methods) {
    const EpisodeSetup setup = makeEpisodeSetup(m, 1, options.settings);
    if (m != options.methods.front()) continue;
    for (const std::string& w : setup.warnings) std::cerr << "roomscout: warning: " << w << "\n";
  }
  std::vector<std::string> names;
  for (const BenchWorld& w : worlds) names.push_back(w.name);
  const std::vector<EpisodeKey> plan =
      planEpisodes(names, options.methods, options.seeds, options.shard);

  io::ensureWritableDirectory(options.out);
  io::removeStaleTempFiles(options.out);  // left by a killed bench
  std::error_code exists_ec;
  const bool results_existed = fs::exists(options.out / "results.jsonl", exists_ec);
  ResultsFile results(options.out / "results.jsonl");
  // Episodes from the worlds' starts and from random ones are different experiments that
  // share keys: one results file holds one kind.
  const std::string start_mode = options.random_starts ? "random" : "world";
  for (const auto& [mode, where] : results.startModes()) {
    if (mode != start_mode) {
      throw OptionError(where + ": recorded with start_mode '" + mode + "', this bench uses '" +
                        start_mode + "' (" +
                        (options.random_starts ? "--random-starts" : "no --random-starts") +
                        "): use another --out");
    }
  }
  const fs::path scratch_root = options.out / ".scratch";
  std::vector<EpisodeKey> pending;
  for (const EpisodeKey& k : plan) {
    if (!results.recorded().count(k)) {
      pending.push_back(k);
    } else {
      // A bench killed between recording an episode and removing its scratch files.
      std::error_code ec;
      fs::remove_all(scratch_root / k.world / k.method / ("seed" + std::to_string(k.seed)), ec);
    }
  }

  std::map<std::string, std::unique_ptr<WorldSlot>> slots;
  for (const BenchWorld& w : worlds) {
    auto slot = std::make_unique<WorldSlot>();
    slot->world = &w;
    slots.emplace(w.name, std::move(slot));
  }
  for (const EpisodeKey& k : pending) ++slots.at(k.world)->pending;

  BenchSummary summary;
  summary.results = results.path();
  summary.dropped_truncated_line = results.droppedTruncatedLine();
  summary.progress.planned = plan.size();
  summary.progress.skipped = plan.size() - pending.size();

  std::mutex mutex;  // guards progress, first_error, finished_workers
  std::condition_variable changed;
  BenchProgress progress = summary.progress;
  std::exception_ptr first_error;
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> next{0};
  std::size_t finished_workers = 0;
  const std::string version(gitRevision());
  const std::string host = hostName();

  const auto work = [&]() {
    while (!stop.load()) {
      const std::size_t i = next.fetch_add(1);
      if (i >= pending.size()) break;
      const EpisodeKey& key = pending[i];
      {
        const std::lock_guard<std::mutex> lock(mutex);
        ++progress.running;
      }
      // The lowest seed keeps explore's outputs, for the report's figures.
      const bool keep_outputs = key.seed == static_cast<std::uint64_t>(options.seeds.first);
      const fs::path relative = fs::path(keep_outputs ? "runs" : ".scratch") / key.world /
                                key.method / ("seed" + std::to_string(key.seed));
      const fs::path dir = options.out / relative;
      WorldSlot& slot = *slots.at(key.world);
      bool acquired = false;
      bool recorded = false;
      try {
        EpisodeSetup setup = makeEpisodeSetup(key.method, key.seed, options.settings);
        const std::shared_ptr<const sim::WorldModel> model =
            slot.acquire(setup.config.world, options.random_starts, key.seed);
        acquired = true;
        // The folder of an episode not recorded yet holds at most what a killed bench left
        // of it (files of an unfinished episode, temporary files): start afresh.
        fs::remove_all(dir);
        const RecordedEpisode episode = runRecordedEpisode(*model, setup, options.settings, dir);
        slot.release();
        acquired = false;
        const RecordContext context{version, host, utcTimestamp(),
                                    keep_outputs ? relative.generic_string() : "", start_mode};
        results.append(makeResultRecord(*slot.world, episode, context));
        recorded = true;
      } catch (...) {
        if (acquired) slot.release();
        const std::lock_guard<std::mutex> lock(mutex);
        if (!first_error) first_error = std::current_exception();
        stop = true;
      }
      if (!keep_outputs) {
        std::error_code ec;
        // Only the episode's own folder: removing its emptied parents here raced with another
        // worker creating a sibling under them ("cannot create directory"); the empty
        // parents go once every worker has finished.
        fs::remove_all(dir, ec);
      }
      {
        const std::lock_guard<std::mutex> lock(mutex);
        --progress.running;
        if (recorded) ++progress.done;
      }
      changed.notify_all();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    ++finished_workers;
    changed.notify_all();
  };

  const std::size_t workers =
      std::min<std::size_t>(static_cast<std::size_t>(options.jobs), pending.size());
  {
    const OpenCvThreads single_threaded(1);
    std::vector<std::jthread> threads;
    for (std::size_t t = 0; t < workers; ++t) threads.emplace_back(work);
    std::unique_lock<std::mutex> lock(mutex);
    std::size_t reported_done = static_cast<std::size_t>(-1);
    while (true) {
      const bool all_finished = finished_workers == workers;
      progress.elapsed_s = secondsSince(start);
      if (progress.done > 0 && progress.done < pending.size()) {
        progress.remaining_s = progress.elapsed_s *
                               static_cast<double>(pending.size() - progress.done) /
                               static_cast<double>(progress.done);
      } else if (progress.done == pending.size()) {
        progress.remaining_s = 0.0;
      }
      if (on_progress) {
        const BenchProgress snapshot = progress;
        lock.unlock();
        on_progress(snapshot);
        lock.lock();
      }
      reported_done = progress.done;
      if (all_finished) break;
      changed.wait_for(lock, std::chrono::seconds(1), [&] {
        return finished_workers == workers || progress.done != reported_done;
      });
    }
    lock.unlock();
    threads.clear();  // joins
  }
  removeEmptyFolders(scratch_root);
  if (first_error) {
    // A bench that fails (a world too large, say) leaves no empty results file or runs/
    // folders of its own behind, so the command's output directory goes if it made it.
    removeEmptyFolders(options.out / "runs");
    std::error_code ec;
    if (!results_existed && progress.done == 0 && fs::file_size(results.path(), ec) == 0 && !ec)
      fs::remove(results.path(), ec);
    std::rethrow_exception(first_error);
  }
  summary.progress = progress;
  return summary;
}

}  // namespace roomscout::experiment
