#include "roomscout/sim/world_file.hpp"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::sim {
namespace {

using roomscout::test::Contains;
using roomscout::test::TempDir;

constexpr double kEps = 1e-9;
constexpr const char* kSource = "mem:test_world.yaml";

void expectPoint(const Vec2& actual, double x, double y) {
  EXPECT_NEAR(actual.x(), x, kEps);
  EXPECT_NEAR(actual.y(), y, kEps);
}

void expectWall(const sim::Wall& w, Vec2 a, Vec2 b, double z_min, double z_max, double thickness) {
  expectPoint(w.a_m, a.x(), a.y());
  expectPoint(w.b_m, b.x(), b.y());
  EXPECT_NEAR(w.z_min_m, z_min, kEps);
  EXPECT_NEAR(w.z_max_m, z_max, kEps);
  EXPECT_NEAR(w.thickness_m, thickness, kEps);
}

/// Axis-aligned bounds of a footprint: (min_x, min_y, max_x, max_y).
std::vector<double> boxOf(const Polygon& p) {
  std::vector<double> b = {1e9, 1e9, -1e9, -1e9};
  for (const Vec2& v : p) {
    b[0] = std::min(b[0], v.x());
    b[1] = std::min(b[1], v.y());
    b[2] = std::max(b[2], v.x());
    b[3] = std::max(b[3], v.y());
  }
  return b;
}

void expectBox(const Polygon& p, double min_x, double min_y, double max_x, double max_y) {
  ASSERT_EQ(p.size(), 4u);
  const std::vector<double> b = boxOf(p);
  EXPECT_NEAR(b[0], min_x, 1e-9);
  EXPECT_NEAR(b[1], min_y, 1e-9);
  EXPECT_NEAR(b[2], max_x, 1e-9);
  EXPECT_NEAR(b[3], max_y, 1e-9);
  EXPECT_NEAR(polygonArea(p), (max_x - min_x) * (max_y - min_y), 1e-9);
}

const char* const kGoodWorld = R"(
name: test_house
description: "A 10 m house"
wall_thickness_m: 0.2
wall_height_m: 2.6
start: [1.5, 2.0, 90]
walls:
  - [[0, 0], [10, 0]]
  - points: [[0, 5], [10, 5]]
    thickness_m: 0.1
    height_m: 3.0
doors:
  - center: [3, 0.05]        # 0.05 m off the centre line, inside the 0.2 m wall
    width_m: 0.9
rooms:
  - name: hall
    polygon: [[0, 0], [5, 0], [5, 5], [0, 5]]
  - name: kitchen
    polygon: [[5, 0], [10, 0], [10, 5], [5, 5]]
furniture:
  - name: sofa
    box: {center: [2, 4], size: [2.0, 0.8], yaw_deg: 90}
    z_m: [0.0, 0.8]
  - name: wardrobe
    kind: block
    polygon: [[7, 4.4], [8.5, 4.4], [8.5, 5], [7, 5]]
    z_m: [0.1, 2.0]
)";

