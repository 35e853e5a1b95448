// Skeleton graphs of simple synthetic maps: the graph's shape is known exactly.

#include "roomscout/maps/topology_builder.hpp"

#include <gtest/gtest.h>

#include <set>

#include <opencv2/ximgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/detail/thinning.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::box;
using test::canvas;
const auto F = CellState::kFree;

TopologicalMap buildOf(const cv::Mat& states) {
  return TopologyBuilder().build(
      states, GridGeometry(Vec2::Zero(), test::kRes, states.cols, states.rows), nullptr);
}

int countKind(const TopologicalMap& t, TopoNodeKind kind) {
  int n = 0;
  for (const TopoNode& node : t.nodes()) n += node.kind == kind;
  return n;
}

TEST(TopologyBuilder, StraightCorridorIsOneEdge) {
  cv::Mat m = canvas(12, 3);
  box(m, 1, 1, 11, 2.2, F);
  const TopologicalMap t = buildOf(m);
  ASSERT_EQ(t.edges().size(), 1u);
  ASSERT_EQ(t.nodes().size(), 2u);
  EXPECT_EQ(countKind(t, TopoNodeKind::kEndpoint), 2);
  const TopoEdge& e = t.edges()[0];
  EXPECT_GT(e.length_m, 8.0);
  EXPECT_LT(e.length_m, 10.2);
  EXPECT_NEAR(e.min_clearance_m, 0.6, 0.15);
  EXPECT_GE(e.polyline_m.size(), 2u);
  for (const Vec2& p : e.polyline_m) EXPECT_NEAR(p.y(), 1.6, 0.15);
}

TEST(TopologyBuilder, PlusShapedCorridorIsOneJunctionWithFourEdges) {
  cv::Mat m = canvas(12, 12);
  box(m, 1, 5.4, 11, 6.6, F);
  box(m, 5.4, 1, 6.6, 11, F);
  const TopologicalMap t = buildOf(m);
  ASSERT_EQ(countKind(t, TopoNodeKind::kJunction), 1);
  EXPECT_EQ(countKind(t, TopoNodeKind::kEndpoint), 4);
  EXPECT_EQ(t.edges().size(), 4u);
  for (const TopoNode& n : t.nodes()) {
    if (n.kind == TopoNodeKind::kJunction) {
      EXPECT_NEAR(n.position_m.x(), 6.0, 0.2);
      EXPECT_NEAR(n.position_m.y(), 6.0, 0.2);
      EXPECT_EQ(t.degree(n.id), 4);
    }
  }
}

TEST(TopologyBuilder, DiagonalCorridorHasNoStaircaseJunctions) {
  cv::Mat m = canvas(12, 12);
  cv::line(m, {40, 40}, {200, 200}, cv::Scalar(test::v(F)), 24);
  const TopologicalMap t = buildOf(m);
  EXPECT_EQ(countKind(t, TopoNodeKind::kJunction), 0);
  EXPECT_EQ(t.edges().size(), 1u);
}

TEST(TopologyBuilder, RoomWithATableHasNoLoop) {
  cv::Mat m = canvas(8, 8);
  box(m, 0.5, 0.5, 7.5, 7.5, F);
  box(m, 3.4, 3.6, 4.6, 4.4, CellState::kOccupied);  // a 1.2 x 0.8 m table
  const TopologicalMap t = buildOf(m);
  ASSERT_FALSE(t.nodes().empty());
  // A tree: one component without cycles has exactly nodes - 1 edges.
  EXPECT_EQ(t.edges().size() + 1, t.nodes().size());
  for (const TopoEdge& e : t.edges()) EXPECT_NE(e.u, e.v);
}

TEST(TopologyBuilder, PillarLargerThanFurnitureMakesALoop) {
  cv::Mat m = canvas(10, 10);
  box(m, 0.5, 0.5, 9.5, 9.5, F);
  box(m, 3.0, 3.0, 7.0, 7.0, CellState::kOccupied);  // 16 m^2: a block, not furniture
  const TopologicalMap t = buildOf(m);
  EXPECT_EQ(t.edges().size(), t.nodes().size());  // one cycle
}

TEST(TopologyBuilder, EndsFacingUnknownAreFrontiers) {
  cv::Mat m = canvas(12, 3);
  box(m, 1, 1, 11, 2.2, F);
  box(m, 11, 0.8, 12, 2.4, CellState::kUnknown);  // the corridor runs on into the unknown
  const TopologicalMap t = buildOf(m);
  EXPECT_EQ(countKind(t, TopoNodeKind::kFrontier), 1);
  EXPECT_EQ(countKind(t, TopoNodeKind::kEndpoint), 1);
}

TEST(TopologyBuilder, NodesCarryTheirRoom) {
  cv::Mat truth;
  const cv::Mat m = test::threeRoomsAndCorridor(&truth);
  const GridGeometry g(Vec2::Zero(), test::kRes, m.cols, m.rows);
  SemanticMap rooms;
  rooms.update(g, RoomSegmenter().segment(m, test::kRes).labels, m);
  const TopologicalMap t = TopologyBuilder().build(m, g, &rooms);
  ASSERT_FALSE(t.nodes().empty());
  std::set<int> regions;
  for (const TopoNode& n : t.nodes()) {
    EXPECT_EQ(n.region_id, rooms.roomAt(n.position_m));
    EXPECT_NE(n.region_id, 0);
    regions.insert(n.region_id);
  }
  // The graph reaches every room, and it is one tree (no furniture, no loops).
  EXPECT_EQ(regions.size(), 4u);
  EXPECT_EQ(t.edges().size() + 1, t.nodes().size());
}

TEST(Thinning, SameSkeletonAsOpenCv) {
  cv::Mat img = cv::Mat::zeros(300, 400, CV_8U);
  cv::rectangle(img, {20, 20}, {380, 280}, cv::Scalar(255), cv::FILLED);
  cv::rectangle(img, {100, 90}, {180, 200}, cv::Scalar(0), cv::FILLED);
  cv::circle(img, {300, 150}, 40, cv::Scalar(0), cv::FILLED);
  cv::line(img, {0, 0}, {399, 299}, cv::Scalar(0), 5);
  cv::Mat expected;
  cv::ximgproc::thinning(img, expected, cv::ximgproc::THINNING_ZHANGSUEN);
  const cv::Mat ours = maps::thinZhangSuen(img);
  EXPECT_EQ(cv::countNonZero(ours != expected), 0);
}

TEST(TopologyBuilder, RejectsMismatchedGeometry) {
  const cv::Mat m = canvas(2, 2);
  EXPECT_THROW(TopologyBuilder().build(m, GridGeometry(Vec2::Zero(), 0.05, 3, 3), nullptr),
               InvalidArgument);
  TopologyBuilderOptions bad;
  bad.opening_radius_m = -1;
  EXPECT_THROW(TopologyBuilder{bad}, OptionError);
}

}  // namespace
}  // namespace roomscout
