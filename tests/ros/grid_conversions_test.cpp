// The message adapters: map messages read as map_server reads images, grids written back,
// room ids as a grid, poses, and markers.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout_ros/grid_conversions.hpp"
#include "roomscout_ros/map_markers.hpp"

namespace roomscout::ros1 {
namespace {

nav_msgs::OccupancyGrid message(int w, int h, std::vector<std::int8_t> data) {
  nav_msgs::OccupancyGrid m;
  m.info.resolution = 0.05f;
  m.info.width = static_cast<std::uint32_t>(w);
  m.info.height = static_cast<std::uint32_t>(h);
  m.info.origin.position.x = -1.0;
  m.info.origin.position.y = 2.0;
  m.info.origin.orientation.w = 1.0;
  m.data = std::move(data);
  return m;
}

TEST(GridConversions, ClassifiesValuesAsMapServerDoes) {
  const ReceivedGrid r = fromMsg(message(5, 1, {-1, 0, 19, 50, 65}));
  EXPECT_EQ(r.grid.geometry().width(), 5);
  EXPECT_DOUBLE_EQ(r.grid.geometry().origin_m().x(), -1.0);
  EXPECT_DOUBLE_EQ(r.grid.geometry().origin_m().y(), 2.0);
  EXPECT_NEAR(r.grid.geometry().resolution_m(), 0.05, 1e-7);
  EXPECT_EQ(r.grid.state(std::size_t{0}), CellState::kUnknown);
  EXPECT_EQ(r.grid.state(std::size_t{1}), CellState::kFree);
  EXPECT_EQ(r.grid.state(std::size_t{2}), CellState::kFree);
  EXPECT_EQ(r.grid.state(std::size_t{3}), CellState::kUnknown);  // between the thresholds
  EXPECT_EQ(r.grid.state(std::size_t{4}), CellState::kOccupied);
  EXPECT_FALSE(r.changed.has_value()) << "no previous grid: any cell may have changed";
}

TEST(GridConversions, ProbabilitiesAsCartographerPublishesThem) {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.05, 3, 1));
  grid.addHit(0);   // log-odds 1.6: p = 0.83
  grid.addMiss(1);  // -0.41: p = 0.40
  nav_msgs::OccupancyGrid msg;
  toProbabilityMsg(grid, msg);
  EXPECT_EQ(msg.data, (std::vector<std::int8_t>{83, 40, -1}));
  // Read with Cartographer's convention, the cells are what the grid says; map_server's
  // thresholds leave the cell seen free once unknown.
  const ReceivedGrid cartographer = fromMsg(msg, nullptr, MapConvention::named("cartographer"));
  EXPECT_EQ(cartographer.grid.state(std::size_t{0}), CellState::kOccupied);
  EXPECT_EQ(cartographer.grid.state(std::size_t{1}), CellState::kFree);
  EXPECT_EQ(cartographer.grid.state(std::size_t{2}), CellState::kUnknown);
  EXPECT_EQ(fromMsg(msg).grid.state(std::size_t{1}), CellState::kUnknown);
}

TEST(GridConversions, MapUpdatesPatchTheMapOrAreRefused) {
  nav_msgs::OccupancyGrid map = message(4, 3, std::vector<std::int8_t>(12, -1));
  map_msgs::OccupancyGridUpdate patch;
  patch.x = 1;
  patch.y = 1;
  patch.width = 2;
  patch.height = 2;
  patch.data = {0, 100, 0, 0};
  applyUpdate(map, patch);
  EXPECT_EQ(map.data, (std::vector<std::int8_t>{-1, -1, -1, -1,  //
                                                -1, 0, 100, -1,  //
                                                -1, 0, 0, -1}));
  const nav_msgs::OccupancyGrid before = map;
  map_msgs::OccupancyGridUpdate outside = patch;
  outside.x = 3;  // columns 3 and 4 of a 4-column map
  EXPECT_THROW(applyUpdate(map, outside), InvalidArgument);
  map_msgs::OccupancyGridUpdate negative = patch;
  negative.y = -1;
  EXPECT_THROW(applyUpdate(map, negative), InvalidArgument);
  map_msgs::OccupancyGridUpdate short_data = patch;
  short_data.data.pop_back();
  EXPECT_THROW(applyUpdate(map, short_data), InvalidArgument);
  EXPECT_EQ(map.data, before.data) << "a refused patch changed the map";
}

