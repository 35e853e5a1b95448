// The rooms and skeleton graph on their schedule: the topology_every option, a worker.

#include "roomscout/explorer/analysis_maps.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

/// A 16 x 6 m map of three rooms in a row (walls with 1 m doors), revealed 1 m further to the
/// east at each step.
OccupancyGrid revealed(double seen_m) {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.05, 320, 120));
  const GridGeometry& g = grid.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Vec2 p = g.centerOf(Cell{x, y});
      if (p.x() > seen_m) continue;
      const bool border = x < 4 || y < 4 || x >= g.width() - 4 || y >= g.height() - 4;
      const bool partition = (std::abs(p.x() - 5.5) < 0.1 || std::abs(p.x() - 10.5) < 0.1) &&
                             std::abs(p.y() - 3.0) > 0.5;
      grid.setState(g.index(Cell{x, y}),
                    border || partition ? CellState::kOccupied : CellState::kFree);
    }
  }
  return grid;
}

struct Observed {
  std::size_t semantic_updates = 0, topological_updates = 0;
  TopologicalMap topology;
  cv::Mat room_labels;
};

/// @param rooms_worker, skeleton_worker where each map is built (null: at once)
Observed drive(const AnalysisMapsOptions& options, MapWorker* rooms_worker = nullptr,
               MapWorker* skeleton_worker = nullptr) {
  AnalysisMap semantic(AnalysisMapKind::kSemantic, options, nullptr, rooms_worker);
  AnalysisMap topological(AnalysisMapKind::kTopological, options, &semantic, skeleton_worker);
  double t = 0.0;
  for (double seen_m = 2.0; seen_m <= 16.0; seen_m += 1.0, t += 1.0) {
    const OccupancyGrid grid = revealed(seen_m);
    for (AnalysisMap* m : {&semantic, &topological}) m->observe(grid, t, true);
  }
  const OccupancyGrid final_grid = revealed(16.0);
  for (AnalysisMap* m : {&semantic, &topological}) m->finish(final_grid);
  return {semantic.updateTimes_ms().size(), topological.updateTimes_ms().size(),
          topological.topologicalMap(), semantic.semanticMap()->labels().clone()};
}

void expectSameTopology(const TopologicalMap& a, const TopologicalMap& b) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  ASSERT_EQ(a.edges().size(), b.edges().size());
  for (std::size_t i = 0; i < a.nodes().size(); ++i) {
    EXPECT_EQ(a.nodes()[i].position_m, b.nodes()[i].position_m);
    EXPECT_EQ(a.nodes()[i].region_id, b.nodes()[i].region_id);
  }
  for (std::size_t i = 0; i < a.edges().size(); ++i)
    EXPECT_EQ(a.edges()[i].polyline_m, b.edges()[i].polyline_m);
}

TEST(AnalysisMap, TopologyFollowsTheRoomsOrEveryNthOfTheirUpdates) {
  const Observed every = drive({});
  EXPECT_EQ(every.semantic_updates, 16u);  // 15 growing maps (>= 2 m^2 new each), then the end
  EXPECT_EQ(every.topological_updates, every.semantic_updates);
  AnalysisMapsOptions options;
  options.topology_every = 4;
  const Observed sparse = drive(options);
  EXPECT_EQ(sparse.semantic_updates, every.semantic_updates);
  EXPECT_EQ(sparse.topological_updates, 4u + 1u);  // updates 1, 5, 9, 13 of 15, then the end
  // The final topological map is the same.
  ASSERT_GT(every.topology.edges().size(), 0u);
  expectSameTopology(sparse.topology, every.topology);
}

TEST(AnalysisMap, MapsBuiltOnAWorkerAreThoseBuiltAtOnce) {
  const Observed at_once = drive({});
  ASSERT_GT(at_once.topology.edges().size(), 0u);
  double max_id = 0.0;
  cv::minMaxLoc(at_once.room_labels, nullptr, &max_id);
  EXPECT_GE(max_id, 3.0);  // the three rooms
  auto expectSame = [&](const Observed& o) {
    EXPECT_EQ(o.semantic_updates, at_once.semantic_updates);
    EXPECT_EQ(o.topological_updates, at_once.topological_updates);
    expectSameTopology(o.topology, at_once.topology);
    ASSERT_EQ(o.room_labels.size(), at_once.room_labels.size());
    EXPECT_EQ(cv::countNonZero(o.room_labels != at_once.room_labels), 0);
  };
  {
    SCOPED_TRACE("rooms and skeleton on one worker");
    MapWorker worker(true);
    expectSame(drive({}, &worker, &worker));
  }
  {
    SCOPED_TRACE("rooms at once, skeleton on a worker (reads copies of the rooms)");
    MapWorker worker(true);
    expectSame(drive({}, nullptr, &worker));
  }
  {
    SCOPED_TRACE("rooms and skeleton on two workers (waits for the rooms, reads copies)");
    MapWorker rooms(true), skeleton(true);
    expectSame(drive({}, &rooms, &skeleton));
  }
  {
    SCOPED_TRACE("rooms on a worker, skeleton at once (waits for the rooms)");
    MapWorker rooms(true);
    expectSame(drive({}, &rooms, nullptr));
  }
}

TEST(AnalysisMap, RejectsBadScheduleOptions) {
  AnalysisMapsOptions options;
  options.topology_every = 0;
  EXPECT_THROW(options.validate(), OptionError);
  options = {};
  options.period_s = 0.0;
  EXPECT_THROW(options.validate(), OptionError);
  EXPECT_NO_THROW(AnalysisMapsOptions{}.validate());
}

}  // namespace
}  // namespace roomscout
