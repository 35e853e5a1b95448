#pragma once
// The paper's topological and semantic maps, rebuilt from the occupancy grid on their own
// schedule while the robot explores (about once a second, as in the paper). One class, two
// instances: the semantic one ("semantic") owns the rooms that strategies read; the
// topological one ("topological") builds the skeleton graph and, given the semantic one,
// labels its nodes with room ids. Feed the semantic one first.
//
// Given a MapWorker, a map decides on the caller's thread when to update and what from (a
// copy of the grid's states, and of the rooms it labels nodes with, unless they are built on
// the same worker), and the worker builds it: the maps are those of updating at once, and
// they and the update times may be read after finish(). The rooms a strategy reads must be
// built without a worker. The grid may change size and origin between calls (a SLAM map that
// grows): room ids follow the map frame (SemanticMap::update).

#include <memory>
#include <string_view>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/explorer/map_worker.hpp"
#include "roomscout/maps/incremental_rooms.hpp"
#include "roomscout/maps/incremental_topology.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/maps/topological_map.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace roomscout {

enum class AnalysisMapKind { kTopological, kSemantic };

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct AnalysisMapsOptions {
  double period_s = 1.0;
  double min_new_area_m2 = 2.0;
  int topology_every = 1;
  IncrementalRoomsOptions rooms;
  IncrementalTopologyOptions skeleton;
  RoomSegmenterOptions segmentation;
  TopologyBuilderOptions topology;
  void validate() const;
  /// The schedule options (period_s, min_new_area_m2, topology_every) and the reach of the
  /// updates (rooms_*, skeleton_*); the algorithms have their own groups.
  std::vector<ParameterRef> parameters();
};

class AnalysisMap {
 public:
  /// @param rooms for the topological kind: the semantic map whose rooms label the nodes
  ///        (borrowed; may be null)
  /// @param worker runs the updates (borrowed; must outlive the map); null: at once
  AnalysisMap(AnalysisMapKind kind, const AnalysisMapsOptions& options = {},
              const AnalysisMap* rooms = nullptr, MapWorker* worker = nullptr);
  ~AnalysisMap();
  AnalysisMap(const AnalysisMap&) = delete;
  AnalysisMap& operator=(const AnalysisMap&) = delete;

  /// Key of its update times (e.g. in metrics.json's update_ms): "semantic" or "topological".
  std::string_view name() const;
  /// Shows the map the latest grid; it updates when its schedule says so.
  /// @param time_s any clock, never decreasing [s]
  /// @param grid_changed the grid may differ from the one of the previous call
  void observe(const OccupancyGrid& grid, double time_s, bool grid_changed);
  /// Brings the map up to date with the final grid and waits for its worker.
  void finish(const OccupancyGrid& grid, bool grid_changed = true);
  /// Wall-clock durations of its updates so far [ms] (with a worker: after finish()).
  const std::vector<double>& updateTimes_ms() const { return update_ms_; }
  /// The area the grid knew (free or occupied) at each of those updates [m^2].
  const std::vector<double>& updateKnownArea_m2() const { return update_known_m2_; }
  /// The rooms (semantic kind only; nullptr for the topological kind). With a worker, up to
  /// date only after finish().
  const SemanticMap* semanticMap() const;
  /// The skeleton graph (topological kind; empty for the semantic kind). With a worker, up to
  /// date only after finish().
  const TopologicalMap& topologicalMap() const { return topology_; }
  const AnalysisMapsOptions& options() const { return options_; }
  /// Updates that rebuilt the whole map (the first among them), and those that rebuilt a
  /// window around what changed (IncrementalRoomSegmenter, IncrementalTopologyBuilder). With
  /// a worker, final only after finish().
  int fullUpdates() const;
  int windowUpdates() const;

 private:
  void update(const OccupancyGrid& grid);
  /// Builds the map from one update's inputs (on the worker, if any).
  void build(const cv::Mat& states, const GridGeometry& geometry,
             std::shared_ptr<const SemanticMap> rooms);

  AnalysisMapKind kind_;
  AnalysisMapsOptions options_;
  const AnalysisMap* rooms_;
  MapWorker* worker_;  ///< null unless it has a thread: a worker without one changes nothing
  IncrementalRoomSegmenter segmenter_;
  IncrementalTopologyBuilder builder_;
  SemanticMap semantic_;
  TopologicalMap topology_;
  cv::Mat states_;                 ///< the grid's cell states at the last update (buffer reused)
  std::vector<double> update_ms_;  ///< written by build()
  std::vector<double> update_known_m2_;  ///< written by build()
  std::size_t updates_ = 0;              ///< updates decided so far (build() may still be behind)
  double next_update_s_ = 0.0;
  bool changed_ = false;
  std::size_t known_at_update_ = 0;
  std::size_t rooms_updates_seen_ = 0;  ///< topological kind: updates of rooms_ already followed
  std::size_t due_updates_ = 0;         ///< topological kind: updates due so far (topology_every)
  bool updated_once_ = false;
};

}  // namespace roomscout
