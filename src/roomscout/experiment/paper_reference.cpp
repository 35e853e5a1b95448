#include "roomscout/experiment/paper_reference.hpp"

#include <map>
#include <utility>

namespace roomscout::experiment {
namespace {

using Key = std::pair<std::string, std::string>;

}  // namespace

std::optional<PaperTimeLength> paperTable1(std::string_view world, std::string_view method) {
  // seed/paper.tex, Table I ("Exploration time and trajectory length comparison").
  static const std::map<Key, PaperTimeLength> table = {
      {{"small_house", "rrt"}, {171, 31}},
      {{"medium_house", "rrt"}, {593, 131}},
      {{"large_office", "rrt"}, {1838, 375}},
      {{"small_house", "improved_rrt"}, {162, 27}},
      {{"medium_house", "improved_rrt"}, {436, 112}},
      {{"large_office", "improved_rrt"}, {1282, 306}},
      {{"small_house", "mmpf"}, {125, 28}},
      {{"medium_house", "mmpf"}, {350, 87}},
      {{"large_office", "mmpf"}, {1267, 338}},
      {{"small_house", "topo"}, {118, 33}},
      {{"medium_house", "topo"}, {414, 119}},
      {{"large_office", "topo"}, {1054, 329}},
      {{"small_house", "semantic"}, {126, 25}},
      {{"medium_house", "semantic"}, {292, 68}},
      {{"large_office", "semantic"}, {1018, 283}},
  };
  const auto it = table.find({std::string(world), std::string(method)});
  if (it == table.end()) return std::nullopt;
  return it->second;
}

std::optional<PaperMapCost> paperTable3(std::string_view world, std::string_view map_type) {
  // seed/paper.tex, Table III ("Storage size and update time of multi-type maps").
  static const std::map<Key, PaperMapCost> table = {
      {{"small_house", "occupancy"}, {509.7, 0.9}},
      {{"medium_house", "occupancy"}, {707.0, 0.9}},
      {{"large_office", "occupancy"}, {798.7, 1.0}},
      {{"small_house", "pointcloud"}, {2604.3, 0.2}},
      {{"medium_house", "pointcloud"}, {6867.3, 0.2}},
      {{"large_office", "pointcloud"}, {16862.5, 0.2}},
      {{"small_house", "topological"}, {23.5, 1.1}},
      {{"medium_house", "topological"}, {52.1, 1.0}},
      {{"large_office", "topological"}, {136.4, 1.0}},
      {{"small_house", "semantic"}, {6.1, 2.2}},
      {{"medium_house", "semantic"}, {8.6, 2.6}},
      {{"large_office", "semantic"}, {18.3, 3.1}},
  };
  const auto it = table.find({std::string(world), std::string(map_type)});
  if (it == table.end()) return std::nullopt;
  return it->second;
}

const std::vector<PaperMapTypesRow>& paperTable2() {
  // seed/paper.tex, Table II ("The types of maps constructed by previous methods and our method").
  static const std::vector<PaperMapTypesRow> rows = {
      {"Cao et al. (ICRA 2021)", {false, true, false, false}},
      {"Lehner et al. (ICRA 2021)", {true, false, false, false}},
      {"Tian et al. (ICRAI 2023)", {true, false, false, false}},
      {"Gomez et al. (ICRA 2020)", {false, true, true, false}},
      {"Zhang et al. (RAL 2022)", {true, false, true, false}},
      {"Ishikawa et al. (SMC 2023)", {true, false, false, true}},
      {"Liu et al. (IROS 2022)", {false, true, true, true}},
      {"Ours (paper)", {true, true, true, true}},
  };
  return rows;
}

namespace {

struct MethodInfo {
  const char* name;
  const char* label;
};

// The paper's order, with semantic_paper right before semantic, then the other methods of the
// registry (nearest_frontier, then the two ablations of semantic).
constexpr MethodInfo kMethods[] = {
    {"rrt", "RRT"},
    {"improved_rrt", "Improved RRT"},
    {"mmpf", "MMPF"},
    {"topo", "TOPO"},
    {"semantic_paper", "The paper's method (semantic_paper)"},
    {"semantic", "Ours (semantic)"},
    {"nearest_frontier", "Nearest frontier (explore_lite)"},
    {"semantic_sampling_only", "Ours, sampling only (ablation)"},
    {"semantic_score_only", "Ours, score only (ablation)"},
};

}  // namespace

std::string methodLabel(std::string_view method) {
  for (const MethodInfo& m : kMethods) {
    if (method == m.name) return m.label;
  }
  return std::string(method);
}

int methodRank(std::string_view method) {
  for (int i = 0; i < static_cast<int>(std::size(kMethods)); ++i) {
    if (method == kMethods[i].name) return i;
  }
  return 100;
}

int worldRank(std::string_view world) {
  if (world == "small_house") return 0;
  if (world == "medium_house") return 1;
  if (world == "large_office") return 2;
  return 100;
}

}  // namespace roomscout::experiment
