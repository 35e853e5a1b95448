// `roomscout options`: the options of a config file printed from the parameters() lists, the
// one place each option is described.

#include "roomscout/cli/options_command.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::cli {
namespace {

struct OptionsArgs {
  std::string method;
  bool markdown = false;
};

/// A group as printed: its options, and for a method's group the method's description.
struct PrintedGroup {
  const ParameterGroup* group = nullptr;
  const StrategyEntry* method = nullptr;
};

std::string methodNote(const StrategyEntry& e) {
  return "method " + e.name + ": " + e.description + ". Read only by --method " + e.name;
}

std::string yamlDocument(const std::vector<PrintedGroup>& groups) {
  std::string out =
      "# Every option a `roomscout explore --config` (or `bench --config`) file may set, at its\n"
      "# default value. A config file needs only the options it changes; an unknown group or\n"
      "# key is an error. `roomscout maps` and `segment-eval` read the groups segmentation and\n"
      "# topology. Generated from the options' parameters() lists by `roomscout options`.\n";
  for (const PrintedGroup& pg : groups) {
    out += "\n";
    if (pg.method != nullptr) out += "# " + methodNote(*pg.method) + "\n";
    if (pg.group->parameters.empty()) {
      out += pg.group->name + ": {}  # no options\n";
      continue;
    }
    out += pg.group->name + ":\n";
    std::vector<std::string> lines;
    std::size_t width = 0;
    for (const ParameterRef& p : pg.group->parameters) {
      lines.push_back("  " + std::string(p.name) + ": " + io::parameterValueYaml(p));
      width = std::max(width, lines.back().size());
    }
    for (std::size_t i = 0; i < lines.size(); ++i) {
      lines[i].resize(width, ' ');
      out += lines[i] + "  # " + std::string(pg.group->parameters[i].doc) + "\n";
    }
  }
  return out;
}

/// A value in a code span in a table cell: only '|' needs escaping there.
std::string codeCell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

/// Text that Markdown shows as it is, also inside a table cell.
std::string markdownText(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|' || c == '*') out += '\\';  // a table cell's end, emphasis
    out += c;
  }
  return out;
}

std::string markdownDocument(const std::vector<PrintedGroup>& groups) {
  std::string out =
      "# Options of a config file\n\n"
      "Every option a `roomscout explore --config` (or `bench --config`) file may set: a YAML\n"
      "map of groups, each a map of options (`laser: {num_beams: 180}`). A config file needs\n"
      "only the options it changes; an unknown group or key is an error. `roomscout maps` and\n"
      "`segment-eval` read the groups `segmentation` and `topology`. `roomscout options` prints\n"
      "the same as a config file with every default.\n";
  for (const PrintedGroup& pg : groups) {
    out += "\n## " + pg.group->name + "\n\n";
    if (pg.method != nullptr) {
      out += "The method `" + pg.method->name + "`: " + markdownText(pg.method->description) +
             ". Read only by `--method " + pg.method->name + "`.\n\n";
    }
    if (pg.group->parameters.empty()) {
      out += "No options.\n";
      continue;
    }
    out += "| key | default | description |\n|---|---|---|\n";
    for (const ParameterRef& p : pg.group->parameters) {
      out += "| `" + std::string(p.name) + "` | `" + codeCell(io::parameterValueYaml(p)) + "` | " +
             markdownText(p.doc) + " |\n";
    }
  }
  return out;
}

int runOptions(const OptionsArgs& args) {
  experiment::EpisodeSetup setup;
  setup.method = args.method.empty() ? strategyRegistry().front().name : args.method;
  setup.strategy = createStrategy(setup.method, setup.seed);  // throws for an unknown name
  std::vector<std::unique_ptr<ExplorationStrategy>> others;
  const std::vector<ParameterGroup> groups = experiment::configGroups(setup, others);

  std::vector<PrintedGroup> printed;
  for (const ParameterGroup& g : groups) {
    const auto& registry = strategyRegistry();
    const auto method = std::find_if(registry.begin(), registry.end(),
                                     [&](const StrategyEntry& e) { return e.name == g.name; });
    if (method == registry.end()) {
      printed.push_back({&g, nullptr});
    } else if (args.method.empty() || method->name == args.method) {
      printed.push_back({&g, &*method});
    }
  }
  const std::string text = args.markdown ? markdownDocument(printed) : yamlDocument(printed);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace

Subcommand addOptionsCommand(CLI::App& app) {
  auto args = std::make_shared<OptionsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "options", "Print every option of a --config file with its default and description");
  cmd->add_option("--method", args->method,
                  "print only this method's group of the method groups (default: every method's)");
  cmd->add_flag("--markdown", args->markdown, "print Markdown tables instead of YAML");
  return {cmd, [args] { return runOptions(*args); }};
}

}  // namespace roomscout::cli
