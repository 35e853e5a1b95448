// Every config key the documentation names loads: in the simulator's config file (`roomscout
// explore --config`) or in a robot's (roomscout_explore_node's ~config), without a warning
// unless the docs name it as a former name; and docs/explorer.md lists every option of the
// Explorer.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/experiment/run_outputs.hpp"
#include "roomscout/io/explorer_config.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace fs = std::filesystem;
using namespace roomscout;

namespace {

using roomscout::test::readText;

/// Every option a config file of either kind may set, by "group.name", with its default
/// written as YAML.
std::map<std::string, std::string> knownOptions() {
  std::map<std::string, std::string> known;
  auto add = [&](const std::vector<ParameterGroup>& groups) {
    for (const ParameterGroup& g : groups) {
      for (const ParameterRef& p : g.parameters)
        known[g.name + "." + std::string(p.name)] = io::parameterValueYaml(p);
    }
  };
  experiment::EpisodeSetup setup = experiment::makeEpisodeSetup("nearest_frontier", 1, {});
  std::vector<std::unique_ptr<ExplorationStrategy>> others;
  add(experiment::configGroups(setup, others));
  io::ExplorerConfig robot = io::loadExplorerConfig("nearest_frontier", 1, {});
  add(robot.groups("nearest_frontier", 1, others));
  return known;
}

/// Every "a.b" path of a JSON object.
void addPaths(const nlohmann::json& j, const std::string& prefix, std::set<std::string>& paths) {
  for (const auto& [key, value] : j.items()) {
    paths.insert(prefix + key);
    if (value.is_object()) addPaths(value, prefix + key + ".", paths);
  }
}

/// Fields of metrics.json whose names look like options ("slam.diverged", "maps.pointcloud").
std::set<std::string> recordFields() {
  sim::EpisodeResult result;
  result.slam = sim::SlamResult{};
  std::set<std::string> fields;
  addPaths(experiment::metricsJson({}, result), "", fields);
  for (const char* map : {"occupancy", "pointcloud", "topology", "semantic"})
    fields.insert(std::string("maps.") + map);
  return fields;
}

/// The "group.name" words of a Markdown file whose group is a config group.
std::set<std::string> mentionedKeys(const std::string& text, const std::set<std::string>& groups) {
  static const std::set<std::string> kFileExtensions = {"json", "jsonl", "png", "svg", "pdf",
                                                        "yaml", "pgm",   "pcd", "csv", "md",
                                                        "cpp",  "hpp",   "html"};
  static const std::regex kWord(R"re(\b([a-z][a-z0-9_]*)\.([a-z][a-z0-9_]*)\b(?![\w(.]))re");
  std::set<std::string> keys;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kWord);
       it != std::sregex_iterator(); ++it) {
    const std::string group = (*it)[1], name = (*it)[2];
    if (groups.count(group) != 0 && kFileExtensions.count(name) == 0)
      keys.insert(group + "." + name);
  }
  return keys;
}

TEST(DocumentedOptions, EveryKeyTheDocsNameLoadsWithoutAWarning) {
  const std::map<std::string, std::string> known = knownOptions();
  std::set<std::string> groups;
  for (const auto& [key, value] : known) groups.insert(key.substr(0, key.find('.')));
  const std::set<std::string> record = recordFields();
  std::set<std::string> former;
  for (const auto& list :
       {sim::EpisodeConfig::renamedOptions(), io::ExplorerConfig::renamedOptions()}) {
    for (const RenamedOption& r : list) former.insert(r.old_name);
  }
  const test::TempDir dir;
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(ROOMSCOUT_SOURCE_DIR) / "docs")) {
    if (entry.path().extension() != ".md") continue;
    for (const std::string& key : mentionedKeys(readText(entry.path()), groups)) {
      SCOPED_TRACE(entry.path().filename().string() + ": " + key);
      const auto value = known.find(key);
      if (record.count(key) != 0) continue;
      if (value == known.end()) {
        EXPECT_EQ(former.count(key), 1u) << "no such option";
        continue;
      }
      const std::string group = key.substr(0, key.find('.'));
      const fs::path file = dir.write(
          "key.yaml", group + ":\n  " + key.substr(group.size() + 1) + ": " + value->second + "\n");
      std::vector<std::string> warnings;
      bool loaded = false;
      try {
        experiment::RunSettings settings;
        settings.config_file = file;
        warnings = experiment::makeEpisodeSetup("nearest_frontier", 1, settings).warnings;
        loaded = warnings.empty();
      } catch (const OptionError&) {
      }
      if (!loaded) {
        warnings = io::loadExplorerConfig("nearest_frontier", 1, file).warnings;
        loaded = warnings.empty();
      }
      EXPECT_TRUE(loaded || (former.count(key) != 0 && !warnings.empty()))
          << (warnings.empty() ? "" : warnings.front());
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(DocumentedOptions, ExplorerMdListsEveryOptionOfTheExplorer) {
  // Every group by name; the keys of the costmap, the planner and the watchdogs one by one (the
  // rooms' and skeleton's are listed in docs/options.md).
  const std::string doc = readText(fs::path(ROOMSCOUT_SOURCE_DIR) / "docs" / "explorer.md");
  ExplorerOptions options;
  for (const ParameterGroup& g : options.groups()) {
    EXPECT_NE(doc.find("`" + g.name + "`"), std::string::npos) << g.name;
    if (g.name != "costmap" && g.name != "planner" && g.name != "explorer") continue;
    for (const ParameterRef& p : g.parameters)
      EXPECT_NE(doc.find("`" + std::string(p.name) + "`"), std::string::npos)
          << g.name << "." << p.name;
  }
}

}  // namespace
