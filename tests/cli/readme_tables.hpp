#pragma once
// The README's result tables and the episodes behind them. Each table sits between
// `<!-- table: COMMAND -->` and `<!-- end table -->`, where COMMAND (run from the source
// folder) prints it from a CSV of episodes in docs/tables/ that scripts/method_table.py --csv
// wrote from a bench. The tests check that the command still prints the README's table and
// that the binary still gives the CSV's episodes, so a change that moves the results fails
// until the tables are remade.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"

namespace roomscout::test {

/// One generated table of a Markdown file: the command that prints it and what the file holds.
struct GeneratedTable {
  std::string command;
  std::string content;  ///< between the markers, without surrounding blank lines
};

inline std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \n") - first + 1);
}

/// The generated tables of `markdown`.
inline std::vector<GeneratedTable> generatedTables(const std::string& markdown) {
  static const std::string kBegin = "<!-- table: ", kBeginEnd = " -->", kEnd = "<!-- end table -->";
  std::vector<GeneratedTable> tables;
  std::size_t at = 0;
  while ((at = markdown.find(kBegin, at)) != std::string::npos) {
    const std::size_t command_end = markdown.find(kBeginEnd, at);
    const std::size_t end = markdown.find(kEnd, at);
    if (command_end == std::string::npos || end == std::string::npos || end < command_end) {
      ADD_FAILURE() << "a table marker without its end at offset " << at;
      break;
    }
    GeneratedTable t;
    t.command = markdown.substr(at + kBegin.size(), command_end - at - kBegin.size());
    const std::size_t body = command_end + kBeginEnd.size();
    t.content = trimmed(markdown.substr(body, end - body));
    tables.push_back(t);
    at = end + kEnd.size();
  }
  return tables;
}

/// One episode of a table's CSV (the columns scripts/method_table.py --csv writes).
struct TableEpisode {
  std::string world, method, setting, start_mode;
  int seed = 0;
  double exploration_rate = 0.0;
  bool timed_out = false, diverged = false;
  std::optional<double> t98_s, l98_m;
  std::string key() const {
    return world + "/" + method + "/" + std::to_string(seed) + "/" + setting;
  }
};

inline std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

inline std::vector<TableEpisode> readTableCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "world,method,seed,setting,start_mode,exploration_rate,timed_out,diverged,t98_s,l98_m")
      << path;
  std::vector<TableEpisode> episodes;
  auto number = [](const std::string& text) {
    return text.empty() ? std::optional<double>() : std::optional<double>(std::stod(text));
  };
  while (std::getline(in, line)) {
    const std::vector<std::string> c = splitCsvLine(line);
    if (c.size() != 10) {
      ADD_FAILURE() << path << ": not 10 cells: " << line;
      continue;
    }
    TableEpisode e;
    e.world = c[0];
    e.method = c[1];
    e.seed = std::stoi(c[2]);
    e.setting = c[3];
    e.start_mode = c[4];
    e.exploration_rate = std::stod(c[5]);
    e.timed_out = c[6] == "true";
    e.diverged = c[7] == "true";
    e.t98_s = number(c[8]);
    e.l98_m = number(c[9]);
    episodes.push_back(e);
  }
  return episodes;
}

/// The CSVs the README's tables are printed from.
inline std::vector<std::filesystem::path> readmeTableCsvs() {
  const std::filesystem::path source(ROOMSCOUT_SOURCE_DIR);
  std::set<std::filesystem::path> csvs;
  for (const GeneratedTable& t : generatedTables(readText(source / "README.md"))) {
    std::stringstream words(t.command);
    std::string word;
    while (words >> word) {
      if (word.size() > 4 && word.ends_with(".csv")) csvs.insert(source / word);
    }
  }
  return {csvs.begin(), csvs.end()};
}

inline bool sameNumber(const std::optional<double>& a, const std::optional<double>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || std::abs(*a - *b) <= 1e-9 * std::max(1.0, std::abs(*a));
}

