// The paper's semantic-region-aware strategy: its sampling law, where P_sem comes from, the
// sign of the room reward, and the behaviour it exists for (finish the room you are in).

#include "roomscout/exploration/detail/semantic_explorer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout {
namespace {

/// A 10 x 6 m grid at 0.05 m whose cells, and their rooms, come from a function of the cell:
/// `paint(x, y)` returns {state, room id (0 = none)}.
struct LabelledGrid {
  OccupancyGrid grid;
  Costmap costmap;
  SemanticMap semantic;
  /// A 10 x 6 m grid unless `height_cells` says otherwise (0.05 m cells, 200 wide).
  template <class Paint>
  explicit LabelledGrid(Paint paint, int height_cells = 120)
      : grid(GridGeometry({0.0, 0.0}, 0.05, 200, height_cells)) {
    const GridGeometry& g = grid.geometry();
    cv::Mat labels(g.height(), g.width(), CV_32S, cv::Scalar(0));
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        const auto [state, label] = paint(x, y);
        grid.setState(g.index(Cell{x, y}), state);
        labels.at<int>(y, x) = label;
      }
    }
    costmap.update(grid);
    semantic.update(g, labels, cv::Mat());
  }
};

/// x < 5 m is room 1, x >= 5 m room 2; known free for y < 3 m, unknown above.
struct TwoRoomGrid : LabelledGrid {
  TwoRoomGrid()
      : LabelledGrid([](int x, int y) {
          return y < 60 ? std::pair{CellState::kFree, x < 100 ? 1 : 2}
                        : std::pair{CellState::kUnknown, 0};
        }) {}
};

/// The decision after `grow_s` of tree growth with the robot standing still at `robot`.
template <class World>
Decision decideAfterGrowing(SemanticExplorer& s, const World& w, const Pose2& robot,
                            double grow_s = 20.0) {
  s.decide({w.grid, w.costmap, robot, 0.0, &w.semantic});
  return s.decide({w.grid, w.costmap, robot, grow_s, &w.semantic});
}

/// What a strategy with one scoring term set by `configure` does first: heading off (so that the
/// robot's yaw takes no part) and a dense tree (2000 iterations/s) grown with the robot at `robot`.
struct TermGoal {
  Decision decision;
  int room;
  bool hub;
  std::vector<Vec2> semantic_candidates;  ///< the cells P_sem was drawn from
};
template <class World, class Configure>
TermGoal firstGoalWithTerm(const World& w, std::uint64_t seed, const Pose2& robot,
                           Configure configure) {
  SemanticExplorerOptions o;
  o.score.heading_weight = 0.0;
  o.tree.iterations_per_s = 2000.0;
  configure(o);
  SemanticExplorer s(seed, o);
  const Decision d = decideAfterGrowing(s, w, robot);
  return {d, s.currentRoom(), s.inHub(), s.semanticCandidates()};
}

