#pragma once
// The numbers of the paper (seed/paper.tex: Semantic Region Aware Autonomous Exploration for
// Multi-Type Map Construction) that report tables print beside ours, and how its methods are
// named in our registry.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roomscout::experiment {

/// Table I: exploration time T [s] and trajectory length L [m] of one method in one world.
struct PaperTimeLength {
  double t_s = 0.0;
  double l_m = 0.0;
};

/// The paper's Table I value for a built-in world (small_house, medium_house, large_office) and
/// a registered method (rrt, improved_rrt, mmpf, topo, semantic = "Ours"); nullopt otherwise.
std::optional<PaperTimeLength> paperTable1(std::string_view world, std::string_view method);

/// Table III: storage S [KB] and update time U [s] of one map type in one world.
struct PaperMapCost {
  double storage_kb = 0.0;
  double update_s = 0.0;
};

/// The paper's Table III value for a built-in world and a map type (occupancy, pointcloud,
/// topological, semantic); nullopt otherwise.
std::optional<PaperMapCost> paperTable3(std::string_view world, std::string_view map_type);

/// One row of the paper's Table II: a work and which of M1 occupancy grid, M2 point cloud,
/// M3 topological and M4 semantic map it builds.
struct PaperMapTypesRow {
  std::string work;
  std::array<bool, 4> maps{};
};

/// Table II's rows in the paper's order, its own method ("Ours") last.
const std::vector<PaperMapTypesRow>& paperTable2();

/// How tables name a method: the paper's name for those it has ("RRT", "Improved RRT",
/// "MMPF", "TOPO", "Ours (semantic)"), a readable name for the others.
std::string methodLabel(std::string_view method);

/// Sort rank of a method in tables: the paper's order (rrt, improved_rrt, mmpf, topo,
/// semantic_paper, semantic), then nearest_frontier, semantic_sampling_only and
/// semantic_score_only, then unknown ones (rank 100; ties broken by name).
int methodRank(std::string_view method);

/// Sort rank of a built-in world in tables: small_house, medium_house, large_office; others 100.
int worldRank(std::string_view world);

}  // namespace roomscout::experiment
