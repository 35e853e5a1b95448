#pragma once
// `roomscout options`: every option a config file may set, with its default and description.

#include <CLI/CLI.hpp>

#include "roomscout/cli/map_commands.hpp"

namespace roomscout::cli {

/// `roomscout options [--method NAME] [--markdown]`: every group a `--config` file may set,
/// each key with its default value and description, as a commented YAML document that is
/// itself a valid config file, or as Markdown tables (one per group). Method groups: the one
/// of --method, or every method's when it is not given.
Subcommand addOptionsCommand(CLI::App& app);

}  // namespace roomscout::cli