TEST(ParseWorldYaml, ReadsAGoodWorld) {
  const sim::World w = parseWorldYaml(kGoodWorld, kSource);
  EXPECT_EQ(w.name, "test_house");
  EXPECT_EQ(w.source, kSource);
  EXPECT_EQ(w.description, "A 10 m house");
  EXPECT_DOUBLE_EQ(w.wall_height_m, 2.6);
  EXPECT_TRUE(w.start_given);
  EXPECT_DOUBLE_EQ(w.start.x_m, 1.5);
  EXPECT_DOUBLE_EQ(w.start.y_m, 2.0);
  EXPECT_NEAR(w.start.yaw_rad, M_PI / 2, 1e-12);
  EXPECT_FALSE(w.image.has_value());

  // The door splits the 10 m wall into two pieces plus a lintel over the 0.9 m gap.
  ASSERT_EQ(w.walls.size(), 4u);
  expectWall(w.walls[0], {0, 0}, {2.55, 0}, 0.0, 2.6, 0.2);
  expectWall(w.walls[1], {3.45, 0}, {10, 0}, 0.0, 2.6, 0.2);
  expectWall(w.walls[2], {2.55, 0}, {3.45, 0}, 2.0, 2.6, 0.2);
  expectWall(w.walls[3], {0, 5}, {10, 5}, 0.0, 3.0, 0.1);
  ASSERT_EQ(w.doors.size(), 1u);
  expectPoint(w.doors[0].center_m, 3, 0.05);
  EXPECT_DOUBLE_EQ(w.doors[0].width_m, 0.9);

  ASSERT_EQ(w.rooms.size(), 2u);
  EXPECT_EQ(w.rooms[0].id, 1);
  EXPECT_EQ(w.rooms[0].name, "hall");
  EXPECT_EQ(w.rooms[1].id, 2);
  EXPECT_EQ(w.rooms[1].name, "kitchen");
  ASSERT_EQ(w.rooms[1].polygon_m.size(), 4u);
  expectPoint(w.rooms[1].polygon_m[2], 10, 5);

  ASSERT_EQ(w.furniture.size(), 2u);
  EXPECT_EQ(w.furniture[0].name, "sofa");
  expectBox(w.furniture[0].footprint_m, 1.6, 3.0, 2.4, 5.0);  // turned by 90 degrees
  EXPECT_DOUBLE_EQ(w.furniture[0].z_min_m, 0.0);
  EXPECT_DOUBLE_EQ(w.furniture[0].z_max_m, 0.8);
  EXPECT_EQ(w.furniture[1].name, "wardrobe");
  ASSERT_EQ(w.furniture[1].footprint_m.size(), 4u);
  expectPoint(w.furniture[1].footprint_m[1], 8.5, 4.4);
  EXPECT_DOUBLE_EQ(w.furniture[1].z_min_m, 0.1);
  EXPECT_DOUBLE_EQ(w.furniture[1].z_max_m, 2.0);
}

TEST(ParseWorldYaml, DefaultsAndMinimalWorld) {
  const sim::World w = parseWorldYaml("name: empty\nstart: [0, 0, 0]\n", kSource);
  EXPECT_EQ(w.name, "empty");
  EXPECT_EQ(w.description, "");
  EXPECT_DOUBLE_EQ(w.wall_height_m, 2.5);
  EXPECT_TRUE(w.walls.empty());
  EXPECT_TRUE(w.rooms.empty());
  // A polyline gives one wall per consecutive pair, with the default thickness and height.
  const sim::World p = parseWorldYaml(
      "name: p\nstart: [1, 1, -90]\nwalls:\n  - [[0, 0], [4, 0], [4, 3]]\n", kSource);
  ASSERT_EQ(p.walls.size(), 2u);
  expectWall(p.walls[0], {0, 0}, {4, 0}, 0.0, 2.5, 0.15);
  expectWall(p.walls[1], {4, 0}, {4, 3}, 0.0, 2.5, 0.15);
  EXPECT_NEAR(p.start.yaw_rad, -M_PI / 2, 1e-12);
}

TEST(ParseWorldYaml, StartOutsideTheWallsIsLeftToTheSimulator) {
  const sim::World w =
      parseWorldYaml("name: far\nstart: [100, 100, 0]\nwalls: [[[0, 0], [1, 0]]]\n", kSource);
  EXPECT_DOUBLE_EQ(w.start.x_m, 100.0);
}

TEST(ParseWorldYaml, DoorAtAJunctionCutsBothWalls) {
  const sim::World w = parseWorldYaml(R"(
name: junction
start: [1, 1, 0]
walls:
  - [[0, 0], [5, 0], [10, 0]]
doors:
  - {center: [5, 0], width_m: 1.0, lintel_m: 2.2}
)",
                                      kSource);
  ASSERT_EQ(w.walls.size(), 4u);
  expectWall(w.walls[0], {0, 0}, {4.5, 0}, 0.0, 2.5, 0.15);
  expectWall(w.walls[1], {4.5, 0}, {5, 0}, 2.2, 2.5, 0.15);
  expectWall(w.walls[2], {5.5, 0}, {10, 0}, 0.0, 2.5, 0.15);
  expectWall(w.walls[3], {5, 0}, {5.5, 0}, 2.2, 2.5, 0.15);
}