TEST(SemanticExplorerTest, SamplingProbabilityFollowsKtOverOnePlusKt) {
  EXPECT_DOUBLE_EQ(semanticSampleProbability(0.1, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(semanticSampleProbability(0.1, 10.0), 0.5);
  EXPECT_NEAR(semanticSampleProbability(0.5, 6.0), 0.75, 1e-12);
  EXPECT_DOUBLE_EQ(semanticSampleProbability(0.0, 100.0), 0.0);

  // The strategy's own draws, with a fixed seed: the robot sits in room 1 for t seconds; the
  // share of P_sem draws in the next second must match k t / (1 + k t) within 4 sigma.
  for (const double t : {5.0, 20.0, 60.0}) {
    TwoRoomGrid w;
    SemanticExplorerOptions o;
    o.tree.k = 0.1;
    o.tree.iterations_per_s = 20000.0;
    SemanticExplorer s(7, o);
    const Pose2 robot{2.0, 1.0, 0.0};
    s.decide({w.grid, w.costmap, robot, 0.0, &w.semantic});
    s.decide({w.grid, w.costmap, robot, t, &w.semantic});  // grows t * 20000 iterations
    const long sem0 = s.semanticDraws(), rad0 = s.randomDraws();
    s.decide({w.grid, w.costmap, robot, t + 1.0, &w.semantic});
    const double n = static_cast<double>((s.semanticDraws() - sem0) + (s.randomDraws() - rad0));
    ASSERT_GT(n, 10000.0);
    // The probability in force during the last call is that of its t (time in the room).
    const double p = semanticSampleProbability(o.tree.k, t + 1.0);
    const double share = static_cast<double>(s.semanticDraws() - sem0) / n;
    EXPECT_NEAR(share, p, 4.0 * std::sqrt(p * (1.0 - p) / n)) << "t = " << t;
  }
}

TEST(SemanticExplorerTest, SemanticPointsLieOnTheFrontierOfTheCurrentRoom) {
  TwoRoomGrid w;
  SemanticExplorer s(3);
  s.decide({w.grid, w.costmap, Pose2{2.0, 1.0, 0.0}, 0.0, &w.semantic});
  EXPECT_EQ(s.currentRoom(), 1);
  ASSERT_FALSE(s.semanticCandidates().empty());
  const GridGeometry& g = w.grid.geometry();
  for (const Vec2& p : s.semanticCandidates()) {
    const Cell c = g.cellOf(p);
    EXPECT_TRUE(w.grid.isFree(g.index(c)));
    EXPECT_EQ(w.semantic.roomAt(p), 1) << p.transpose();
    const bool next_to_unknown = w.grid.isUnknown(g.index(Cell{c.x + 1, c.y})) ||
                                 w.grid.isUnknown(g.index(Cell{c.x - 1, c.y})) ||
                                 w.grid.isUnknown(g.index(Cell{c.x, c.y + 1})) ||
                                 w.grid.isUnknown(g.index(Cell{c.x, c.y - 1}));
    EXPECT_TRUE(next_to_unknown) << p.transpose();
  }
  // In room 2 the candidates move there.
  SemanticExplorer s2(3);
  s2.decide({w.grid, w.costmap, Pose2{8.0, 1.0, 0.0}, 0.0, &w.semantic});
  EXPECT_EQ(s2.currentRoom(), 2);
  for (const Vec2& p : s2.semanticCandidates()) EXPECT_EQ(w.semantic.roomAt(p), 2);
}

TEST(SemanticExplorerTest, RoomRewardFlipsSignWithMembership) {
  SemanticExplorerOptions o;
  o.score.gain_weight = 2.0;
  o.score.cost_weight = 0.5;
  o.score.room_reward = 4.0;
  const SemanticExplorer s(1, o);
  EXPECT_DOUBLE_EQ(s.score(3.0, 2.0, true), 2.0 * 3.0 - 0.5 * 2.0 + 4.0);
  EXPECT_DOUBLE_EQ(s.score(3.0, 2.0, false), 2.0 * 3.0 - 0.5 * 2.0 - 4.0);
  EXPECT_DOUBLE_EQ(s.score(3.0, 2.0, true) - s.score(3.0, 2.0, false), 2.0 * o.score.room_reward);
}

/// The strategy's first goal in the two-room grid, the robot standing at (2, 1) m, with no
/// periodic switch: only the goal's own state decides whether it stands.
struct FirstGoal {
  TwoRoomGrid w;
  SemanticExplorerOptions o;
  SemanticExplorer s;
  Pose2 robot{2.0, 1.0, 0.0};
  Decision first;
  explicit FirstGoal(const SemanticExplorerOptions& options = {})
      : o(withoutPeriodicSwitch(options)), s(5, o), first(decideAfterGrowing(s, w, robot, 2.0)) {}
  static SemanticExplorerOptions withoutPeriodicSwitch(SemanticExplorerOptions options) {
    options.goal.replan_period_s = 100.0;
    return options;
  }
};

TEST(SemanticExplorerTest, KeepsItsGoalUntilTheGoalsSquareIsExplored) {
  FirstGoal f;
  auto& [w, o, s, robot, first] = f;
  ASSERT_EQ(first.status, Decision::Status::kGoal);
  const GridGeometry& g = w.grid.geometry();
  ASSERT_TRUE(w.grid.isUnknown(g.index(g.cellOf(first.goal_m))));

  // The goal's own cell and its neighbours are seen; the square around it still holds
  // unknown space, so the goal stands.
  // Plain variables for the lambda: clang 14 cannot capture structured bindings.
  auto& world = w;
  const Vec2 first_goal = first.goal_m;
  auto reveal = [&](double half_m) {
    const Cell c = g.cellOf(first_goal);
    const int r = static_cast<int>(std::lround(half_m / g.resolution_m()));
    for (int y = c.y - r; y <= c.y + r; ++y) {
      for (int x = c.x - r; x <= c.x + r; ++x) {
        if (g.contains(Cell{x, y})) world.grid.setState(g.index(Cell{x, y}), CellState::kFree);
      }
    }
    world.costmap.update(world.grid);
  };
  reveal(0.1);
  const Decision kept = s.decide({w.grid, w.costmap, robot, 2.5, &w.semantic});
  ASSERT_EQ(kept.status, Decision::Status::kGoal);
  EXPECT_LT((kept.goal_m - first.goal_m).norm(), 1e-9);

  // The whole square is seen: the strategy moves on to another point.
  reveal(o.score.gain_half_side_m + 0.05);
  const Decision next = s.decide({w.grid, w.costmap, robot, 3.0, &w.semantic});
  ASSERT_EQ(next.status, Decision::Status::kGoal);
  EXPECT_GT((next.goal_m - first.goal_m).norm(), 0.5);
  EXPECT_TRUE(w.grid.isUnknown(g.index(g.cellOf(next.goal_m))));
}

TEST(SemanticExplorerTest, DropsAGoalOnceTheWallBehindItIsSeen) {
  // The goal's square still holds unknown space, but behind a wall seen since: the outside of
  // a room corner. Whether the strategy keeps the goal then.
  auto keepsTheGoal = [](double min_frontier_m) {
    SemanticExplorerOptions options;
    options.slivers.min_frontier_m = min_frontier_m;
    FirstGoal f(options);
    auto& [w, o, s, robot, first] = f;
    EXPECT_EQ(first.status, Decision::Status::kGoal);
    // Known free up to 0.25 m beyond the goal, then a wall, over the goal's square and 1.5 m
    // either side of it; unknown beyond the wall (0.7 m deep in the square: more than
    // min_unknown_m2), and no free cell of the square next to unknown space.
    const GridGeometry& g = w.grid.geometry();
    const Cell c = g.cellOf(first.goal_m);
    const int r =
        static_cast<int>(std::lround((o.score.gain_half_side_m + 1.5) / g.resolution_m()));
    for (int y = 0; y <= c.y + 6; ++y) {
      for (int x = std::max(0, c.x - r); x <= std::min(g.width() - 1, c.x + r); ++x) {
        w.grid.setState(g.index(Cell{x, y}),
                        y == c.y + 6 ? CellState::kOccupied : CellState::kFree);
      }
    }
    w.costmap.update(w.grid);
    const Decision next = s.decide({w.grid, w.costmap, robot, 2.5, &w.semantic});
    EXPECT_EQ(next.status, Decision::Status::kGoal);
    return (next.goal_m - first.goal_m).norm() < 1e-9;
  };
  EXPECT_FALSE(keepsTheGoal(SemanticExplorerOptions{}.slivers.min_frontier_m));
  // Counting unknown area only, the square is not explored yet.
  EXPECT_TRUE(keepsTheGoal(0.0));
}

TEST(SemanticExplorerTest, DoesNotReturnToAGoalWhoseCellTurnedLethal) {
  // A wall seen from close by puts the goal's cell into the inflation, and the goal is dropped.
  // Seen from afar again, the wall fades back to unknown (log-odds fall with misses at grazing
  // angles): the tree finds the same cell again, and without a blacklist the robot shuttled
  // between two such points until its time limit.
  FirstGoal f;
  auto& [w, o, s, robot, first] = f;
  ASSERT_EQ(first.status, Decision::Status::kGoal);
  const GridGeometry& g = w.grid.geometry();
  const Cell c = g.cellOf(first.goal_m);
  const Cell wall{c.x, c.y + 1};
  ASSERT_TRUE(g.contains(wall));
  w.grid.setState(g.index(wall), CellState::kOccupied);
  w.costmap.update(w.grid);
  ASSERT_TRUE(w.costmap.isLethal(g.index(c)));
  const Decision dropped = s.decide({w.grid, w.costmap, robot, 2.5, &w.semantic});
  ASSERT_EQ(dropped.status, Decision::Status::kGoal);
  EXPECT_GT((dropped.goal_m - first.goal_m).norm(), o.goal.blacklist_radius_m);

  // The wall fades; however long the tree grows, that cell is no goal again.
  w.grid.setState(g.index(wall), CellState::kUnknown);
  w.costmap.update(w.grid);
  for (double t = 3.0; t <= 60.0; t += 1.0) {
    s.decide({w.grid, w.costmap, robot, t, &w.semantic});
    for (const SemanticExplorer::FrontierPoint& point : s.frontierPoints()) {
      EXPECT_GT((point.p - first.goal_m).norm(), o.goal.blacklist_radius_m - 1e-9) << "t = " << t;
    }
  }
}

/// A hallway with four rooms along it: room 1 is the hallway, y < 1.5 m and x < 9 m, running on
/// into unknown space at x = 9 m; rooms 2-5, 2.25 m wide each, lie north of it for x < 9 m and
/// 1.5 <= y < 4 m, unknown beyond y = 4 m, with a wall at x = 9 m. Only the labels part the
/// rooms, so the hallway has four neighbouring rooms.
struct HallwayGrid : LabelledGrid {
  HallwayGrid()
      : LabelledGrid([](int x, int y) {
          if (x == 180 && y >= 30) return std::pair{CellState::kOccupied, 0};
          if (x >= 180 || y >= 80) return std::pair{CellState::kUnknown, 0};
          return std::pair{CellState::kFree, y < 30 ? 1 : 2 + x / 45};
        }) {}
};

TEST(SemanticExplorerTest, InAHallwayTakesTheRoomBesideItInsteadOfTheHallwaysFarEnd) {
  // Robot in the hallway at x = 2 m: the rooms north of it open 3.3 m away, the hallway's own
  // frontier 7 m away. With the room reward the hallway's end wins (+A against -A); the hub
  // rule drops the reward there, and a room beside the robot wins. In the hub P_sem comes from
  // the frontier near the robot: the rooms' frontier within 4.5 m, not the hallway's end.
  auto firstGoal = [](int hub_min_neighbours, bool& in_hub, std::vector<Vec2>& candidates) {
    HallwayGrid w;
    ASSERT_EQ(w.semantic.region(1)->neighbours.size(), 4u);
    SemanticExplorerOptions o;
    o.rooms.hub_min_neighbours = hub_min_neighbours;
    o.tree.iterations_per_s = 2000.0;
    SemanticExplorer s(11, o);
    const Decision d = decideAfterGrowing(s, w, Pose2{2.0, 0.75, 0.0});
    EXPECT_EQ(s.currentRoom(), 1);
    in_hub = s.inHub();
    candidates = s.semanticCandidates();
    ASSERT_EQ(d.status, Decision::Status::kGoal);
    if (in_hub) {
      EXPECT_DOUBLE_EQ(s.score(2.0, 3.0, true), s.score(2.0, 3.0, false));
      EXPECT_GT(d.goal_m.y(), 3.9) << d.goal_m.transpose();  // a room's far side
      EXPECT_LT(d.goal_m.x(), 4.5) << d.goal_m.transpose();  // room 2 or 3
    } else {
      EXPECT_GT(d.goal_m.x(), 8.9) << d.goal_m.transpose();  // the hallway's end
      EXPECT_LT(d.goal_m.y(), 1.6) << d.goal_m.transpose();
    }
  };
  bool in_hub = false;
  std::vector<Vec2> candidates;
  firstGoal(SemanticExplorerOptions{}.rooms.hub_min_neighbours, in_hub, candidates);
  EXPECT_TRUE(in_hub);
  ASSERT_FALSE(candidates.empty());
  const SemanticExplorerOptions defaults;
  const double reach_m = defaults.rooms.hub_sample_radius_m + 0.1;
  for (const Vec2& c : candidates) {
    EXPECT_LE((c - Vec2(2.0, 0.75)).lpNorm<Eigen::Infinity>(), reach_m) << c.transpose();
    EXPECT_GT(c.y(), 3.8) << c.transpose();  // the rooms' frontier, not the hallway's end
  }
  firstGoal(0, in_hub, candidates);
  EXPECT_FALSE(in_hub);
  ASSERT_FALSE(candidates.empty());
  for (const Vec2& c : candidates)
    EXPECT_LT(c.y(), 1.5) << c.transpose();  // the hallway's own: its end
  firstGoal(5, in_hub, candidates);          // four neighbours: no hub at five
  EXPECT_FALSE(in_hub);

  // A room off the hallway, with one neighbour, is no hub.
  HallwayGrid w;
  SemanticExplorer s(11);
  s.decide({w.grid, w.costmap, Pose2{1.0, 2.5, 0.0}, 0.0, &w.semantic});
  EXPECT_EQ(s.currentRoom(), 2);
  EXPECT_FALSE(s.inHub());
}

/// A finished room (room 1, x < 2 m) beside room 2 (2 m <= x < 6 m), both 1 m <= y < 3 m with
/// solid ground around. Two ways on: a 1.2 m gap in room 2's north wall at x = 2.6 m into a
/// 1.2 m wide, 2.95 m deep alcove, and room 2's open east end into a 2 x 2 m unknown space
/// (the wall behind it, at x = 8 m, seen). The alcove's squares hold about 0.3 m^2 of G (1.2
/// m^2 unknown, 0.9 m^2 wall), the east end's up to 2 m^2.
struct NextRoomGrid : LabelledGrid {
  NextRoomGrid()
      : LabelledGrid([](int x, int y) {
          if (y >= 20 && y < 60 && x < 120) return std::pair{CellState::kFree, x < 40 ? 1 : 2};
          if (x >= 52 && x < 76 && y >= 60 && y < 119) return std::pair{CellState::kUnknown, 0};
          if (x >= 120 && x < 160 && y >= 20 && y < 60) return std::pair{CellState::kUnknown, 0};
          return std::pair{CellState::kOccupied, 0};  // walls and what lies behind them
        }) {}
};

TEST(SemanticExplorerTest, ChoosingTheNextRoomTheNearestComesFirst) {
  // The robot has finished room 1. The plain score (w_g G - w_c C) takes room 2's open east end,
  // 5 m away with more unknown space around it; with C weighed next_room_cost_factor times,
  // the alcove 2.5 m away comes first instead of being left to fetch later. Without the
  // segment term, which favours the east end's 2 m of frontier over the alcove's 1.2 m: this is
  // about the factor alone.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const double factor : {1.0, SemanticExplorerOptions{}.score.next_room_cost_factor}) {
      NextRoomGrid w;
      SemanticExplorerOptions o;
      o.score.next_room_cost_factor = factor;
      o.score.segment_weight = 0.0;
      o.rooms.leaf_rooms = false;  // room 2 is a dead end off room 1
      o.tree.iterations_per_s = 2000.0;
      SemanticExplorer s(seed, o);
      const Decision d = decideAfterGrowing(s, w, Pose2{1.0, 2.0, 0.0});
      EXPECT_EQ(s.currentRoom(), 1);
      EXPECT_FALSE(s.inHub());
      EXPECT_TRUE(s.semanticCandidates().empty());  // room 1 is finished
      ASSERT_EQ(d.status, Decision::Status::kGoal);
      if (factor == 1.0) {
        EXPECT_GT(d.goal_m.x(), 5.9)
            << "seed " << seed << ": " << d.goal_m.transpose();  // the east end
      } else {
        EXPECT_LT(d.goal_m.x(), 4.0)
            << "seed " << seed << ": " << d.goal_m.transpose();  // the alcove
        EXPECT_GT(d.goal_m.y(), 2.9) << "seed " << seed << ": " << d.goal_m.transpose();
      }
    }
  }
}