/// Reruns the episodes of `csv` in `worlds` at the CSV's lowest seed with the binary (one
/// bench per setting, in `work`), and expects the records the CSV holds for them.
inline void expectTheBinaryGivesTheEpisodes(const std::filesystem::path& csv,
                                            const std::set<std::string>& worlds,
                                            const std::filesystem::path& work) {
  const std::vector<TableEpisode> all = readTableCsv(csv);
  ASSERT_FALSE(all.empty()) << csv;
  int seed = all.front().seed;
  for (const TableEpisode& e : all) seed = std::min(seed, e.seed);
  // setting -> the episodes to rerun
  std::map<std::string, std::map<std::string, TableEpisode>> wanted;
  for (const TableEpisode& e : all) {
    if (e.seed == seed && worlds.count(e.world) != 0) wanted[e.setting][e.key()] = e;
  }
  ASSERT_FALSE(wanted.empty()) << csv << " holds none of the worlds asked for";
  for (const auto& [setting, episodes] : wanted) {
    SCOPED_TRACE(csv.filename().string() + ", setting " + setting);
    std::set<std::string> methods, bench_worlds;
    bool random_starts = false;
    for (const auto& [key, e] : episodes) {
      methods.insert(e.method);
      bench_worlds.insert(e.world);
      random_starts = e.start_mode == "random";
    }
    auto joined = [](const std::set<std::string>& names) {
      std::string text;
      for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
      return text;
    };
    const std::filesystem::path dir = work / ("bench_" + setting);
    std::filesystem::create_directories(dir);
    std::string args = "bench --worlds " + joined(bench_worlds) + " --methods " + joined(methods) +
                       " --seeds " + std::to_string(seed) + "-" + std::to_string(seed) +
                       " --jobs 2 --out " + (dir / "out").string();
    if (random_starts) args += " --random-starts";
    if (setting != "none") {
      const std::size_t plus = setting.find('+');
      std::ofstream config(dir / "config.yaml");
      config << "noise:\n  profile: " << setting.substr(0, plus) << "\n";
      if (plus != std::string::npos)
        config << "slam:\n  mode: " << setting.substr(plus + 1) << "\n";
      args += " --config " + (dir / "config.yaml").string();
    }
    const CommandResult r = runRoomscout(args, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream results(dir / "out" / "results.jsonl");
    std::string line;
    std::set<std::string> seen;
    while (std::getline(results, line)) {
      const nlohmann::json j = nlohmann::json::parse(line);
      TableEpisode got;
      got.world = j.at("world").get<std::string>();
      got.method = j.at("method").get<std::string>();
      got.seed = j.at("seed").get<int>();
      got.setting = setting;
      const auto expected = episodes.find(got.key());
      if (expected == episodes.end()) continue;  // a world x method pair the CSV leaves out
      seen.insert(got.key());
      const TableEpisode& e = expected->second;
      auto optional = [&](const char* name) {
        return j.at(name).is_null() ? std::optional<double>() : j.at(name).get<double>();
      };
      SCOPED_TRACE(got.key() + ": the binary no longer gives the episode of " +
                   csv.filename().string() + "; remake the table with the command in README.md");
      EXPECT_TRUE(sameNumber(j.at("exploration_rate").get<double>(), e.exploration_rate))
          << j.at("exploration_rate") << " vs " << e.exploration_rate;
      EXPECT_EQ(j.at("timed_out").get<bool>(), e.timed_out);
      EXPECT_TRUE(sameNumber(optional("t98_s"), e.t98_s));
      EXPECT_TRUE(sameNumber(optional("l98_m"), e.l98_m))
          << j.at("l98_m") << " vs " << e.l98_m.value_or(-1.0);
    }
    EXPECT_EQ(seen.size(), episodes.size()) << "episodes of the CSV the bench did not run";
  }
}

}  // namespace roomscout::test