TEST(ParseWorldYaml, TwoDoorsInOneWallAndNoLintelAboveTheWall) {
  const sim::World w = parseWorldYaml(R"(
name: two_doors
start: [1, 1, 0]
walls:
  - points: [[0, 0], [0, 10]]
    height_m: 2.0
doors:
  - {center: [0, 2], width_m: 1.0}           # default lintel 2.0 = wall height: no lintel
  - {center: [0.075, 8], width_m: 0.8, lintel_m: 1.5}  # exactly half a thickness off
)",
                                      kSource);
  ASSERT_EQ(w.walls.size(), 4u);
  expectWall(w.walls[0], {0, 0}, {0, 1.5}, 0.0, 2.0, 0.15);
  expectWall(w.walls[1], {0, 2.5}, {0, 7.6}, 0.0, 2.0, 0.15);
  expectWall(w.walls[2], {0, 8.4}, {0, 10}, 0.0, 2.0, 0.15);
  expectWall(w.walls[3], {0, 7.6}, {0, 8.4}, 1.5, 2.0, 0.15);
}

TEST(ParseWorldYaml, DoorAtTheEndOfAWallIsClipped) {
  const sim::World w = parseWorldYaml(
      "name: e\nstart: [1, 1, 0]\nwalls: [[[0, 0], [4, 0]]]\ndoors: [{center: [0.2, 0], "
      "width_m: 1.0}]\n",
      kSource);
  ASSERT_EQ(w.walls.size(), 2u);
  expectWall(w.walls[0], {0.7, 0}, {4, 0}, 0.0, 2.5, 0.15);
  expectWall(w.walls[1], {0, 0}, {0.7, 0}, 2.0, 2.5, 0.15);
}

TEST(ParseWorldYaml, TableExpandsIntoTopAndFourLegs) {
  const sim::World w = parseWorldYaml(R"(
name: dining
start: [0, 0, 0]
furniture:
  - name: dining_table
    kind: table
    box: {center: [4, 4], size: [1.6, 0.9]}
    height_m: 0.75
)",
                                      kSource);
  ASSERT_EQ(w.furniture.size(), 5u);
  const sim::FurniturePiece& top = w.furniture[0];
  EXPECT_EQ(top.name, "dining_table/top");
  expectBox(top.footprint_m, 3.2, 3.55, 4.8, 4.45);
  EXPECT_NEAR(top.z_min_m, 0.71, kEps);
  EXPECT_NEAR(top.z_max_m, 0.75, kEps);
  // Legs: 0.05 m squares whose outer faces are 0.05 m in from the box's edges.
  const double legs[4][4] = {{3.25, 3.60, 3.30, 3.65},
                             {4.70, 3.60, 4.75, 3.65},
                             {4.70, 4.35, 4.75, 4.40},
                             {3.25, 4.35, 3.30, 4.40}};
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const sim::FurniturePiece& leg = w.furniture[1 + i];
    EXPECT_EQ(leg.name, "dining_table/leg_" + std::to_string(i + 1));
    expectBox(leg.footprint_m, legs[i][0], legs[i][1], legs[i][2], legs[i][3]);
    EXPECT_NEAR(leg.z_min_m, 0.0, kEps);
    EXPECT_NEAR(leg.z_max_m, 0.71, kEps);
  }
}

