// The contract every registered strategy keeps (STYLE §10): deterministic for a seed, never a
// goal inside an obstacle or the lethal inflation, a fully known map ends exploration at once,
// and a closed room ends cleanly instead of hanging.

#include <gtest/gtest.h>

#include <cstdint>

#include "../sim/test_worlds.hpp"
#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout {
namespace {

/// A strategy wrapper that checks every goal against the costmap it was decided on. It forwards
/// every virtual of ExplorationStrategy, so the suite runs the strategy's own code.
class CheckedStrategy final : public ExplorationStrategy {
 public:
  explicit CheckedStrategy(std::unique_ptr<ExplorationStrategy> inner) : inner_(std::move(inner)) {}
  std::string_view name() const override { return inner_->name(); }
  Decision decide(const ExplorationInput& input) override {
    const Decision d = inner_->decide(input);
    if (d.status == Decision::Status::kGoal) {
      const GridGeometry& g = input.costmap.geometry();
      const Cell c = g.cellOf(d.goal_m);
      ++goals;
      if (!g.contains(c) || input.costmap.isLethal(g.index(c)) || input.grid.isOccupied(g.index(c)))
        ++bad_goals;
    }
    return d;
  }
  void onGoalReached(const Vec2& g) override { inner_->onGoalReached(g); }
  void onGoalFailed(const Vec2& g) override { inner_->onGoalFailed(g); }
  void onGoalStalled(const Vec2& g) override { inner_->onGoalStalled(g); }
  std::vector<Vec2> candidateGoals() const override { return inner_->candidateGoals(); }
  double replanPeriod_s() const override { return inner_->replanPeriod_s(); }
  bool readsRooms() const override { return inner_->readsRooms(); }
  std::vector<ParameterRef> parameters() override { return inner_->parameters(); }
  void validateOptions() const override { inner_->validateOptions(); }
  int goals = 0;
  int bad_goals = 0;

 private:
  std::unique_ptr<ExplorationStrategy> inner_;
};

sim::EpisodeResult run(const sim::World& world, const std::string& method, std::uint64_t seed,
                       CheckedStrategy** out = nullptr, double max_time_s = 0.0) {
  sim::EpisodeConfig config;
  config.resolve();
  config.episode.max_time_s = max_time_s;
  const sim::WorldModel model(world, config.world);
  static std::unique_ptr<CheckedStrategy> keep;
  keep = std::make_unique<CheckedStrategy>(createStrategy(method, seed));
  if (out) *out = keep.get();
  return sim::runEpisode(model, config, *keep, seed);
}

class StrategyContract : public ::testing::TestWithParam<std::string> {};

TEST_P(StrategyContract, OptionsValidateAndAreNamed) {
  auto s = createStrategy(GetParam(), 1);
  EXPECT_EQ(s->name(), GetParam());
  EXPECT_NO_THROW(s->validateOptions());
  for (const ParameterRef& p : s->parameters()) EXPECT_FALSE(p.name.empty());
}

TEST_P(StrategyContract, FullyKnownMapEndsAtOnce) {
  // A closed 4 x 4 m room whose map is fully known: the first decision ends exploration
  // (strategies with an end test spread over several checks may take a few seconds).
  const sim::World world = sim::testing::squareRoom(4.0, 0.2);
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(world, config.world);
  const GridGeometry geometry = sim::mapGeometryFor(model, config.mapping.resolution_m);
  const sim::ExplorationTruth truth(model, geometry, config.explorer.costmap.lethalRadius_m());
  OccupancyGrid grid(geometry, config.mapping);
  for (std::size_t i = 0; i < geometry.cellCount(); ++i) {
    grid.setState(i, truth.trulyFree()[i] ? CellState::kFree : CellState::kOccupied);
  }
  Costmap costmap(config.explorer.costmap);
  costmap.update(grid);
  auto s = createStrategy(GetParam(), 3);
  bool done = false;
  for (int k = 0; k < 200 && !done; ++k) {
    const ExplorationInput input{grid, costmap, world.start, 0.1 * k};
    const Decision d = s->decide(input);
    if (d.status == Decision::Status::kDone) {
      done = true;
    } else {
      const Cell c = geometry.cellOf(d.goal_m);
      ASSERT_TRUE(geometry.contains(c));
      EXPECT_FALSE(costmap.isLethal(geometry.index(c)));
      s->onGoalReached(d.goal_m);
    }
  }
  EXPECT_TRUE(done) << "no end within 20 simulated seconds on a fully known map";
}

TEST_P(StrategyContract, ClosedRoomEndsCleanlyWithSafeGoals) {
  CheckedStrategy* checked = nullptr;
  const sim::EpisodeResult r =
      run(sim::testing::squareRoom(4.0, 0.2), GetParam(), 1, &checked, 600.0);
  EXPECT_FALSE(r.timed_out);
  ASSERT_TRUE(r.t_done_s.has_value());
  EXPECT_LT(*r.t_done_s, 200.0);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_EQ(checked->bad_goals, 0) << "of " << checked->goals;
}

TEST_P(StrategyContract, DeterministicForASeedAndSafeGoalsInTwoRooms) {
  CheckedStrategy* checked = nullptr;
  const sim::EpisodeResult a = run(sim::testing::twoRooms(), GetParam(), 7, &checked, 900.0);
  const int bad = checked->bad_goals;
  const sim::EpisodeResult b = run(sim::testing::twoRooms(), GetParam(), 7, nullptr, 900.0);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(a.exploration_rate, b.exploration_rate);
  EXPECT_EQ(a.t98_s, b.t98_s);
  EXPECT_EQ(a.t_done_s, b.t_done_s);
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t i = 0; i < a.trajectory.size(); i += 7) {
    EXPECT_EQ(a.trajectory[i].pose.x_m, b.trajectory[i].pose.x_m);
    EXPECT_EQ(a.trajectory[i].pose.y_m, b.trajectory[i].pose.y_m);
  }
  EXPECT_GE(a.exploration_rate, 0.98);
  EXPECT_FALSE(a.timed_out);
}

