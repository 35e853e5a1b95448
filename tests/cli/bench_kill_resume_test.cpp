// `roomscout bench` killed with SIGKILL at random moments and resumed with the same command:
// no episode is lost or recorded twice, every results line parses, the outputs and tables
// are whole, and the records equal those of an uninterrupted run. The moments are events of
// the run (a record written, an episode's outputs appearing, a report file appearing), not
// times, so a busy machine moves them no more than a quiet one.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/temp_dir.hpp"
#include "roomscout/experiment/result_record.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

const std::vector<std::string> kWorlds = {"small_house"};
const std::vector<std::string> kMethods = {"nearest_frontier", "mmpf"};
constexpr int kSeeds = 6;

/// How one child run ended.
struct Outcome {
  bool killed = false;  ///< ended by our SIGKILL
  int exit_code = -1;   ///< when it exited by itself
  double seconds = 0.0;
};

using roomscout::test::readText;

class BenchKillResumeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("roomscout_kill_resume_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  static std::vector<std::string> benchArgs(const fs::path& out, int seeds = kSeeds) {
    std::string worlds, methods;
    for (const std::string& w : kWorlds) worlds += (worlds.empty() ? "" : ",") + w;
    for (const std::string& m : kMethods) methods += (methods.empty() ? "" : ",") + m;
    return {"bench",
            "--worlds",
            worlds,
            "--methods",
            methods,
            "--seeds",
            std::to_string(seeds),
            "--jobs",
            "2",
            "--max-time",
            "20",
            "--out",
            out.string()};
  }

  /// Runs roomscout with `args`, output appended to log.txt. With `kill_when`, polled every
  /// millisecond from the start, sends SIGKILL `then_s` after it first holds (if the run has
  /// not ended by itself by then).
  Outcome run(const std::vector<std::string>& args, const std::function<bool()>& kill_when = {},
              double then_s = 0.0) {
    std::vector<std::string> all = {ROOMSCOUT_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log = (dir_ / "log.txt").string();
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    const Clock::time_point start = Clock::now();
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
      ADD_FAILURE() << "cannot start " << argv[0] << ": " << std::strerror(spawned);
      return {};
    }
    Outcome outcome;
    int status = 0;
    if (kill_when) {
      // Poll so that a run that ends early is seen; the child stays a zombie until reaped,
      // so its pid cannot be reused before the kill.
      const auto ended = [&] {
        siginfo_t info{};
        return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
               info.si_pid == pid;
      };
      bool event = false;
      while (!ended()) {
        if (kill_when()) {
          event = true;
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      if (event) {
        std::this_thread::sleep_for(std::chrono::duration<double>(then_s));
        ::kill(pid, SIGKILL);
      }
    }
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    outcome.killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return outcome;
  }

  std::string log() const { return readText(dir_ / "log.txt"); }

  /// The complete lines of results.jsonl (each must parse) and whether a torn last line
  /// (no newline) follows them.
  static std::vector<nlohmann::json> completeRecords(const fs::path& bench, bool& torn_tail) {
    std::vector<nlohmann::json> records;
    torn_tail = false;
    const std::string text = readText(bench / "results.jsonl");
    std::size_t begin = 0;
    while (begin < text.size()) {
      const std::size_t end = text.find('\n', begin);
      if (end == std::string::npos) {
        torn_tail = true;
        break;
      }
      const std::string line = text.substr(begin, end - begin);
      begin = end + 1;
      if (line.empty()) continue;
      try {
        records.push_back(nlohmann::json::parse(line));
      } catch (const nlohmann::json::parse_error& e) {
        ADD_FAILURE() << bench / "results.jsonl"
                      << ": a complete line does not parse: " << e.what() << "\n"
                      << line;
      }
    }
    return records;
  }

  static std::string key(const nlohmann::json& r) {
    return r.at("world").get<std::string>() + "/" + r.at("method").get<std::string>() + "/" +
           std::to_string(r.at("seed").get<int>());
  }

  static std::set<std::string> expectedKeys(int seeds = kSeeds) {
    std::set<std::string> keys;
    for (const std::string& w : kWorlds) {
      for (const std::string& m : kMethods) {
        for (int s = 1; s <= seeds; ++s) keys.insert(w + "/" + m + "/" + std::to_string(s));
      }
    }
    return keys;
  }

  /// What must hold after any kill: complete lines parse, name planned episodes, and none twice.
  static void expectConsistent(const fs::path& bench, const std::string& when, int seeds = kSeeds) {
    SCOPED_TRACE(when);
    bool torn = false;
    const std::set<std::string> expected = expectedKeys(seeds);
    std::set<std::string> seen;
    for (const nlohmann::json& r : completeRecords(bench, torn)) {
      const std::string k = key(r);
      EXPECT_TRUE(expected.count(k)) << "unplanned record " << k;
      EXPECT_TRUE(seen.insert(k).second) << "recorded twice: " << k;
    }
  }

  /// What a bench folder holds: complete records and episode folders (runs/ and .scratch/,
  /// world/method/seedN).
  struct Snapshot {
    std::size_t records = 0;
    std::set<std::string> episode_dirs;
  };
  static Snapshot snapshot(const fs::path& bench) {
    Snapshot s;
    std::error_code ec;
    if (fs::exists(bench / "results.jsonl", ec)) {
      // Complete lines only; a line being written is not counted yet.
      const std::string text = readText(bench / "results.jsonl");
      s.records = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    }
    for (const char* root : {"runs", ".scratch"}) {
      for (auto it = fs::recursive_directory_iterator(bench / root, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it.depth() == 2) s.episode_dirs.insert(it->path().string());
      }
      ec.clear();
    }
    return s;
  }
  /// The files at the top of a bench folder and when each was last written.
  static std::map<std::string, fs::file_time_type> topFileTimes(const fs::path& bench) {
    std::map<std::string, fs::file_time_type> times;
    std::error_code ec;
    for (auto it = fs::directory_iterator(bench, ec); !ec && it != fs::directory_iterator();
         it.increment(ec)) {
      const fs::file_time_type t = it->last_write_time(ec);
      if (!ec && it->is_regular_file(ec)) times[it->path().filename().string()] = t;
      ec.clear();
    }
    return times;
  }

  fs::path dir_;
};

TEST_F(BenchKillResumeTest, KilledAtRandomMomentsAndResumedLosesAndRepeatsNothing) {
  // One uninterrupted run: the reference records, and how long a run takes; the same
  // command again finds everything recorded and only rewrites the report.
  const fs::path reference = dir_ / "reference";
  const Outcome whole = run(benchArgs(reference));
  ASSERT_EQ(whole.exit_code, 0) << log();
  const Outcome report_only = run(benchArgs(reference));
  ASSERT_EQ(report_only.exit_code, 0) << log();
  bool torn = false;
  std::map<std::string, nlohmann::json> expected;
  for (const nlohmann::json& r : completeRecords(reference, torn))
    expected[key(r)] = roomscout::experiment::withoutTimingFields(r);
  ASSERT_EQ(expected.size(), expectedKeys().size()) << log();

  // Each kill comes at an event of what the run has left to do, drawn at random: while
  // episodes are left, the k-th record it writes or the k-th episode whose outputs appear;
  // then the k-th file of the report. A few milliseconds after the event, so the kill lands
  // anywhere in what follows it (the next episode, moving outputs, the next table). Some runs
  // are killed a few milliseconds after they start, before anything is written.
  // ROOMSCOUT_KILL_SEED picks other moments (for hunting a rare failure by hand).
  const char* seed_text = std::getenv("ROOMSCOUT_KILL_SEED");
  std::mt19937 rng(seed_text ? static_cast<unsigned>(std::stoul(seed_text)) : 44u);
  std::uniform_real_distribution<double> after_event(0.0, 0.02);
  std::uniform_real_distribution<double> at_once(0.001, 0.03);
  const std::vector<bool> quick = {true, false, false, true, false, false, false, true};
  const fs::path bench = dir_ / "bench";
  int kills = 0;
  for (std::size_t i = 0; i < quick.size(); ++i) {
    const Snapshot before = snapshot(bench);
    const std::size_t left = expected.size() - std::min(expected.size(), before.records);
    // Quick kills: a few milliseconds after the start, before the run has written anything.
    const double soon_s = at_once(rng);
    std::function<bool()> event = [start = Clock::now(), soon_s] {
      return std::chrono::duration<double>(Clock::now() - start).count() >= soon_s;
    };
    std::string what = "at once";
    if (!quick[i] && left > 0) {
      const std::size_t k = std::uniform_int_distribution<std::size_t>(1, left)(rng);
      if (std::uniform_int_distribution<int>(0, 1)(rng) == 0) {
        what = "record " + std::to_string(k) + " of " + std::to_string(left);
        event = [&bench, k, n = before.records] { return snapshot(bench).records >= n + k; };
      } else {
        // A scratch folder may come and go between two polls: the episode's record, written
        // after its outputs, fires the event then.
        what = "episode outputs " + std::to_string(k) + " of " + std::to_string(left);
        auto seen = std::make_shared<std::set<std::string>>();
        event = [&bench, k, seen, before] {
          const Snapshot now = snapshot(bench);
          for (const std::string& d : now.episode_dirs)
            if (!before.episode_dirs.count(d)) seen->insert(d);
          return seen->size() >= k || now.records >= before.records + k;
        };
      }
    } else if (!quick[i]) {
      const std::size_t k = std::uniform_int_distribution<std::size_t>(1, 3)(rng);
      what = "report file " + std::to_string(k);
      // The report rewrites its files: a file is written once its time differs from before.
      const std::map<std::string, fs::file_time_type> old_times = topFileTimes(bench);
      event = [&bench, k, old_times] {
        std::size_t written = 0;
        for (const auto& [name, time] : topFileTimes(bench)) {
          const auto old = old_times.find(name);
          written += name != "results.jsonl" && (old == old_times.end() || old->second != time);
        }
        return written >= k;
      };
    }
    const double then_s = quick[i] ? 0.0 : after_event(rng);
    const Outcome o = run(benchArgs(bench), event, then_s);
    const std::string when =
        "run " + std::to_string(i + 1) + ", kill " + what + " + " + std::to_string(then_s) + " s";
    bool torn_now = false;
    const std::size_t recorded =
        fs::exists(bench / "results.jsonl") ? completeRecords(bench, torn_now).size() : 0;
    std::printf("%s: %s after %.3f s, %zu records%s\n", when.c_str(),
                o.killed ? "killed" : "finished", o.seconds, recorded,
                torn_now ? " and a torn line" : "");
    if (o.killed) {
      ++kills;
    } else {
      ASSERT_EQ(o.exit_code, 0) << when << "\n" << log();
    }
    expectConsistent(bench, when);
    if (HasFailure()) return;
  }
  EXPECT_GE(kills, 6) << "most runs should have been killed: their events came after the end";

  // A report of what a killed bench left behind works (a torn last line is ignored).
  if (fs::exists(bench / "results.jsonl") && !completeRecords(bench, torn).empty()) {
    const Outcome partial =
        run({"report", "--no-oracle", bench.string(), "--out", (dir_ / "partial_report").string()});
    EXPECT_EQ(partial.exit_code, 0) << log();
  }

  // The same command once more, uninterrupted: everything recorded exactly once.
  const Outcome last = run(benchArgs(bench));
  ASSERT_EQ(last.exit_code, 0) << log();
  const std::vector<nlohmann::json> records = completeRecords(bench, torn);
  EXPECT_FALSE(torn);
  std::map<std::string, nlohmann::json> got;
  for (const nlohmann::json& r : records) {
    EXPECT_TRUE(got.emplace(key(r), r).second) << "recorded twice: " << key(r);
  }
  ASSERT_EQ(got.size(), expected.size());
  for (const auto& [k, r] : got) {
    ASSERT_TRUE(expected.count(k)) << "unplanned record " << k;
    // An episode rerun after a kill gives the record an uninterrupted run gives.
    EXPECT_EQ(roomscout::experiment::withoutTimingFields(r).dump(), expected[k].dump()) << k;
    // The lowest seed's outputs are whole: their metrics.json parses.
    if (r.at("seed") == 1) {
      ASSERT_TRUE(r.at("outputs").is_string()) << k;
      const fs::path outputs = bench / r.at("outputs").get<std::string>();
      EXPECT_TRUE(nlohmann::json::accept(readText(outputs / "metrics.json"))) << k;
      EXPECT_TRUE(fs::is_regular_file(outputs / "occupancy.pgm")) << k;
    }
  }

  // No temporary or scratch file of a killed run is left behind.
  EXPECT_FALSE(fs::exists(bench / ".scratch"));
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(bench)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".tmp."), std::string::npos) << "left behind: " << e.path();
    EXPECT_EQ(name.find(".roomscout_probe"), std::string::npos) << "left behind: " << e.path();
  }

  // `roomscout report` of the folder succeeds and writes whole tables.
  const Outcome report = run({"report", bench.string()});
  ASSERT_EQ(report.exit_code, 0) << log();
  for (const char* table : {"table1.md", "table1.csv", "table2.md", "table3.md", "report.html"}) {
    EXPECT_FALSE(readText(bench / table).empty()) << table;
  }
  const std::string table1 = readText(bench / "table1.csv");
  for (const std::string& m : kMethods) EXPECT_NE(table1.find(m), std::string::npos) << table1;
  const std::string html = readText(bench / "report.html");
  EXPECT_NE(html.find("</html>", html.size() - 16), std::string::npos) << "report.html is torn";
}

TEST_F(BenchKillResumeTest, KilledBeforeWritingAnythingThenResumed) {
  const fs::path bench = dir_ / "early";
  // Killed at once, twice in a row: at most an empty folder or an empty results file.
  for (int i = 0; i < 2; ++i) {
    const Outcome o = run(benchArgs(bench, 2), [] { return true; });
    ASSERT_TRUE(o.killed || o.exit_code == 0) << log();
    expectConsistent(bench, "kill " + std::to_string(i + 1), 2);
  }
  // A report of it fails cleanly (no records yet) or succeeds; it does not crash.
  const Outcome report = run({"report", "--no-oracle", bench.string()});
  EXPECT_TRUE(report.exit_code == 0 || report.exit_code == 2) << log();
  const Outcome o = run(benchArgs(bench, 2));
  ASSERT_EQ(o.exit_code, 0) << log();
  bool torn = false;
  EXPECT_EQ(completeRecords(bench, torn).size(), expectedKeys(2).size());
  EXPECT_FALSE(torn);
}

}  // namespace
