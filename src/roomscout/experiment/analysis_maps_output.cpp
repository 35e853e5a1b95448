#include "roomscout/experiment/analysis_maps_output.hpp"

#include "roomscout/io/semantic_io.hpp"
#include "roomscout/io/topology_io.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "roomscout/maps/topology_builder.hpp"

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
                              {"updates", topological.updateTimes_ms().size()},
                              {"full_updates", topological.fullUpdates()},
                              {"window_updates", topological.windowUpdates()}}},
                            {"semantic",
                             {{"files", {"semantic.json", "semantic.png", "semantic_labels.png"}},
                              {"regions", rooms.regions().size()},
                              {"updates", semantic.updateTimes_ms().size()},
                              {"full_updates", semantic.fullUpdates()},
                              {"window_updates", semantic.windowUpdates()}}}};
  if (world != nullptr && world->hasRooms()) {
    auto toJson = [](const SegmentationScore& s) {
      return nlohmann::json{{"rooms", s.ground_truth_rooms},
                            {"segments", s.segments},
                            {"recall", s.recall},
                            {"precision", s.precision},
                            {"pooled_recall", s.pooled_recall},
                            {"pooled_precision", s.pooled_precision},
                            {"iou", s.iou}};
    };
    const cv::Mat truth = groundTruthRoomLabels(grid, *world);
    extra["ground_truth_score"] = toJson(scoreSegmentation(rooms.labels(), truth));
    summary["semantic"]["ground_truth_score"] = extra["ground_truth_score"];
    // The rooms were updated where the map changed; a segmentation of the final map from
    // scratch, scored the same way, shows what that costs.
    const RoomSegmenter from_scratch(semantic.options().segmentation);
    summary["semantic"]["from_scratch_score"] =
        toJson(scoreSegmentation(from_scratch.segment(grid).labels, truth));
  }
  // The skeleton was updated where the map changed; the graph of the final map built from
  // scratch, for comparison.
  const TopologicalMap scratch = TopologyBuilder(topological.options().topology).build(grid);
  summary["topological"]["from_scratch"] = {{"nodes", scratch.nodes().size()},
                                            {"edges", scratch.edges().size()}};
  io::writeTopologicalMap(directory, topo, grid);
  io::writeSemanticMap(directory, rooms, grid, extra);
  return summary;
}

}  // namespace roomscout::experiment