INSTANTIATE_TEST_SUITE_P(Registered, StrategyContract, ::testing::ValuesIn(strategyNames()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// RrtTree unit tests.

OccupancyGrid corridorGrid() {
  // 4 x 2 m: x < 2 m known free, x >= 2 m unknown; an occupied wall at y in [1.0, 1.05).
  OccupancyGrid grid(GridGeometry({0, 0}, 0.05, 80, 40));
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x)
      grid.setState(static_cast<std::size_t>(y) * 80 + x, CellState::kFree);
  }
  for (int x = 0; x < 30; ++x)
    grid.setState(static_cast<std::size_t>(20) * 80 + x, CellState::kOccupied);
  return grid;
}

TEST(RrtTree, EdgeCheckFindsFreeFrontierAndObstacle) {
  const OccupancyGrid grid = corridorGrid();
  EXPECT_EQ(checkEdge(grid, {0.2, 0.2}, {1.8, 0.4}).status, EdgeStatus::kFree);
  const EdgeCheck f = checkEdge(grid, {0.2, 0.5}, {3.0, 0.5});
  EXPECT_EQ(f.status, EdgeStatus::kFrontier);
  EXPECT_NEAR(f.end_m.x(), 2.0, 0.02);  // truncated at the first unknown cell
  EXPECT_EQ(checkEdge(grid, {0.5, 0.5}, {0.5, 1.5}).status, EdgeStatus::kObstacle);
  EXPECT_EQ(checkEdge(grid, {0.5, 0.5}, {-1.0, 0.5}).status,
            EdgeStatus::kObstacle);  // leaves the grid
}

TEST(RrtTree, NearestMatchesBruteForce) {
  RrtTree tree(0.5, {0, 0}, {20, 10}, 0.5);
  std::mt19937_64 rng(4);
  const auto sampler = uniformBoxSampler({0, 0}, {20, 10});
  tree.reset({1, 1});
  for (int i = 0; i < 3000; ++i) tree.add(sampler(rng), 0);
  for (int q = 0; q < 500; ++q) {
    const Vec2 p = uniformBoxSampler({-2, -2}, {22, 12})(rng);
    std::size_t best = 0;
    for (std::size_t i = 1; i < tree.size(); ++i) {
      if ((tree.node(i) - p).squaredNorm() < (tree.node(best) - p).squaredNorm()) best = i;
    }
    EXPECT_EQ(tree.nearest(p), best);
  }
}