TEST(ParseWorldYaml, TableRespectsBoxYaw) {
  const sim::World w = parseWorldYaml(R"(
name: turned
start: [0, 0, 0]
furniture:
  - name: t
    kind: table
    box: {center: [0, 0], size: [2.0, 1.0], yaw_deg: 90}
    height_m: 0.7
)",
                                      kSource);
  ASSERT_EQ(w.furniture.size(), 5u);
  expectBox(w.furniture[0].footprint_m, -0.5, -1.0, 0.5, 1.0);
  // Leg 1 is centred at local (-0.925, -0.425); turned by 90 degrees: (0.425, -0.925).
  expectBox(w.furniture[1].footprint_m, 0.4, -0.95, 0.45, -0.9);
  EXPECT_NEAR(w.furniture[1].z_max_m, 0.66, kEps);
}

TEST(LoadWorldFile, ReadsFileAndNamesItInErrors) {
  const TempDir dir;
  const auto good = dir.write("w.yaml", kGoodWorld);
  const sim::World w = loadWorldFile(good);
  EXPECT_EQ(w.source, good.string());
  EXPECT_EQ(w.walls.size(), 4u);

  const auto bad = dir.write("bad.yaml", "name: bad\nstart: [0, 0, 0]\nwals: []\n");
  const std::string message = roomscout::test::messageOf<InputError>([&] { loadWorldFile(bad); });
  EXPECT_TRUE(Contains(message, bad.string() + ": unknown key 'wals'"));
  EXPECT_TRUE(
      Contains(roomscout::test::messageOf<InputError>([&] { loadWorldFile(dir / "none.yaml"); }),
               (dir / "none.yaml").string() + ": file not found"));
}

/// A bad world and the parts its error message must contain (after "<source>: ").
struct BadWorld {
  const char* label;
  std::string yaml;
  std::vector<std::string> expected;
};

void PrintTo(const BadWorld& bad, std::ostream* os) { *os << bad.label; }

const std::string kHead = "name: bad\nstart: [1, 1, 0]\n";
const std::string kWall = "walls:\n  - [[0, 0], [10, 0]]\n";