/// A finished room (room 1, 4 x 2 m, x 4-6 m, y 5-7 m) between two 1 m corridors, each a room
/// of its own and open at its end: south to y = 2 m (4 m from the room's middle), north to
/// y = 11 m (5 m). Beyond the corridors' walls all is unknown but for three 0.6 m patches of
/// floor beside the north corridor (seen through a gap, say), 1.5-2.5 m from its end: frontier
/// around the north end, outside G's square and not reachable by the tree. 10 x 12 m.
struct FrontierMassGrid : LabelledGrid {
  FrontierMassGrid()
      : LabelledGrid(
            [](int x, int y) {
              auto in = [&](int x0, int x1, int y0, int y1) {
                return x >= x0 && x < x1 && y >= y0 && y < y1;
              };
              if (in(80, 120, 100, 140)) return std::pair{CellState::kFree, 1};
              if (in(90, 110, 40, 100)) return std::pair{CellState::kFree, 2};
              if (in(90, 110, 140, 220)) return std::pair{CellState::kFree, 3};
              if (in(50, 62, 170, 182) || in(140, 152, 170, 182) || in(50, 62, 200, 212)) {
                return std::pair{CellState::kFree, 0};
              }
              if (in(78, 122, 98, 142) || in(88, 112, 40, 220))
                return std::pair{CellState::kOccupied, 0};
              // Known corners (walls) so that the known cells' box, which the uniform samples
              // come from, reaches past the corridors' ends.
              if (in(0, 4, 0, 4) || in(196, 200, 236, 240))
                return std::pair{CellState::kOccupied, 0};
              return std::pair{CellState::kUnknown, 0};
            },
            240) {}
};

