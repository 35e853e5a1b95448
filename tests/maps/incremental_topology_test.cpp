// IncrementalTopologyBuilder: a map revealed piece by piece ends with the skeleton graph a
// build from scratch gives, and the windows stay small.

#include "roomscout/maps/incremental_topology.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/topology_builder.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::geometryOf;
using test::kRes;
using test::roomRow;
using test::seenUpTo;
using test::v;

/// Every node of `a` has a node of `b` of the same kind within `cells` cells, and the other way
/// round; the edges agree in number and, in order of length, within a cell each.
void expectSameGraph(const TopologicalMap& a, const TopologicalMap& b, double cells) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  ASSERT_EQ(a.edges().size(), b.edges().size());
  for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    for (const TopoNode& n : x->nodes()) {
      bool found = false;
      for (const TopoNode& m : y->nodes()) {
        found |= m.kind == n.kind && (m.position_m - n.position_m).norm() <= cells * kRes + 1e-9;
      }
      EXPECT_TRUE(found) << "node at " << n.position_m.transpose();
    }
  }
  std::vector<double> la, lb;
  for (const TopoEdge& e : a.edges()) la.push_back(e.length_m);
  for (const TopoEdge& e : b.edges()) lb.push_back(e.length_m);
  std::sort(la.begin(), la.end());
  std::sort(lb.begin(), lb.end());
  for (std::size_t i = 0; i < la.size(); ++i) EXPECT_NEAR(la[i], lb[i], cells * kRes * 1.5) << i;
}

TEST(IncrementalTopology, ARevealedMapEndsWithTheGraphOfABuildFromScratch) {
  cv::Mat truth;
  const cv::Mat full = roomRow(24, &truth);
  IncrementalTopologyBuilder skeleton;
  for (double x = 3.0; x < full.cols * kRes + 1.0; x += 1.5) {
    const cv::Mat seen = seenUpTo(full, x);
    const TopologicalMap inc = skeleton.update(seen, geometryOf(seen), nullptr);
    // Mid-way too, not only at the end.
    if (static_cast<int>(x * 10) % 150 == 0) {
      SCOPED_TRACE(x);
      expectSameGraph(inc, TopologyBuilder().build(seen, geometryOf(seen), nullptr), 1.0);
    }
  }
  const TopologicalMap inc = skeleton.update(full, geometryOf(full), nullptr);
  EXPECT_GT(skeleton.windowUpdates(), 40);
  EXPECT_LT(skeleton.fullUpdates(), 40);
  const TopologicalMap scratch = TopologyBuilder().build(full, geometryOf(full), nullptr);
  expectSameGraph(inc, scratch, 1.0);
  EXPECT_GE(inc.nodes().size(), 24u);
}

TEST(IncrementalTopology, AGrownGridIsMatchedByMapPosition) {
  cv::Mat truth;
  const cv::Mat full = roomRow(6, &truth);
  IncrementalTopologyBuilder skeleton;
  const TopologicalMap first = skeleton.update(full, geometryOf(full), nullptr);
  cv::Mat grown(full.rows + 80, full.cols + 80, CV_8U, cv::Scalar(v(CellState::kUnknown)));
  full.copyTo(grown(cv::Rect(40, 40, full.cols, full.rows)));
  const TopologicalMap moved = skeleton.update(grown, geometryOf(grown, Vec2(-2.0, -2.0)), nullptr);
  EXPECT_EQ(skeleton.fullUpdates(), 1);
  EXPECT_EQ(skeleton.windowUpdates(), 0);
  expectSameGraph(first, moved, 0.0);
}

TEST(IncrementalTopology, FullShareZeroRebuildsTheWholeMapEachTime) {
  cv::Mat truth;
  const cv::Mat full = roomRow(6, &truth);
  IncrementalTopologyBuilder skeleton({}, {4.0, 0.0});
  for (double x = 5.0; x < 31.0; x += 5.0) {
    const cv::Mat seen = seenUpTo(full, x);
    expectSameGraph(skeleton.update(seen, geometryOf(seen), nullptr),
                    TopologyBuilder().build(seen, geometryOf(seen), nullptr), 0.0);
  }
  EXPECT_EQ(skeleton.windowUpdates(), 0);
}

TEST(IncrementalTopology, RejectsBadInputAndOptions) {
  IncrementalTopologyBuilder skeleton;
  const cv::Mat floats(10, 10, CV_32F, cv::Scalar(0));
  EXPECT_THROW(skeleton.update(floats, GridGeometry(Vec2::Zero(), kRes, 10, 10), nullptr),
               InvalidArgument);
  EXPECT_THROW(IncrementalTopologyBuilder({}, {-1.0, 0.5}), OptionError);
  EXPECT_THROW(IncrementalTopologyBuilder({}, {4.0, 2.0}), OptionError);
}

}  // namespace
}  // namespace roomscout