TEST(RrtTree, ExtendSteersAndAddsFreeEdgesOnly) {
  const OccupancyGrid grid = corridorGrid();
  RrtTree tree(0.5, {0, 0}, {4, 2}, 0.5);
  tree.reset({0.5, 0.5});
  const RrtExtension a = tree.extend(grid, {1.5, 0.5});
  EXPECT_TRUE(a.added);
  EXPECT_NEAR(a.new_m.x(), 1.0, 1e-9);
  const RrtExtension b = tree.extend(grid, {1.0, 1.8});  // through the wall
  EXPECT_EQ(b.status, EdgeStatus::kObstacle);
  EXPECT_FALSE(b.added);
  EXPECT_EQ(tree.size(), 2u);
  EXPECT_EQ(tree.parent(1), 0u);
}

// A tree re-indexed for a new box keeps its nodes in order (or drops those rejected, hanging
// their children from the nearest kept ancestor) and finds nearest nodes as before.
TEST(RrtTreeRebound, KeepsOrderAndParentsAndFindsNearestNodesInTheNewBox) {
  RrtTree tree(0.5, {0, 0}, {10, 5}, 0.5);
  std::mt19937_64 rng(9);
  tree.reset({1, 1});
  const auto sampler = uniformBoxSampler({0, 0}, {10, 5});
  for (int i = 0; i < 1500; ++i) tree.add(sampler(rng), tree.nearest(sampler(rng)));
  std::vector<Vec2> nodes;
  std::vector<std::size_t> parents;
  for (std::size_t i = 0; i < tree.size(); ++i) {
    nodes.push_back(tree.node(i));
    parents.push_back(tree.parent(i));
  }
  // Grown: every node kept, same order and parents.
  EXPECT_EQ(tree.rebound({-6, -3}, {20, 12}, [](const Vec2&) { return true; }), nodes.size());
  ASSERT_EQ(tree.size(), nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(tree.node(i), nodes[i]);
    EXPECT_EQ(tree.parent(i), parents[i]);
  }
  const auto query = uniformBoxSampler({-8, -5}, {22, 14});
  auto bruteNearest = [&](const Vec2& p) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < tree.size(); ++i) {
      if ((tree.node(i) - p).squaredNorm() < (tree.node(best) - p).squaredNorm()) best = i;
    }
    return best;
  };
  for (int q = 0; q < 300; ++q) {
    const Vec2 p = query(rng);
    EXPECT_EQ(tree.nearest(p), bruteNearest(p));
  }
  // Cropped to x >= 3: the nodes west of it go; each kept node's parent is its nearest kept
  // ancestor, or itself when it had none.
  const auto keep = [](const Vec2& p) { return p.x() >= 3.0; };
  std::vector<std::size_t> new_index(nodes.size(), SIZE_MAX);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (keep(nodes[i])) new_index[i] = kept++;
  }
  ASSERT_GT(kept, 0u);
  ASSERT_LT(kept, nodes.size());
  EXPECT_EQ(tree.rebound({3, 0}, {10, 5}, keep), kept);
  ASSERT_EQ(tree.size(), kept);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (new_index[i] == SIZE_MAX) continue;
    EXPECT_EQ(tree.node(new_index[i]), nodes[i]);
    std::size_t a = i;
    while (a != parents[a] && new_index[parents[a]] == SIZE_MAX) a = parents[a];
    const std::size_t expected =
        a == parents[a] || new_index[parents[a]] == SIZE_MAX ? new_index[i] : new_index[parents[a]];
    EXPECT_EQ(tree.parent(new_index[i]), expected) << "node " << i;
  }
  for (int q = 0; q < 300; ++q) {
    const Vec2 p = query(rng);
    EXPECT_EQ(tree.nearest(p), bruteNearest(p));
  }
  // Nothing kept: an empty tree, ready for reset().
  EXPECT_EQ(tree.rebound({0, 0}, {1, 1}, [](const Vec2&) { return false; }), 0u);
  EXPECT_TRUE(tree.empty());
  tree.reset({0.5, 0.5});
  EXPECT_EQ(tree.size(), 1u);
}

}  // namespace
}  // namespace roomscout