TEST(GridConversions, EachMapSourceReadsItsOwnConvention) {
  const std::vector<std::int8_t> values = {-1, 0, 19, 40, 49, 50, 55, 65, 99, 100};
  const auto states = [&](const std::string& source) {
    const ReceivedGrid r = fromMsg(message(10, 1, values), nullptr, MapConvention::named(source));
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i)
      text += "?fo"[static_cast<int>(r.grid.state(i))];
    return text;
  };
  // Cartographer's probabilities: a cell seen free a few times (in the forties) is free, one
  // hit once (55) occupied; map_server's thresholds leave the forties unknown.
  EXPECT_EQ(states("map_server"), "?ff????ooo");
  EXPECT_EQ(states("cartographer"), "?ffff?oooo");
  EXPECT_EQ(states("slam_toolbox"), "?ffffooooo");
  EXPECT_EQ(states("gmapping"), states("slam_toolbox"));
  EXPECT_EQ(states("costmap"), "?ffffffffo");
  try {
    MapConvention::named("hector");
    FAIL() << "an unknown source was accepted";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("cartographer"), std::string::npos) << e.what();
  }
  EXPECT_THROW((MapConvention{50.0, 50.0}.validate()), OptionError);
  EXPECT_THROW((MapConvention{-1.0, 50.0}.validate()), OptionError);
  EXPECT_NO_THROW(MapConvention::named("cartographer").validate());
}

TEST(GridConversions, ReportsTheCellsThatChanged) {
  const ReceivedGrid a = fromMsg(message(4, 3, std::vector<std::int8_t>(12, -1)));
  std::vector<std::int8_t> data(12, -1);
  data[1 * 4 + 2] = 0;    // cell (2, 1)
  data[2 * 4 + 3] = 100;  // cell (3, 2)
  const ReceivedGrid b = fromMsg(message(4, 3, data), &a.grid);
  ASSERT_TRUE(b.changed.has_value());
  EXPECT_EQ(b.changed->min_x, 2);
  EXPECT_EQ(b.changed->min_y, 1);
  EXPECT_EQ(b.changed->max_x, 4);
  EXPECT_EQ(b.changed->max_y, 3);
  const ReceivedGrid same = fromMsg(message(4, 3, data), &b.grid);
  ASSERT_TRUE(same.changed.has_value());
  EXPECT_TRUE(same.changed->empty());
  // Grown map: another geometry, so any cell may differ.
  EXPECT_FALSE(
      fromMsg(message(5, 3, std::vector<std::int8_t>(15, -1)), &b.grid).changed.has_value());
}

TEST(GridConversions, RejectsMapsItCannotUse) {
  nav_msgs::OccupancyGrid rotated = message(2, 2, {0, 0, 0, 0});
  rotated.info.origin.orientation.z = std::sin(0.25);
  rotated.info.origin.orientation.w = std::cos(0.25);
  EXPECT_THROW(fromMsg(rotated), InvalidArgument);
  EXPECT_THROW(fromMsg(message(2, 2, {0, 0, 0})), InvalidArgument);
  nav_msgs::OccupancyGrid zero = message(2, 2, {0, 0, 0, 0});
  zero.info.resolution = 0.0f;
  EXPECT_THROW(fromMsg(zero), InvalidArgument);
  EXPECT_THROW(fromMsg(message(0, 0, {})), InvalidArgument);
  nav_msgs::OccupancyGrid nan_origin = message(2, 2, {0, 0, 0, 0});
  nan_origin.info.origin.position.x = std::nan("");
  EXPECT_THROW(fromMsg(nan_origin), InvalidArgument);
}