TEST(SemanticExplorerTest, ChoosingTheNextRoomTheSideWithMoreFrontierAroundItComesFirst) {
  // Both corridor ends open the same way (G, the segment term); the south one is 1 m nearer,
  // 3 in S with C weighed next_room_cost_factor times. The frontier mass term adds 6.6 m of
  // the patches' frontier (x 1 per metre) to the north end and takes it.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const double weight : {0.0, SemanticExplorerOptions{}.score.mass_weight}) {
      FrontierMassGrid w;
      const TermGoal g =
          firstGoalWithTerm(w, seed, Pose2{5.0, 6.0, 0.0}, [&](SemanticExplorerOptions& o) {
            o.score.mass_weight = weight;
            o.rooms.leaf_rooms = false;  // both corridors are dead ends off room 1
          });
      EXPECT_NE(g.room, 0);
      EXPECT_FALSE(g.hub);
      const Decision& d = g.decision;
      ASSERT_EQ(d.status, Decision::Status::kGoal);
      if (weight == 0.0) {
        EXPECT_LT(d.goal_m.y(), 2.5)
            << "seed " << seed << ": " << d.goal_m.transpose();  // south end
      } else {
        EXPECT_GT(d.goal_m.y(), 10.5)
            << "seed " << seed << ": " << d.goal_m.transpose();  // north end
      }
    }
  }
}

/// A finished room (room 1, x 0.2-3.8 m, y 0.2-3.8 m) with two doors: east (y 0.5-1.3 m) into
/// room 2, a dead end (its only neighbour is room 1), seen up to x = 5 m and unknown beyond;
/// north (x 1.5-2.3 m) into rooms 3 and 4, side by side (so neither is a leaf), seen up to
/// y = 5 m and unknown beyond. From the robot at (2, 3.3) m room 3's frontier is 1.7 m away,
/// room 2's over 4 m. All else is wall. 10 x 8 m.
struct LeafRoomGrid : LabelledGrid {
  LeafRoomGrid()
      : LabelledGrid(
            [](int x, int y) {
              auto in = [&](int x0, int x1, int y0, int y1) {
                return x >= x0 && x < x1 && y >= y0 && y < y1;
              };
              if (in(4, 76, 4, 76) || in(76, 80, 10, 26) || in(30, 46, 76, 80)) {
                return std::pair{CellState::kFree, 1};
              }
              if (in(80, 100, 4, 56)) return std::pair{CellState::kFree, 2};
              if (in(20, 60, 80, 100)) return std::pair{CellState::kFree, x < 40 ? 3 : 4};
              if (in(100, 140, 4, 56) || in(20, 60, 100, 150))
                return std::pair{CellState::kUnknown, 0};
              return std::pair{CellState::kOccupied, 0};
            },
            160) {}
};

TEST(SemanticExplorerTest, ALeafRoomOffTheCurrentRoomIsFinishedWithIt) {
  // Leaving room 1, the nearest room seen is room 3 (next_room_cost_factor). Room 2 opens only
  // onto room 1: left now, it is a dead end to come back to. With leaf_rooms it counts as part
  // of room 1, so P_sem is drawn from its frontier and its points take +A.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const bool leaf : {false, true}) {
      LeafRoomGrid w;
      ASSERT_EQ(w.semantic.region(2)->neighbours, std::vector<int>{1});
      ASSERT_EQ(w.semantic.region(3)->neighbours.size(), 2u);
      const TermGoal g =
          firstGoalWithTerm(w, seed, Pose2{2.0, 3.3, 0.0},
                            [&](SemanticExplorerOptions& o) { o.rooms.leaf_rooms = leaf; });
      EXPECT_EQ(g.room, 1);
      EXPECT_FALSE(g.hub);
      EXPECT_EQ(g.semantic_candidates.empty(), !leaf);
      for (const Vec2& p : g.semantic_candidates)
        EXPECT_EQ(w.semantic.roomAt(p), 2) << p.transpose();
      const Decision& d = g.decision;
      ASSERT_EQ(d.status, Decision::Status::kGoal);
      if (leaf) {
        EXPECT_GT(d.goal_m.x(), 4.5) << "seed " << seed << ": " << d.goal_m.transpose();  // room 2
      } else {
        EXPECT_GT(d.goal_m.y(), 4.5)
            << "seed " << seed << ": " << d.goal_m.transpose();  // rooms 3-4
      }
    }
  }
}

/// One room (room 1, 10 x 6 m, known free) whose north wall (y = 6 m) has two gaps, never seen
/// through, onto the unknown space beyond it: a narrow one (1.2 m, x 2.4-3.6 m) and a wide one
/// (2.4 m, x 6.8-9.2 m). The squares of G around their points hold about the same unknown area.
struct TwoGapGrid : LabelledGrid {
  TwoGapGrid()
      : LabelledGrid(
            [](int x, int y) {
              const bool gap = (x >= 48 && x < 72) || (x >= 136 && x < 184);
              if (y < 120) return std::pair{CellState::kFree, 1};
              if (y == 120 && !gap) return std::pair{CellState::kOccupied, 0};
              return std::pair{CellState::kUnknown, 0};
            },
            180) {}
};

