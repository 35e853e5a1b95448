#pragma once
// Subcommands over many episodes: `bench` runs them, `report` tabulates and plots their results.

#include <CLI/CLI.hpp>

#include "roomscout/cli/map_commands.hpp"

namespace roomscout::cli {

/// `roomscout bench --worlds ... --methods ... --seeds N --jobs J --out DIR [--shard I/N]
/// [--config FILE] [--max-time S]`: every (world, method, seed) episode into DIR/results.jsonl,
/// then the report (tables, figures, report.html) into DIR.
Subcommand addBenchCommand(CLI::App& app);

/// `roomscout report DIR... [--out OUT] [--no-oracle]`: Tables I-IV, figures and report.html
/// from the results of one or more bench directories (or results.jsonl files), merged by
/// (world, method, seed).
Subcommand addReportCommand(CLI::App& app);

}  // namespace roomscout::cli