TEST(GridConversions, GridRoundTripsThroughAMessage) {
  OccupancyGrid grid(GridGeometry(Vec2(0.5, -0.25), 0.05, 3, 2));
  grid.setState(std::size_t{1}, CellState::kFree);
  grid.setState(std::size_t{5}, CellState::kOccupied);
  nav_msgs::OccupancyGrid msg;
  toMsg(grid, msg);
  EXPECT_EQ(msg.data, (std::vector<std::int8_t>{-1, 0, -1, -1, -1, 100}));
  const ReceivedGrid back = fromMsg(msg);
  EXPECT_EQ(back.grid.geometry(), grid.geometry());
  EXPECT_EQ(back.grid.states(), grid.states());
}

TEST(GridConversions, RoomIdsBecomeAGrid) {
  cv::Mat labels = (cv::Mat_<int>(1, 4) << 0, 1, 7, 101);
  nav_msgs::OccupancyGrid msg;
  labelsToMsg(labels, GridGeometry(Vec2::Zero(), 0.1, 4, 1), msg);
  EXPECT_EQ(msg.data, (std::vector<std::int8_t>{-1, 1, 7, 1}));
  EXPECT_THROW(labelsToMsg(labels, GridGeometry(Vec2::Zero(), 0.1, 3, 1), msg), InvalidArgument);
}

TEST(GridConversions, PosesKeepTheirHeading) {
  const Pose2 p{1.5, -2.0, 2.5};
  const Pose2 q = toPose2(toPoseMsg(p));
  EXPECT_DOUBLE_EQ(q.x_m, 1.5);
  EXPECT_DOUBLE_EQ(q.y_m, -2.0);
  EXPECT_NEAR(q.yaw_rad, 2.5, 1e-12);
}

TEST(MapMarkers, PointsMarkerDeletesWhenEmpty) {
  const auto m = pointsMarker({Vec2(1, 2)}, "goal", {1, 0, 0, 1}, 0.3, "map", ros::Time(1.0));
  EXPECT_EQ(m.action, visualization_msgs::Marker::ADD);
  ASSERT_EQ(m.points.size(), 1u);
  EXPECT_DOUBLE_EQ(m.points[0].x, 1.0);
  EXPECT_EQ(pointsMarker({}, "goal", {1, 0, 0, 1}, 0.3, "map", ros::Time(1.0)).action,
            visualization_msgs::Marker::DELETE);
}

TEST(MapMarkers, RoomsGetTheirCellsOutlineAndLabel) {
  // Two rooms side by side on a 10 x 4 grid: ids 1 (x < 5) and 2.
  const GridGeometry g(Vec2::Zero(), 0.1, 10, 4);
  cv::Mat labels(4, 10, CV_32S, cv::Scalar(1));
  labels.colRange(5, 10).setTo(2);
  cv::Mat states(4, 10, CV_8U, cv::Scalar(static_cast<int>(CellState::kFree)));
  SemanticMap rooms;
  rooms.update(g, labels, states);
  ASSERT_EQ(rooms.regions().size(), 2u);
  const auto array = roomMarkers(rooms, "map", ros::Time(1.0));
  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers.front().action, visualization_msgs::Marker::DELETEALL);
  int labels_seen = 0;
  std::size_t cells = 0;
  for (const auto& m : array.markers) {
    if (m.ns == "room_label") {
      ++labels_seen;
      const SemanticRegion* r = rooms.region(m.id);
      ASSERT_NE(r, nullptr);
      EXPECT_EQ(m.text, r->label + " " + std::to_string(r->id));
      EXPECT_FLOAT_EQ(m.color.r, r->rgb[0] / 255.0f);
    }
    if (m.ns == "room_cells") cells += m.points.size();
  }
  EXPECT_EQ(labels_seen, 2);
  EXPECT_EQ(cells, 40u);
  // Thinned to at most max_cells: every second cell on both axes.
  std::size_t thinned = 0;
  for (const auto& m : roomMarkers(rooms, "map", ros::Time(1.0), 10).markers) {
    if (m.ns == "room_cells") thinned += m.points.size();
  }
  EXPECT_EQ(thinned, 10u);
}

}  // namespace
}  // namespace roomscout::ros1
