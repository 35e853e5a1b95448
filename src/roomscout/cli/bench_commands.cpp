#include "roomscout/cli/bench_commands.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/experiment/bench_plan.hpp"
#include "roomscout/experiment/bench_runner.hpp"
#include "roomscout/experiment/report_writer.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/pcd_io.hpp"

namespace roomscout::cli {
namespace {

/// "1h02m", "3m20s", "42s".
std::string duration(double s) {
  const long total = std::lround(std::max(0.0, s));
  if (total >= 3600) return formatString("%ldh%02ldm", total / 3600, (total / 60) % 60);
  if (total >= 60) return formatString("%ldm%02lds", total / 60, total % 60);
  return formatString("%lds", total);
}

/// The bench's one-line progress bar on a terminal (stderr); silent when not a terminal.
class BenchProgressBar {
 public:
  BenchProgressBar() : enabled_(isatty(STDERR_FILENO) != 0) {}
  ~BenchProgressBar() {
    if (drawn_) std::fprintf(stderr, "\n");
  }
  BenchProgressBar(const BenchProgressBar&) = delete;
  BenchProgressBar& operator=(const BenchProgressBar&) = delete;

  void update(const experiment::BenchProgress& p) {
    if (!enabled_) return;
    const std::size_t total = p.planned - p.skipped;
    const int width = 30;
    const double fraction = total ? static_cast<double>(p.done) / static_cast<double>(total) : 1.0;
    const int filled = static_cast<int>(fraction * width);
    const std::string eta = p.remaining_s ? duration(*p.remaining_s) : std::string("?");
    std::fprintf(stderr, "\rbench [%.*s%*s] %zu/%zu episodes, %zu running, %s elapsed, ~%s left   ",
                 filled, "##############################", width - filled, "", p.done, total,
                 p.running, duration(p.elapsed_s).c_str(), eta.c_str());
    std::fflush(stderr);
    drawn_ = true;
  }