TEST(SemanticExplorerTest, TheLongerFrontierSegmentWinsByTheSegmentTerm) {
  // The robot stands 3 m from the narrow gap and about 4.8 m from the wide one's near end.
  // Without the segment term the nearer gap wins (C); with it (4 per metre up to 2 m: 8 against
  // 4.8) the gap onto more unseen space does.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const double weight : {0.0, SemanticExplorerOptions{}.score.segment_weight}) {
      TwoGapGrid w;
      const Decision d =
          firstGoalWithTerm(w, seed, Pose2{3.0, 3.0, 0.0}, [&](SemanticExplorerOptions& o) {
            o.score.segment_weight = weight;
          }).decision;
      ASSERT_EQ(d.status, Decision::Status::kGoal);
      EXPECT_GT(d.goal_m.y(), 5.9) << "seed " << seed;
      if (weight == 0.0) {
        EXPECT_LT(d.goal_m.x(), 3.6)
            << "seed " << seed << ": " << d.goal_m.transpose();  // the narrow gap
      } else {
        EXPECT_GT(d.goal_m.x(), 6.6)
            << "seed " << seed << ": " << d.goal_m.transpose();  // the wide gap
      }
    }
  }
}

/// Two known rooms (10 x 5 m, x < 5 m is room 1) and, in room 2, a 1.5 x 1.5 m block whose
/// north, east and south faces were seen (occupied) but whose west face and interior never were:
/// the unknown inside of a cupboard whose front the laser only grazed. Nothing else is unknown.
struct PocketGrid : LabelledGrid {
  static constexpr int kX0 = 140, kX1 = 170, kY0 = 40, kY1 = 70;  // the block [cells]
  PocketGrid()
      : LabelledGrid(
            [](int x, int y) {
              const bool block = x >= kX0 && x <= kX1 && y >= kY0 && y <= kY1;
              if (block && (x == kX1 || y == kY0 || y == kY1))
                return std::pair{CellState::kOccupied, 0};
              if (block) return std::pair{CellState::kUnknown, 0};
              return std::pair{CellState::kFree, x < 100 ? 1 : 2};
            },
            100) {}
  bool nearBlock(const Vec2& p) const {
    const Vec2 lo = grid.geometry().centerOf(Cell{kX0, kY0}),
               hi = grid.geometry().centerOf(Cell{kX1, kY1});
    return p.x() > lo.x() - 1.0 && p.x() < hi.x() + 1.0 && p.y() > lo.y() - 1.0 &&
           p.y() < hi.y() + 1.0;
  }
};

TEST(SemanticExplorerTest, DoesNotDriveToAPocketOfUnknownSpaceInAnotherRoom) {
  // Whether any goal of 20 s of decisions, the robot standing in room 1, lies at the block.
  auto goesToTheBlock = [](double pocket_area_m2) {
    PocketGrid w;
    SemanticExplorerOptions o;
    o.slivers.pocket_area_m2 = pocket_area_m2;
    SemanticExplorer s(11, o);
    bool at_block = false;
    for (double t = 0.0; t <= 20.0; t += 1.0) {
      const Decision d = s.decide({w.grid, w.costmap, Pose2{2.0, 2.5, 0.0}, t, &w.semantic});
      if (d.status == Decision::Status::kGoal && w.nearBlock(d.goal_m)) at_block = true;
    }
    bool tree_found_it = false;
    for (const auto& f : s.frontierPoints()) tree_found_it = tree_found_it || w.nearBlock(f.p);
    EXPECT_TRUE(tree_found_it) << "pocket_area_m2 " << pocket_area_m2;
    return at_block;
  };
  // About 1.1 m^2 of the block's inside is unknown and clear of the inflation: a pocket.
  EXPECT_FALSE(goesToTheBlock(SemanticExplorerOptions{}.slivers.pocket_area_m2));
  // Without the test, its open face is the best (the only) frontier point.
  EXPECT_TRUE(goesToTheBlock(0.0));
}

TEST(SemanticExplorerTest, OnceIdleLooksIntoAPocketThatIsLargeForTheMap) {
  // The robot stands in room 1 for 100 s of decisions. The block's 1.1 m^2 is a pocket by
  // pocket_area_m2 (2 m^2), but 2.3 % of the 48 m^2 of known floor: in a flat that small it is
  // as likely a wedge of floor the laser saw past a door jamb (a HouseExpo plan ended at 97 %
  // with one), so once nothing else is left it is looked at instead of ending there.
  struct Outcome {
    double first_block_goal_s = -1.0;
    double done_s = -1.0;
  };
  auto run = [](double fraction) {
    PocketGrid w;
    SemanticExplorerOptions o;
    o.slivers.pocket_area_fraction = fraction;
    SemanticExplorer s(11, o);
    Outcome out;
    for (double t = 0.0; t <= 100.0 && out.done_s < 0.0; t += 1.0) {
      const Decision d = s.decide({w.grid, w.costmap, Pose2{2.0, 2.5, 0.0}, t, &w.semantic});
      if (d.status == Decision::Status::kDone) out.done_s = t;
      if (d.status == Decision::Status::kGoal && w.nearBlock(d.goal_m) &&
          out.first_block_goal_s < 0.0) {
        out.first_block_goal_s = t;
      }
    }
    return out;
  };
  const SemanticExplorerOptions defaults;
  const Outcome with = run(defaults.slivers.pocket_area_fraction);
  EXPECT_GE(with.first_block_goal_s, defaults.end.idle_end_s) << "not before idling";
  EXPECT_LT(with.done_s, 0.0) << "ended at " << with.done_s << " s";
  const Outcome without = run(0.0);
  EXPECT_LT(without.first_block_goal_s, 0.0);
  // Idle with nothing left but a pocket: the end phase has no cell to visit, so it ends.
  EXPECT_GE(without.done_s, defaults.end.idle_end_s) << "not before idling";
}

/// A known 12 x 6 m floor split by a wall at x = 4 m that leaves a 1 m gap at the north end,
/// with two unknown blocks: A just east of the wall (1.5 m from the robot in a straight line,
/// about 10 m around the wall) and B in the west room's north-west corner (about 3.5 m away
/// either way).
struct WallGrid {
  OccupancyGrid grid{GridGeometry({0.0, 0.0}, 0.05, 240, 120)};
  Costmap costmap;
  WallGrid() {
    const GridGeometry& g = grid.geometry();
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        const Vec2 p = g.centerOf(Cell{x, y});
        CellState s = CellState::kFree;
        if (p.x() > 3.95 && p.x() < 4.05 && p.y() < 5.0) s = CellState::kOccupied;
        if (inA(p) || inB(p)) s = CellState::kUnknown;
        grid.setState(g.index(Cell{x, y}), s);
      }
    }
    costmap.update(grid);
  }
  static bool inA(const Vec2& p) { return p.x() > 4.5 && p.x() < 6.0 && p.y() < 2.0; }
  static bool inB(const Vec2& p) { return p.x() < 1.2 && p.y() > 3.5; }
};

