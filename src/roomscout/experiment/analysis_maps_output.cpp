#include "roomscout/experiment/analysis_maps_output.hpp"

#include "roomscout/io/semantic_io.hpp"
#include "roomscout/io/topology_io.hpp"
#include "roomscout/maps/segmentation_score.hpp"

namespace roomscout::experiment {

cv::Mat groundTruthRoomLabels(const OccupancyGrid& grid, const sim::WorldModel& world) {
  const GridGeometry& g = grid.geometry();
  cv::Mat labels = cv::Mat::zeros(g.height(), g.width(), CV_32S);
  for (int y = 0; y < g.height(); ++y) {
    int* row = labels.ptr<int>(y);
    for (int x = 0; x < g.width(); ++x) {
      if (grid.state(Cell{x, y}) == CellState::kFree) row[x] = world.roomAt(g.centerOf(Cell{x, y}));
    }
  }
  return labels;
}

nlohmann::json writeAnalysisMaps(const std::filesystem::path& directory,
                                 const AnalysisMap& semantic, const AnalysisMap& topological,
                                 const OccupancyGrid& grid, const sim::WorldModel* world) {
  const SemanticMap& rooms = *semantic.semanticMap();
  const TopologicalMap& topo = topological.topologicalMap();
  nlohmann::json extra = nlohmann::json::object();
  nlohmann::json summary = {{"topological",
                             {{"files", {"topology.json", "topology.png"}},
                              {"nodes", topo.nodes().size()},
                              {"edges", topo.edges().size()},
                              {"updates", topological.updateTimes_ms().size()}}},
                            {"semantic",
                             {{"files", {"semantic.json", "semantic.png", "semantic_labels.png"}},
                              {"regions", rooms.regions().size()},
                              {"updates", semantic.updateTimes_ms().size()}}}};
  if (world != nullptr && world->hasRooms()) {
    const SegmentationScore s =
        scoreSegmentation(rooms.labels(), groundTruthRoomLabels(grid, *world));
    extra["ground_truth_score"] = {{"rooms", s.ground_truth_rooms},
                                   {"segments", s.segments},
                                   {"recall", s.recall},
                                   {"precision", s.precision},
                                   {"pooled_recall", s.pooled_recall},
                                   {"pooled_precision", s.pooled_precision},
                                   {"iou", s.iou}};
    summary["semantic"]["ground_truth_score"] = extra["ground_truth_score"];
  }
  io::writeTopologicalMap(directory, topo, grid);
  io::writeSemanticMap(directory, rooms, grid, extra);
  return summary;
}

}  // namespace roomscout::experiment