std::vector<BadWorld> badWorlds() {
  return {
      {"malformed", "name: bad\nstart: [1, 1, 0\nwalls: []\n", {"line ", "invalid YAML"}},
      {"empty", "", {"empty"}},
      {"not_a_map", "- 1\n- 2\n", {"expected a map"}},
      {"unknown_top_key",
       kHead + "wals: []\n",
       {"unknown key 'wals' (known: name, description, wall_thickness_m"}},
      {"duplicate_key", kHead + "name: again\n", {"key 'name' appears twice"}},
      {"missing_name", "start: [1, 1, 0]\n", {"missing required key 'name'"}},
      {"missing_start", "name: bad\n", {"missing required key 'start'"}},
      {"bad_name", "name: Bad House\nstart: [1, 1, 0]\n", {"name: 'Bad House' must match"}},
      {"start_short",
       "name: bad\nstart: [1, 1]\n",
       {"start: expected a start pose [x, y, yaw_deg]"}},
      {"start_type", "name: bad\nstart: [1, one, 0]\n", {"start[1]: expected a number, got 'one'"}},
      {"start_nan", "name: bad\nstart: [.nan, 1, 0]\n", {"start[0]: expected a finite number"}},
      {"height_inf", kHead + "wall_height_m: .inf\n", {"wall_height_m: expected a finite number"}},
      {"thickness_zero", kHead + "wall_thickness_m: 0\n", {"wall_thickness_m: must be > 0, got 0"}},
      {"walls_not_list", kHead + "walls: {a: 1}\n", {"walls: expected a list, got a map"}},
      {"wall_one_point",
       kHead + "walls:\n  - [[0, 0]]\n",
       {"walls[0]: a wall polyline needs at least 2 points, got 1"}},
      {"wall_point_type",
       kHead + "walls:\n  - [[0, 0], [1, x]]\n",
       {"walls[0][1][1]: expected a number, got 'x'"}},
      {"wall_point_size",
       kHead + "walls:\n  - [[0, 0], [1, 2, 3]]\n",
       {"walls[0][1]: expected a point [x, y]"}},
      {"wall_coincide",
       kHead + "walls:\n  - [[0, 0], [0, 0]]\n",
       {"walls[0]: points 0 and 1 coincide"}},
      {"wall_unknown_key",
       kHead + "walls:\n  - points: [[0, 0], [1, 0]]\n    thickness: 0.1\n",
       {"walls[0]: unknown key 'thickness' (known: points, thickness_m, height_m)"}},
      {"wall_negative_thickness",
       kHead + "walls:\n  - points: [[0, 0], [1, 0]]\n    thickness_m: -0.1\n",
       {"walls[0].thickness_m: must be > 0, got -0.1"}},
      {"wall_missing_points",
       kHead + "walls:\n  - height_m: 2\n",
       {"walls[0]: missing required key 'points'"}},
      {"door_missing_width",
       kHead + kWall + "doors:\n  - center: [3, 0]\n",
       {"doors[0]: missing required key 'width_m'"}},
      {"door_width_type",
       kHead + kWall + "doors:\n  - {center: [3, 0], width_m: wide}\n",
       {"doors[0].width_m: expected a number, got 'wide'"}},
      {"door_width_zero",
       kHead + kWall + "doors:\n  - {center: [3, 0], width_m: 0}\n",
       {"doors[0].width_m: must be > 0"}},
      {"door_lintel_negative",
       kHead + kWall + "doors:\n  - {center: [3, 0], width_m: 0.9, lintel_m: -1}\n",
       {"doors[0].lintel_m: must be > 0"}},
      {"door_no_wall",
       kHead + kWall +
           "doors:\n  - {center: [3, 0], width_m: 0.9}\n  - {center: [3, 1], width_m: 0.9}\n",
       {"doors[1]: the door at (3, 1) touches no wall"}},
      {"door_just_off_wall",
       kHead + kWall + "doors:\n  - {center: [3, 0.076], width_m: 0.9}\n",
       {"doors[0]: the door at (3, 0.076) touches no wall"}},
      {"door_unknown_key",
       kHead + kWall + "doors:\n  - {centre: [3, 0], width_m: 0.9}\n",
       {"doors[0]: unknown key 'centre' (known: center, width_m, lintel_m)"}},
      {"room_short_polygon",
       kHead + "rooms:\n  - {name: r, polygon: [[0, 0], [1, 0]]}\n",
       {"rooms[0].polygon: a polygon needs at least 3 points, got 2"}},
      {"room_missing_name",
       kHead + "rooms:\n  - {polygon: [[0, 0], [1, 0], [1, 1]]}\n",
       {"rooms[0]: missing required key 'name'"}},
      {"furniture_unknown_key",
       kHead + "furniture:\n" +
           "  - {name: a, box: {center: [1, 1], size: [1, 1]}, z_m: [0, 1]}\n" +
           "  - {name: b, box: {center: [1, 1], size: [1, 1]}, z_m: [0, 1]}\n" +
           "  - {name: c, box: {center: [1, 1], size: [1, 1]}, z_m: [0, 1]}\n" +
           "  - name: d\n    kind: table\n    box: {center: [1, 1], size: [1, 1]}\n    hight_m: "
           "0.7\n",
       {"furniture[3]: unknown key 'hight_m' (known: name, kind, box, polygon, z_m, height_m)"}},
      {"furniture_size_zero",
       kHead + "furniture:\n  - {name: a, box: {center: [1, 1], size: [0, 1]}, z_m: [0, 1]}\n",
       {"furniture[0].box.size[0]: must be > 0, got 0"}},
      {"furniture_box_unknown_key",
       kHead +
           "furniture:\n  - {name: a, box: {center: [1, 1], size: [1, 1], yaw: 3}, z_m: [0, 1]}\n",
       {"furniture[0].box: unknown key 'yaw' (known: center, size, yaw_deg)"}},
      {"furniture_z_order",
       kHead + "furniture:\n  - {name: a, box: {center: [1, 1], size: [1, 1]}, z_m: [1, 1]}\n",
       {"furniture[0].z_m: z_min (1) must be below z_max (1)"}},
      {"furniture_missing_z",
       kHead + "furniture:\n  - {name: a, box: {center: [1, 1], size: [1, 1]}}\n",
       {"furniture[0]: missing required key 'z_m'"}},
      {"furniture_both_footprints",
       kHead + "furniture:\n  - {name: a, box: {center: [1, 1], size: [1, 1]}, polygon: [[0, 0], "
               "[1, 0], [1, 1]], z_m: [0, 1]}\n",
       {"furniture[0]: give either 'box' or 'polygon', not both"}},
      {"furniture_no_footprint",
       kHead + "furniture:\n  - {name: a, z_m: [0, 1]}\n",
       {"furniture[0]: missing 'box' or 'polygon'"}},
      {"furniture_short_polygon",
       kHead + "furniture:\n  - {name: a, polygon: [[0, 0], [1, 1]], z_m: [0, 1]}\n",
       {"furniture[0].polygon: a polygon needs at least 3 points"}},
      {"furniture_unknown_kind",
       kHead + "furniture:\n  - {name: a, kind: chair, box: {center: [1, 1], size: [1, 1]}, z_m: "
               "[0, 1]}\n",
       {"furniture[0].kind: unknown kind 'chair' (known: block, table)"}},
      {"block_with_height",
       kHead + "furniture:\n  - {name: a, box: {center: [1, 1], size: [1, 1]}, height_m: 1}\n",
       {"furniture[0]: 'height_m' is only for kind: table"}},
      {"table_with_polygon",
       kHead + "furniture:\n  - {name: a, kind: table, polygon: [[0, 0], [1, 0], [1, 1]], "
               "height_m: 1}\n",
       {"furniture[0]: kind: table needs a 'box'"}},
      {"table_with_z",
       kHead + "furniture:\n  - {name: a, kind: table, box: {center: [1, 1], size: [1, 1]}, z_m: "
               "[0, 1]}\n",
       {"furniture[0]: kind: table takes 'height_m', not 'z_m'"}},
      {"table_missing_height",
       kHead + "furniture:\n  - {name: a, kind: table, box: {center: [1, 1], size: [1, 1]}}\n",
       {"furniture[0]: missing required key 'height_m'"}},
      {"table_too_low",
       kHead + "furniture:\n  - {name: a, kind: table, box: {center: [1, 1], size: [1, 1]}, "
               "height_m: 0.03}\n",
       {"furniture[0].height_m: must be above the top's thickness"}},
      {"table_too_small",
       kHead + "furniture:\n  - {name: a, kind: table, box: {center: [1, 1], size: [0.15, 1]}, "
               "height_m: 0.7}\n",
       {"furniture[0].box.size: a table needs at least 0.2 m on each side"}},
  };
}

class BadWorldTest : public ::testing::TestWithParam<BadWorld> {};

TEST_P(BadWorldTest, IsRejectedWithSourceAndPlace) {
  const BadWorld& bad = GetParam();
  std::string problem;
  try {
    parseWorldYaml(bad.yaml, kSource);
    ADD_FAILURE() << "accepted:\n" << bad.yaml;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), kSource);
    EXPECT_TRUE(Contains(e.what(), std::string(kSource) + ": "));
    problem = e.problem();
  }
  for (const std::string& part : bad.expected) EXPECT_TRUE(Contains(problem, part));
}

INSTANTIATE_TEST_SUITE_P(AllBadInputs, BadWorldTest, ::testing::ValuesIn(badWorlds()),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(ParseWorldYaml, MalformedYamlReportsTheLine) {
  try {
    parseWorldYaml("name: bad\nstart: [1, 1, 0]\nwalls:\n  - [[0, 0], [1, 0]\n  - x: : y\n",
                   kSource);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.problem(), "line ")) << e.what();
    EXPECT_EQ(e.problem().rfind("line ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace roomscout::sim