TEST(SemanticExplorerTest, CostsAPointByThePathToItNotTheStraightLine) {
  // The goal after 20 s of tree growth, the robot standing at (3, 1) west of the wall.
  auto goal = [](bool geodesic) {
    WallGrid w;
    SemanticExplorerOptions o;
    o.score.geodesic_cost = geodesic;
    SemanticExplorer s(5, o);
    const Pose2 robot{3.0, 1.0, 0.0};
    s.decide({w.grid, w.costmap, robot, 0.0, nullptr});
    const Decision d = s.decide({w.grid, w.costmap, robot, 20.0, nullptr});
    EXPECT_EQ(d.status, Decision::Status::kGoal);
    bool found_a = false, found_b = false;
    for (const auto& f : s.frontierPoints()) {
      found_a = found_a || (f.p.x() > 4.0 && f.p.y() < 2.5);
      found_b = found_b || (f.p.x() < 1.7 && f.p.y() > 3.0);
    }
    EXPECT_TRUE(found_a && found_b) << "the tree must have found both blocks";
    return d.goal_m;
  };
  const Vec2 by_path = goal(true);
  EXPECT_TRUE(by_path.x() < 1.7 && by_path.y() > 3.0) << "goal " << by_path.transpose();
  // The straight line makes the block behind the wall look nearest.
  const Vec2 by_line = goal(false);
  EXPECT_TRUE(by_line.x() > 4.0 && by_line.y() < 2.5) << "goal " << by_line.transpose();
}

TEST(SemanticExplorerTest, EndPhaseTakesTheCellNearestByPath) {
  // Every tree point is a sliver (min_unknown_m2 beyond any square), so the robot standing at
  // (3, 1) idles and then, in the end phase, visits frontier cells: first the one nearest by C.
  // By path that is block B (3.5 m); in a straight line block A, behind the wall (1.5 m).
  auto first_end_goal = [](bool geodesic) {
    WallGrid w;
    SemanticExplorerOptions o;
    o.slivers.min_unknown_m2 = 100.0;
    o.score.geodesic_cost = geodesic;
    SemanticExplorer s(5, o);
    const Pose2 robot{3.0, 1.0, 0.0};
    for (double t = 0.0; t <= 2.0 * o.end.idle_end_s; t += 1.0) {
      const Decision d = s.decide({w.grid, w.costmap, robot, t, nullptr});
      if (d.status == Decision::Status::kGoal && (d.goal_m - robot.position()).norm() > 0.5) {
        EXPECT_GE(t, o.end.idle_end_s) << "not before idling";
        return d.goal_m;
      }
    }
    ADD_FAILURE() << "no end-phase goal";
    return Vec2(0.0, 0.0);
  };
  const Vec2 by_path = first_end_goal(true);
  EXPECT_TRUE(WallGrid::inB(by_path)) << "goal " << by_path.transpose();
  const Vec2 by_line = first_end_goal(false);
  EXPECT_TRUE(WallGrid::inA(by_line)) << "goal " << by_line.transpose();
}

/// One room, known free for 2.5 m <= x < 7.5 m, unknown beyond both ends.
struct CorridorGrid : LabelledGrid {
  CorridorGrid()
      : LabelledGrid([](int x, int) {
          return x >= 50 && x < 150 ? std::pair{CellState::kFree, 1}
                                    : std::pair{CellState::kUnknown, 0};
        }) {}
};

TEST(SemanticExplorerTest, OfTwoEqualEndsTakesTheOneAhead) {
  // The robot in the middle of the corridor sees two ends alike in gain and cost. The heading
  // term takes the one it faces, so that the robot does not turn round for a point no better
  // than the one in front of it.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    for (const double yaw : {0.0, M_PI}) {
      CorridorGrid w;
      SemanticExplorerOptions o;
      o.tree.iterations_per_s = 2000.0;
      SemanticExplorer s(seed, o);
      const Decision d = decideAfterGrowing(s, w, Pose2{5.0, 3.0, yaw});
      ASSERT_EQ(d.status, Decision::Status::kGoal);
      bool east = false, west = false;
      for (const auto& f : s.frontierPoints()) {
        east = east || f.p.x() > 7.4;
        west = west || f.p.x() < 2.6;
      }
      ASSERT_TRUE(east && west) << "seed " << seed << ": the tree must have found both ends";
      if (yaw == 0.0) {
        EXPECT_GT(d.goal_m.x(), 7.4) << "seed " << seed << ": " << d.goal_m.transpose();
      } else {
        EXPECT_LT(d.goal_m.x(), 2.6) << "seed " << seed << ": " << d.goal_m.transpose();
      }
    }
  }
}

TEST(SemanticExplorerTest, KeepsItsGoalWhenTheRobotTurnsAwayFromIt) {
  // The robot facing east takes the east end; then it faces west (as it does where its path
  // bends round a wall) and, a replan period later, the west end is no better than the goal:
  // the heading term is a cost of turning away from the goal the robot drives to, so the goal
  // itself never pays it and the robot does not swing round.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    CorridorGrid w;
    SemanticExplorerOptions o;
    o.tree.iterations_per_s = 2000.0;
    SemanticExplorer s(seed, o);
    s.decide({w.grid, w.costmap, Pose2{5.0, 3.0, 0.0}, 0.0, &w.semantic});
    const Decision first = s.decide({w.grid, w.costmap, Pose2{5.0, 3.0, 0.0}, 20.0, &w.semantic});
    ASSERT_EQ(first.status, Decision::Status::kGoal);
    ASSERT_GT(first.goal_m.x(), 7.4) << "seed " << seed << ": " << first.goal_m.transpose();
    const Decision later = s.decide({w.grid, w.costmap, Pose2{5.0, 3.0, M_PI}, 30.0, &w.semantic});
    ASSERT_EQ(later.status, Decision::Status::kGoal);
    EXPECT_GT(later.goal_m.x(), 7.4) << "seed " << seed << ": " << later.goal_m.transpose();
  }
}

/// A 1 m wide corridor, 2.5 m <= y < 3.5 m, labelled room 1 for x < 5 m and seen but not yet
/// labelled for 5 m <= x < 7 m (the segmentation has not run since), unknown from x = 7 m on.
/// Behind its north wall (3.5 m <= y < 3.6 m) lies room 2, known and labelled; south of the
/// corridor is solid ground.
struct FreshCorridorGrid : LabelledGrid {
  FreshCorridorGrid()
      : LabelledGrid([](int x, int y) {
          if (x >= 140) return std::pair{CellState::kUnknown, 0};
          if (y >= 72) return std::pair{CellState::kFree, 2};
          if (y < 50 || y >= 70) return std::pair{CellState::kOccupied, 0};
          return std::pair{CellState::kFree, x < 100 ? 1 : 0};
        }) {}
};

