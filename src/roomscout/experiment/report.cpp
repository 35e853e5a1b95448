#include "roomscout/experiment/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include "roomscout/experiment/paper_reference.hpp"
#include "roomscout/experiment/result_record.hpp"

namespace roomscout::experiment {
namespace {

/// Paper worlds first, then other worlds, then groups.
void sortRows(std::vector<ReportRow>& rows) {
  std::sort(rows.begin(), rows.end(), [](const ReportRow& a, const ReportRow& b) {
    const auto rank = [](const ReportRow& r) { return r.is_group ? 200 : worldRank(r.name); };
    return std::pair(rank(a), a.name) < std::pair(rank(b), b.name);
  });
}

/// Paper order, then others by name.
std::vector<std::string> sortedMethods(const std::set<std::string>& methods) {
  std::vector<std::string> sorted(methods.begin(), methods.end());
  std::sort(sorted.begin(), sorted.end(), [](const std::string& a, const std::string& b) {
    return std::pair(methodRank(a), a) < std::pair(methodRank(b), b);
  });
  return sorted;
}

/// Table IV's numbers of every (row, method) with episodes in a setting other than `main`.
SettingComparison compareSettings(const std::vector<EpisodeSummary>& episodes,
                                  const std::string& main) {
  SettingComparison table;
  struct Samples {
    std::size_t episodes = 0, successes = 0, diverged = 0;
    std::vector<double> t98, l98, ate, false_occupied, occupied_precision;
    std::map<std::pair<std::string, std::uint64_t>, double> l98_by_episode;  ///< successes
  };
  std::map<std::pair<std::string, std::string>, std::map<std::string, Samples>> cells;
  std::map<std::string, std::pair<bool, std::set<std::string>>> rows;  // name -> (group, worlds)
  for (const EpisodeSummary& e : episodes) {
    const std::string row = rowNameOf(e);
    auto& r = rows[row];
    r.first = e.world_group != "builtin";
    r.second.insert(e.key.world);
    if (e.setting != main) {
      if (table.episodes[e.setting]++ == 0) table.settings.push_back(e.setting);
    }
    Samples& c = cells[{row, e.key.method}][e.setting];
    ++c.episodes;
    if (e.slam_diverged) ++c.diverged;
    if (e.succeeded()) {
      ++c.successes;
      if (e.t98_s) c.t98.push_back(*e.t98_s);
      if (e.l98_m) {
        c.l98.push_back(*e.l98_m);
        c.l98_by_episode[{e.key.world, e.key.seed}] = *e.l98_m;
      }
    }
    if (e.ate_rmse_m) c.ate.push_back(*e.ate_rmse_m);
    if (e.false_occupied) c.false_occupied.push_back(*e.false_occupied);
    if (e.occupied_precision) c.occupied_precision.push_back(*e.occupied_precision);
  }
  std::set<std::string> row_names, methods;
  for (const auto& [key, by_setting] : cells) {
    if (by_setting.size() == 1 && by_setting.begin()->first == main) continue;
    row_names.insert(key.first);
    methods.insert(key.second);
    auto& out = table.cells[key];
    const auto main_samples = by_setting.find(main);
    for (const auto& [setting, c] : by_setting) {
      SettingStats& s = out[setting];
      s.episodes = c.episodes;
      s.successes = c.successes;
      s.diverged = c.diverged;
      s.t98_s = Stat::of(c.t98);
      s.l98_m = Stat::of(c.l98);
      s.ate_rmse_m = Stat::of(c.ate);
      s.false_occupied = Stat::of(c.false_occupied);
      s.occupied_precision = Stat::of(c.occupied_precision);
      if (setting == main || main_samples == by_setting.end()) continue;
      double sum = 0.0, main_sum = 0.0;
      for (const auto& [episode, l98] : c.l98_by_episode) {
        const auto other = main_samples->second.l98_by_episode.find(episode);
        if (other == main_samples->second.l98_by_episode.end()) continue;
        ++s.pairs;
        sum += l98;
        main_sum += other->second;
      }
      if (s.pairs && main_sum > 0.0) s.l98_ratio = sum / main_sum;
    }
  }
  for (const std::string& name : row_names) {
    const auto& r = rows.at(name);
    table.rows.push_back({name, r.first, r.second.size()});
  }
  sortRows(table.rows);
  table.methods = sortedMethods(methods);
  return table;
}

/// A successful episode with the numbers Table I pairs: T98 and L98.
bool finished(const EpisodeSummary* e) { return e && e->succeeded() && e->t98_s && e->l98_m; }

/// Table I's paired numbers (see PairedRow and MethodStats) from every row's episodes by
/// (world, seed) and method; report.table1 holds a cell for every (row, method) with episodes.
void pairEpisodes(
    const std::map<std::string, std::map<std::pair<std::string, std::uint64_t>,
                                         std::map<std::string, const EpisodeSummary*>>>& by_pair,
    const std::map<std::string, std::set<std::string>>& row_methods, Report& report) {
  for (const auto& [row, pairs] : by_pair) {
    const std::set<std::string>& methods = row_methods.at(row);
    PairedRow& paired = report.paired[row];
    paired.methods = methods.size();
    paired.all_pairs = pairs.size();
    struct Samples {
      std::vector<double> t98, l98, l98_ratio, t98_ratio, oracle_ratio;
    };
    std::map<std::string, Samples> samples;
    for (const auto& [world_seed, episodes] : pairs) {
      const auto semantic = episodes.find("semantic");
      if (semantic != episodes.end() && finished(semantic->second)) {
        for (const auto& [method, e] : episodes) {
          if (method == "semantic" || !finished(e)) continue;
          MethodStats& s = report.table1.at({row, method});
          ++s.semantic_pairs;
          if (*e->l98_m < *semantic->second->l98_m) ++s.beats_semantic;
        }
      }
      if (episodes.size() != methods.size() ||
          !std::all_of(episodes.begin(), episodes.end(),
                       [](const auto& m) { return finished(m.second); }))
        continue;
      ++paired.pairs;
      const auto reference = episodes.find(report.reference);
      const EpisodeSummary* ref = reference == episodes.end() ? nullptr : reference->second;
      for (const auto& [method, e] : episodes) {
        Samples& c = samples[method];
        c.t98.push_back(*e->t98_s);
        c.l98.push_back(*e->l98_m);
        if (ref && *ref->l98_m > 0.0) c.l98_ratio.push_back(*e->l98_m / *ref->l98_m);
        if (ref && *ref->t98_s > 0.0) c.t98_ratio.push_back(*e->t98_s / *ref->t98_s);
        if (e->oracle && e->oracle->length_m > 0.0)
          c.oracle_ratio.push_back(*e->l98_m / e->oracle->length_m);
      }
    }
    for (const auto& [method, c] : samples) {
      MethodStats& s = report.table1.at({row, method});
      s.t98_s = Stat::of(c.t98);
      s.l98_m = Stat::of(c.l98);
      s.l98_reference_ratio = Stat::of(c.l98_ratio);
      s.t98_reference_ratio = Stat::of(c.t98_ratio);
      s.l98_oracle_ratio = Stat::of(c.oracle_ratio);
    }
  }
}

}  // namespace

Stat Stat::of(const std::vector<double>& values) {
  Stat s;
  s.n = values.size();
  if (s.n == 0) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n >= 2) {
    double ss = 0.0;
    for (double v : values) ss += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(ss / static_cast<double>(s.n - 1));
  }
  return s;
}