 private:
  bool enabled_;
  bool drawn_ = false;
};

/// Runs the report and prints its notes (stderr); returns the files written.
std::vector<std::filesystem::path> reportInto(const std::vector<std::filesystem::path>& inputs,
                                              const std::filesystem::path& out,
                                              const experiment::ReportSettings& settings) {
  const experiment::ReportOutput report = experiment::runReport(inputs, out, settings);
  if (report.duplicates > 0) {
    std::fprintf(stderr,
                 "roomscout: note: %zu records repeat an earlier (world, method, seed, setting); "
                 "kept the first\n",
                 report.duplicates);
  }
  if (report.truncated > 0) {
    std::fprintf(
        stderr,
        "roomscout: note: %zu results file(s) end in a truncated line (an interrupted bench), "
        "ignored\n",
        report.truncated);
  }
  for (const std::string& note : report.notes)
    std::fprintf(stderr, "roomscout: note: %s\n", note.c_str());
  return report.files;
}

struct BenchArgs {
  std::string worlds;
  std::string methods;
  std::string seeds = "1";
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string out;
  std::string shard;
  std::string config;
  std::optional<double> max_time_s;
  std::string pcd_format = "binary_compressed";
  double pcd_precision_m = 0.005;
  bool random_starts = false;
};

int runBenchCommand(const BenchArgs& args) {
  experiment::BenchOptions options;
  options.worlds = experiment::splitList(args.worlds);
  options.methods = experiment::splitList(args.methods);
  options.seeds = experiment::parseSeeds(args.seeds);
  options.random_starts = args.random_starts;
  options.jobs = args.jobs;
  options.out = args.out;
  if (!args.shard.empty()) options.shard = experiment::parseShard(args.shard);
  options.settings.config_file = args.config;
  options.settings.max_time_s = args.max_time_s;
  options.settings.pcd_format = io::parsePcdFormat(args.pcd_format);
  options.settings.pcd_precision_m = args.pcd_precision_m;

  io::OutputDirectory out(options.out);  // removed again if the bench fails before writing
  experiment::BenchSummary summary;
  {
    BenchProgressBar bar;
    summary =
        experiment::runBench(options, [&](const experiment::BenchProgress& p) { bar.update(p); });
  }
  if (summary.dropped_truncated_line) {
    std::fprintf(
        stderr,
        "roomscout: note: %s ended in a truncated line (an interrupted bench); removed it\n",
        summary.results.string().c_str());
  }
  experiment::ReportSettings report_settings;
  report_settings.threads = static_cast<unsigned>(options.jobs);
  (void)reportInto({options.out}, options.out, report_settings);
  const experiment::BenchProgress& p = summary.progress;
  std::printf(
      "bench: %zu episodes (%zu run, %zu already recorded) in %.1f s -> %s; report in %s "
      "(report.html)\n",
      p.planned, p.done, p.skipped, p.elapsed_s, summary.results.string().c_str(),
      options.out.string().c_str());
  out.keep();
  return 0;
}

}  // namespace

Subcommand addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run every (world, method, seed) episode and tabulate the results");
  cmd->add_option("--worlds", args->worlds,
                  "comma-separated built-in names, world/map_server YAML files, or folders of them "
                  "(their *.yaml)")
      ->required();
  cmd->add_option("--methods", args->methods, "comma-separated methods (see `roomscout methods`)")
      ->required();
  cmd->add_option("--seeds", args->seeds, "seeds of each world x method: N for 1..N, or A-B")
      ->capture_default_str();
  cmd->add_option("--jobs", args->jobs, "episodes run at a time (one thread each)")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "bench directory: results.jsonl, runs/, tables")->required();
  cmd->add_option("--shard", args->shard,
                  "run only slice I of N of the sorted episode list (I/N, 1-based)");
  cmd->add_option("--config", args->config, "YAML file of options, grouped as in metrics.json");
  cmd->add_flag("--random-starts", args->random_starts,
                "start each seed at a pose drawn from it (the same for every method) instead of "
                "the world's start");
  cmd->add_option("--max-time", args->max_time_s, "simulated time limit of each episode [s]");
  cmd->add_option("--pcd-format", args->pcd_format,
                  "pointcloud.pcd encoding: ascii, binary, binary_compressed")
      ->capture_default_str();
  cmd->add_option("--pcd-precision", args->pcd_precision_m,
                  "pointcloud.pcd coordinates rounded to multiples of this [m]; 0 = exact")
      ->capture_default_str();
  return {cmd, [args]() { return runBenchCommand(*args); }};
}

Subcommand addReportCommand(CLI::App& app) {
  struct ReportArgs {
    std::vector<std::string> inputs;
    std::string out;
    bool no_oracle = false;
  };
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Tables I-IV, figures and report.html from the results of one or more bench directories");
  cmd->add_option("dirs", args->inputs,
                  "bench directories (or results.jsonl files); records merged by key")
      ->required();
  cmd->add_option("--out", args->out, "where the report goes (default: the first directory)");
  cmd->add_flag("--no-oracle", args->no_oracle,
                "skip the full-knowledge oracle tours (Table I's L98 / oracle)");
  return {cmd, [args]() {
            std::vector<std::filesystem::path> inputs(args->inputs.begin(), args->inputs.end());
            std::filesystem::path out = args->out;
            if (out.empty()) {
              std::error_code ec;
              out = std::filesystem::is_directory(inputs.front(), ec)
                        ? inputs.front()
                        : inputs.front().parent_path();
              if (out.empty()) out = ".";
            }
            experiment::ReportSettings settings;
            settings.oracle = !args->no_oracle;
            const std::vector<std::filesystem::path> tables = reportInto(inputs, out, settings);
            for (const std::filesystem::path& t : tables) std::printf("%s\n", t.string().c_str());
            return 0;
          }};
}

}  // namespace roomscout::cli