TEST(SemanticExplorerTest, TakesTheCorridorSeenSinceTheLastSegmentationAsItsRoom) {
  // The corridor's open end, 2 m past the last labelled cell, is the current room's frontier:
  // the unlabelled cells take the room they connect to through free cells (room 1), not the
  // one 0.15 m away across the wall (room 2). So P_sem is drawn there and the end is the goal.
  auto run = [](double label_search_m, std::vector<Vec2>& candidates) {
    FreshCorridorGrid w;
    SemanticExplorerOptions o;
    o.rooms.label_search_m = label_search_m;
    o.tree.iterations_per_s = 2000.0;
    SemanticExplorer s(4, o);
    const Decision d = decideAfterGrowing(s, w, Pose2{1.0, 3.0, 0.0});
    EXPECT_EQ(s.currentRoom(), 1);
    candidates = s.semanticCandidates();
    return d;
  };
  std::vector<Vec2> candidates;
  const Decision d = run(SemanticExplorerOptions{}.rooms.label_search_m, candidates);
  ASSERT_FALSE(candidates.empty());
  for (const Vec2& c : candidates) {
    EXPECT_GT(c.x(), 6.8) << c.transpose();  // the corridor's end ...
    EXPECT_LT(c.y(), 3.5) << c.transpose();  // ... not room 2's edge at x = 7 m
  }
  ASSERT_EQ(d.status, Decision::Status::kGoal);
  EXPECT_GT(d.goal_m.x(), 6.9) << d.goal_m.transpose();
  EXPECT_LT(d.goal_m.y(), 3.5) << d.goal_m.transpose();
  // Searching only 0.5 m for a label, the end belongs to no room: no P_sem there.
  run(0.5, candidates);
  EXPECT_TRUE(candidates.empty());
}

/// The options of a registered semantic_* strategy, through its parameters() (as the CLI sets
/// them), compared with `expected` field by field.
void expectOptions(std::string_view method, const SemanticExplorerOptions& expected) {
  auto strategy = createStrategy(method, 1);
  SemanticExplorerOptions copy = expected;
  const std::vector<ParameterRef> want = copy.parameters();
  const std::vector<ParameterRef> got = strategy->parameters();
  ASSERT_EQ(got.size(), want.size()) << method;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].name, want[i].name) << method;
    std::visit(
        [&](auto* g) {
          using T = std::remove_pointer_t<decltype(g)>;
          EXPECT_EQ(*g, *std::get<T*>(want[i].value)) << method << "." << got[i].name;
        },
        got[i].value);
  }
}

TEST(SemanticExplorerTest, ThePapersPresetHasEveryAdditionOff) {
  const SemanticExplorerOptions p = SemanticExplorerOptions::paper();
  EXPECT_NO_THROW(p.validate());
  // improved_rrt's tree, Euclidean C.
  EXPECT_EQ(p.tree.eta_m, 1.0);
  EXPECT_EQ(p.tree.iterations_per_s, 100.0);
  EXPECT_FALSE(p.score.geodesic_cost);
  // Slivers, label search, hubs, next room, heading, segment, leaf rooms, idle and end phase.
  EXPECT_EQ(p.slivers.min_unknown_m2, 0.0);
  EXPECT_EQ(p.slivers.min_frontier_m, 0.0);
  EXPECT_EQ(p.slivers.pocket_area_m2, 0.0);
  EXPECT_EQ(p.slivers.pocket_area_fraction, 0.0);
  EXPECT_EQ(p.rooms.label_search_m, 0.0);
  EXPECT_EQ(p.rooms.hub_min_neighbours, 0);
  EXPECT_EQ(p.score.next_room_cost_factor, 1.0);
  EXPECT_EQ(p.score.mass_weight, 0.0);
  EXPECT_EQ(p.score.heading_weight, 0.0);
  EXPECT_EQ(p.score.segment_weight, 0.0);
  EXPECT_FALSE(p.rooms.leaf_rooms);
  EXPECT_EQ(p.end.idle_end_s, 0.0);
  // The paper's terms at semantic's values.
  const SemanticExplorerOptions d;
  EXPECT_EQ(p.tree.k, d.tree.k);
  EXPECT_EQ(p.score.gain_weight, d.score.gain_weight);
  EXPECT_EQ(p.score.cost_weight, d.score.cost_weight);
  EXPECT_EQ(p.score.room_reward, d.score.room_reward);
  EXPECT_EQ(p.score.gain_half_side_m, d.score.gain_half_side_m);
  // What it keeps to run and end: goal persistence, blacklist, improved_rrt's end test.
  EXPECT_EQ(p.goal.goal_min_unknown_m2, d.goal.goal_min_unknown_m2);
  EXPECT_EQ(p.goal.replan_period_s, d.goal.replan_period_s);
  EXPECT_EQ(p.goal.switch_margin, d.goal.switch_margin);
  EXPECT_EQ(p.goal.blacklist_radius_m, d.goal.blacklist_radius_m);
  EXPECT_EQ(p.end.end_checks, d.end.end_checks);
  EXPECT_EQ(p.end.end_min_frontier_cells, d.end.end_min_frontier_cells);
  EXPECT_EQ(p.end.end_pocket_area_m2, 4.0);
  EXPECT_EQ(d.end.end_pocket_area_m2, 0.0);
}

TEST(SemanticExplorerTest, TheRegisteredPresetsAreThePapersAndItsAblations) {
  expectOptions("semantic", SemanticExplorerOptions{});
  expectOptions("semantic_paper", SemanticExplorerOptions::paper());
  SemanticExplorerOptions sampling = SemanticExplorerOptions::paper();
  sampling.score.room_reward = 0.0;
  expectOptions("semantic_sampling_only", sampling);
  SemanticExplorerOptions scoring = SemanticExplorerOptions::paper();
  scoring.tree.k = 0.0;
  expectOptions("semantic_score_only", scoring);
}

TEST(SemanticExplorerTest, SamplingOnlyNeverAddsTheRoomReward) {
  auto strategy = createStrategy("semantic_sampling_only", 1);
  auto* s = dynamic_cast<SemanticExplorer*>(strategy.get());
  ASSERT_NE(s, nullptr);
  // After decisions with the robot in room 1 too (score() depends on the room only through
  // membership and, for semantic, hubs).
  TwoRoomGrid w;
  decideAfterGrowing(*s, w, Pose2{2.0, 1.0, 0.0});
  ASSERT_EQ(s->currentRoom(), 1);
  for (const double gain : {0.0, 1.5, 4.0}) {
    for (const double cost : {0.0, 2.0, 9.0}) {
      EXPECT_EQ(s->score(gain, cost, true), s->score(gain, cost, false));
    }
  }
  auto paper = createStrategy("semantic_paper", 1);
  auto* p = dynamic_cast<SemanticExplorer*>(paper.get());
  ASSERT_NE(p, nullptr);
  EXPECT_GT(p->score(1.5, 2.0, true), p->score(1.5, 2.0, false));
}

