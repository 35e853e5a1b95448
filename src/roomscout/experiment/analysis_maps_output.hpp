#pragma once
// Writes the topological and semantic maps of an episode next to its other outputs and
// scores the rooms against the world's ground-truth rooms, when it has some.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/explorer/analysis_maps.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::experiment {

/// The world's ground-truth room of every free cell of `grid` (CV_32S, row y = grid row y,
/// 0 = none), for scoring a segmentation of that grid.
cv::Mat groundTruthRoomLabels(const OccupancyGrid& grid, const sim::WorldModel& world);

/// Writes topology.json/.png and semantic.json/.png/_labels.png into `directory`, each
/// atomically. Returns a summary for metrics.json's "maps": counts, and for a world (may be
/// null, as on a robot) with rooms the segmentation's score against them (also stored in
/// semantic.json as "ground_truth_score").
nlohmann::json writeAnalysisMaps(const std::filesystem::path& directory,
                                 const AnalysisMap& semantic, const AnalysisMap& topological,
                                 const OccupancyGrid& grid, const sim::WorldModel* world);

}  // namespace roomscout::experiment