std::string rowNameOf(const EpisodeSummary& e) {
  return e.world_group == "builtin" ? e.key.world : e.world_group;
}

std::string rowTitle(const ReportRow& row) {
  if (!row.is_group) return row.name;
  return row.name + " (" + std::to_string(row.worlds) + (row.worlds == 1 ? " world)" : " worlds)");
}

Report buildReport(const ResultSet& results) {
  Report report;
  report.files = results.files;
  report.main_setting = mainSetting(results.episodes);
  report.table4 = compareSettings(results.episodes, report.main_setting);
  std::vector<const EpisodeSummary*> episodes;  // of the main setting
  for (const EpisodeSummary& e : results.episodes) {
    if (e.setting == report.main_setting) episodes.push_back(&e);
  }
  report.episodes = episodes.size();

  std::map<std::string, std::pair<bool, std::set<std::string>>> rows;  // name -> (group, worlds)
  std::set<std::string> methods;
  struct Samples {
    std::size_t episodes = 0, successes = 0;
    std::vector<double> own_t98, own_l98, revisits, revisits_98;
  };
  std::map<std::pair<std::string, std::string>, Samples> cells;
  // row -> (world, seed) -> method -> its episode, for pairing the methods' episodes
  std::map<std::string, std::map<std::pair<std::string, std::uint64_t>,
                                 std::map<std::string, const EpisodeSummary*>>>
      by_pair;
  std::map<std::string, std::set<std::string>> row_methods;
  // (world, method) -> distinct (final rate, T98, L98) of its seeds, and its episode count
  using Outcome = std::tuple<double, std::optional<double>, std::optional<double>>;
  std::map<std::pair<std::string, std::string>, std::pair<std::set<Outcome>, std::size_t>> outcomes;
  struct MapSamples {
    std::size_t episodes = 0;
    std::vector<double> storage_kb, median_s, p95_s;
  };
  std::map<std::pair<std::string, std::string>, MapSamples> map_cells;
  // row -> (world, world setup) -> its oracle: one per world, or with random starts one per
  // world and start
  std::map<std::string, std::map<std::pair<std::string, std::string>, OracleReference>> oracles;
  const std::vector<std::string>& types = mapTypes();

  for (const EpisodeSummary* episode : episodes) {
    const EpisodeSummary& e = *episode;
    const std::string row = rowNameOf(e);
    const bool is_group = e.world_group != "builtin";
    if (e.random_start) ++report.random_start_episodes;
    auto& r = rows[row];
    r.first = is_group;
    r.second.insert(e.key.world);
    methods.insert(e.key.method);
    row_methods[row].insert(e.key.method);
    by_pair[row][{e.key.world, e.key.seed}][e.key.method] = &e;
    Samples& c = cells[{row, e.key.method}];
    ++c.episodes;
    if (e.succeeded()) {
      ++c.successes;
      if (e.t98_s) c.own_t98.push_back(*e.t98_s);
      if (e.l98_m) c.own_l98.push_back(*e.l98_m);
    }
    if (e.revisits) c.revisits.push_back(*e.revisits);
    if (e.revisits_98) c.revisits_98.push_back(*e.revisits_98);
    auto& o = outcomes[{e.key.world, e.key.method}];
    o.first.emplace(e.exploration_rate, e.t98_s, e.l98_m);
    ++o.second;
    if (e.oracle) oracles[row].emplace(std::pair{e.key.world, e.world_setup}, *e.oracle);
    auto& built = report.map_types[e.key.method];
    for (std::size_t i = 0; i < types.size(); ++i) {
      const auto it = e.maps.find(types[i]);
      if (it == e.maps.end()) continue;
      const MapSample& m = it->second;
      if (m.storage_bytes > 0.0 || m.updates > 0) built[i] = true;
      MapSamples& mc = map_cells[{row, types[i]}];
      ++mc.episodes;
      mc.storage_kb.push_back(m.storage_bytes / 1024.0);
      if (m.update_median_ms) mc.median_s.push_back(*m.update_median_ms / 1000.0);
      if (m.update_p95_ms) mc.p95_s.push_back(*m.update_p95_ms / 1000.0);
    }
  }

  for (const auto& [name, r] : rows) report.rows.push_back({name, r.first, r.second.size()});
  sortRows(report.rows);
  report.methods = sortedMethods(methods);
  if (!report.methods.empty()) {
    const bool rrt = methods.contains("rrt");
    report.reference = rrt ? std::string("rrt") : report.methods.front();
  }
  for (const auto& [key, c] : cells) {
    MethodStats& s = report.table1[key];
    s.episodes = c.episodes;
    s.successes = c.successes;
    s.own_t98_s = Stat::of(c.own_t98);
    s.own_l98_m = Stat::of(c.own_l98);
    s.revisits = Stat::of(c.revisits);
    s.revisits_98 = Stat::of(c.revisits_98);
  }
  pairEpisodes(by_pair, row_methods, report);
  // A row's cell repeats itself when each of its worlds run with several seeds had one outcome.
  std::map<std::pair<std::string, std::string>, std::pair<bool, bool>>
      repeats;  // (several, all same)
  for (const EpisodeSummary* e : episodes) {
    const auto& [distinct, count] = outcomes.at({e->key.world, e->key.method});
    if (count < 2) continue;
    auto& r = repeats.try_emplace({rowNameOf(*e), e->key.method}, false, true).first->second;
    r.first = true;
    r.second = r.second && distinct.size() == 1;
  }
  for (const auto& [key, r] : repeats) report.table1[key].same_every_seed = r.first && r.second;
  for (const auto& [key, c] : map_cells) {
    MapStats& s = report.table3[key];
    s.episodes = c.episodes;
    s.storage_kb = Stat::of(c.storage_kb);
    s.update_median_s = Stat::of(c.median_s);
    s.update_p95_s = Stat::of(c.p95_s);
  }
  for (const auto& [row, tours] : oracles) {
    std::vector<double> length, coverage, viewpoints;
    std::set<std::string> worlds;
    for (const auto& [world_and_setup, o] : tours) {
      worlds.insert(world_and_setup.first);
      length.push_back(o.length_m);
      coverage.push_back(o.coverage);
      viewpoints.push_back(static_cast<double>(o.viewpoints));
    }
    OracleRowStats& s = report.oracle[row];
    s.worlds = worlds.size();
    s.length_m = Stat::of(length);
    s.coverage = Stat::of(coverage);
    s.viewpoints = Stat::of(viewpoints);
  }
  return report;
}

bool Report::hasSemantic() const {
  return std::find(methods.begin(), methods.end(), "semantic") != methods.end();
}

std::vector<std::string> Report::methodsSameEverySeed() const {
  std::vector<std::string> out;
  for (const std::string& method : methods) {
    bool several = false, same = true;
    for (const ReportRow& row : rows) {
      const auto it = table1.find({row.name, method});
      if (it == table1.end()) continue;
      // Rows without several seeds of a world do not say either way.
      const bool repeated = it->second.same_every_seed;
      several = several || repeated;
      if (!repeated && it->second.episodes > row.worlds) same = false;
    }
    if (several && same) out.push_back(method);
  }
  return out;
}

}  // namespace roomscout::experiment