TEST(SemanticExplorerTest, ScoreOnlyMakesNoSemanticDraws) {
  // The robot sits in room 1, beside its frontier, for 60 s: semantic_paper draws P_sem ever
  // more often, semantic_score_only never.
  auto draws = [](std::string_view method) {
    auto strategy = createStrategy(method, 1);
    auto* s = dynamic_cast<SemanticExplorer*>(strategy.get());
    EXPECT_NE(s, nullptr);
    TwoRoomGrid w;
    const Pose2 robot{2.0, 1.0, 0.0};
    for (double t = 0.0; t <= 60.0; t += 1.0) s->decide({w.grid, w.costmap, robot, t, &w.semantic});
    EXPECT_EQ(s->currentRoom(), 1);
    EXPECT_FALSE(s->semanticCandidates().empty());
    EXPECT_GT(s->randomDraws(), 0);
    return s->semanticDraws();
  };
  EXPECT_EQ(draws("semantic_score_only"), 0);
  EXPECT_GT(draws("semantic_paper"), 0);
}

TEST(SemanticExplorerTest, ThePapersMethodExploresTheSmallHouseAndEndsByItself) {
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(sim::loadBuiltinWorld("small_house"), config.world);
  auto strategy = createStrategy("semantic_paper", 1);
  const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_TRUE(r.t98_s.has_value());
  EXPECT_FALSE(r.timed_out) << "ended only by the time limit " << r.max_time_s << " s";
}

/// A west room with a hidden alcove and a door, near the start, to a large east room: does the
/// robot see the west room (alcove included) before it first enters the east room?
sim::World alcoveAndHall() {
  sim::World w;
  w.name = "alcove_and_hall";
  w.source = "test:alcove_and_hall";
  const double t = 0.2;
  w.walls = {{{0, 0}, {20, 0}, t, 0, 2.5},      {{20, 0}, {20, 8}, t, 0, 2.5},
             {{20, 8}, {0, 8}, t, 0, 2.5},      {{0, 8}, {0, 0}, t, 0, 2.5},
             {{10, 0}, {10, 0.6}, t, 0, 2.5},   {{10, 1.6}, {10, 8}, t, 0, 2.5},
             {{3.5, 3.0}, {3.5, 8}, t, 0, 2.5}, {{0, 3.0}, {2.3, 3.0}, t, 0, 2.5}};
  w.doors = {{{10, 1.1}, 1.0}};
  w.rooms = {{1, "west", {{0, 0}, {10, 0}, {10, 8}, {0, 8}}},
             {2, "east", {{10, 0}, {20, 0}, {20, 8}, {10, 8}}}};
  w.start = {8.5, 1.2, 0.0};
  w.start_given = true;
  return w;
}

/// Fraction of the west room's reachable cells known when the robot first enters the east room.
double westKnownOnLeaving(const std::string& method, std::uint64_t seed) {
  const sim::World world = alcoveAndHall();
  sim::EpisodeConfig config;
  config.resolve();
  config.episode.max_time_s = 900.0;
  const sim::WorldModel model(world, config.world);
  const GridGeometry geometry = sim::mapGeometryFor(model, config.mapping.resolution_m);
  const sim::ExplorationTruth truth(model, geometry, config.explorer.costmap.lethalRadius_m());
  struct Probe final : sim::EpisodeObserver {
    const sim::ExplorationTruth* truth = nullptr;
    double fraction = -1.0;
    std::vector<double> times;
    std::string_view name() const override { return "probe"; }
    void onStep(const sim::EpisodeSnapshot& s) override {
      if (fraction >= 0.0 || s.robot.x_m < 10.3) return;
      int known = 0, all = 0;
      for (const std::uint32_t i : truth->reachableCells()) {
        if (s.grid.geometry().centerOf(s.grid.geometry().cellAt(i)).x() >= 9.9) continue;
        ++all;
        known += s.grid.isUnknown(i) ? 0 : 1;
      }
      fraction = static_cast<double>(known) / all;
    }
    void onFinish(const sim::EpisodeSnapshot&) override {}
    const std::vector<double>& updateTimes_ms() const override { return times; }
  } probe;
  probe.truth = &truth;
  auto strategy = createStrategy(method, seed);
  const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, seed, {}, {&probe});
  EXPECT_GE(r.exploration_rate, 0.98) << method;
  return probe.fraction;
}

TEST(SemanticExplorerTest, FinishesTheFirstRoomBeforeEnteringTheSecondWhereRrtDoesNot) {
  // Over six seeds rather than one: a single seed's figure is a draw (seeds 1-12 left the west
  // room with 67-100 % of it known, most above 95 %, the rest mostly 89-92 %, with the alcove
  // half seen; rrt with 27-39 % in ten of the twelve).
  int rrt_left_early = 0;
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const double semantic = westKnownOnLeaving("semantic", seed);
    const double rrt = westKnownOnLeaving("rrt", seed);
    EXPECT_GE(semantic, 0.85) << "seed " << seed << ": semantic left the west room with "
                              << semantic * 100 << " % of it known";
    rrt_left_early += rrt < 0.5 ? 1 : 0;
  }
  EXPECT_GE(rrt_left_early, 4) << "rrt left the west room with less than half of it known in "
                               << rrt_left_early << " of 6 seeds";
}

/// A bare 6 x 4 m room drawn as an image (0.1 m pixels, one-pixel walls), the robot 1.95 m from
/// its west wall: the first scans see all but the two far corners, about 4.3 m away, and the
/// frontier points left there are slivers (less than min_unknown_m2 of unknown space in their
/// squares). The robot must still look at them: it used to idle for idle_end_s and end at 97 %.
TEST(SemanticExplorerTest, LooksIntoTheLastCornersOfItsRoomInsteadOfEndingShort) {
  sim::World w;
  w.name = "bare_room";
  w.source = "test:bare_room";
  sim::ImageWorld image;
  image.solid = cv::Mat(40, 60, CV_8U, cv::Scalar(255));
  image.solid(cv::Rect(1, 1, 58, 38)).setTo(0);
  image.resolution_m = 0.1;
  w.image = image;
  w.start = {1.95, 1.95, 0.0};
  w.start_given = true;
  sim::EpisodeConfig config;
  config.resolve();
  config.episode.max_time_s = 300.0;
  const sim::WorldModel model(w, config.world);
  for (const std::uint64_t seed : {1u, 2u}) {
    auto strategy = createStrategy("semantic", seed);
    const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, seed);
    EXPECT_GE(r.exploration_rate, 0.98) << "seed " << seed;
    EXPECT_FALSE(r.timed_out) << "seed " << seed;
  }
}

}  // namespace
}  // namespace roomscout
