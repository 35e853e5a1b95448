#include "roomscout/io/options_yaml.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/explorer/explorer.hpp"

namespace roomscout::io {
namespace {

using test::Contains;
using test::TempDir;

/// A stand-in options struct with one parameter of every type.
struct LaserOptions {
  double range_max_m = 3.5;
  int num_beams = 360;
  bool noise = true;
  std::string model = "lds01";

  std::vector<ParameterRef> parameters() {
    return {{"range_max_m", &range_max_m, "maximum range [m]"},
            {"num_beams", &num_beams, "beams per scan"},
            {"noise", &noise, "add range noise"},
            {"model", &model, "sensor model"}};
  }
};

struct RobotOptions {
  double radius_m = 0.105;
  std::vector<ParameterRef> parameters() { return {{"radius_m", &radius_m, "footprint radius"}}; }
};

std::string optionErrorOf(const auto& fn) { return test::messageOf<OptionError>(fn); }

TEST(ApplyParameters, AppliesGoodValues) {
  LaserOptions o;
  applyParameters(YAML::Load("{range_max_m: 8, num_beams: 720, noise: false, model: rplidar}"),
                  o.parameters(), "laser");
  EXPECT_DOUBLE_EQ(o.range_max_m, 8.0);
  EXPECT_EQ(o.num_beams, 720);
  EXPECT_FALSE(o.noise);
  EXPECT_EQ(o.model, "rplidar");

  applyParameters(YAML::Load("range_max_m: 1.25e1\nnoise: yes\nmodel: 42\n"), o.parameters(),
                  "laser");
  EXPECT_DOUBLE_EQ(o.range_max_m, 12.5);
  EXPECT_TRUE(o.noise);
  EXPECT_EQ(o.model, "42");
  EXPECT_EQ(o.num_beams, 720);  // untouched
}

TEST(ApplyParameters, EmptyNodeChangesNothing) {
  LaserOptions o;
  applyParameters(YAML::Load(""), o.parameters(), "laser");
  applyParameters(YAML::Load("{}"), o.parameters(), "laser");
  EXPECT_EQ(o.num_beams, 360);
}

TEST(ApplyParameters, RejectsUnknownOptionListingKnownOnes) {
  LaserOptions o;
  EXPECT_EQ(optionErrorOf([&] {
              applyParameters(YAML::Load("{num_beams: 10, foo: 1}"), o.parameters(), "laser");
            }),
            "laser: unknown option 'foo' (known: range_max_m, num_beams, noise, model)");
  EXPECT_EQ(o.num_beams, 360) << "nothing applied when any key is bad";
}

TEST(ApplyParameters, RejectsWrongTypesNamingKeyAndValue) {
  struct Case {
    std::string yaml;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"num_beams: abc", "laser.num_beams: expected an integer, got 'abc'"},
      {"num_beams: 3.5", "laser.num_beams: expected an integer, got '3.5'"},
      {"num_beams: 99999999999", "laser.num_beams: expected an integer, got '99999999999'"},
      {"num_beams: [1, 2]", "laser.num_beams: expected an integer, got a list"},
      {"range_max_m: far", "laser.range_max_m: expected a finite number, got 'far'"},
      {"range_max_m: .inf", "laser.range_max_m: expected a finite number, got '.inf'"},
      {"range_max_m: .nan", "laser.range_max_m: expected a finite number, got '.nan'"},
      {"range_max_m:", "laser.range_max_m: expected a finite number, got nothing"},
      {"noise: maybe", "laser.noise: expected true or false, got 'maybe'"},
      {"noise: 1", "laser.noise: expected true or false, got '1'"},
      {"model: {a: 1}", "laser.model: expected a string, got a map"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.yaml);
    LaserOptions o;
    EXPECT_EQ(optionErrorOf([&] { applyParameters(YAML::Load(c.yaml), o.parameters(), "laser"); }),
              c.message);
    EXPECT_EQ(o.num_beams, 360);
    EXPECT_DOUBLE_EQ(o.range_max_m, 3.5);
  }
}

TEST(ApplyParameters, RejectsNonMapAndDuplicateKeys) {
  LaserOptions o;
  EXPECT_EQ(optionErrorOf([&] { applyParameters(YAML::Load("[1, 2]"), o.parameters(), "laser"); }),
            "laser: expected a map of options, got a list");
  EXPECT_EQ(optionErrorOf([&] { applyParameters(YAML::Load("5"), o.parameters(), ""); }),
            "expected a map of options, got '5'");
  EXPECT_TRUE(Contains(optionErrorOf([&] {
                         applyParameters(YAML::Load("num_beams: 1\nnum_beams: 2\n"), o.parameters(),
                                         "laser");
                       }),
                       "laser.num_beams: given twice"));
}

TEST(ParametersToJson, WritesEveryValueWithItsType) {
  LaserOptions o;
  o.num_beams = 90;
  const nlohmann::json j = parametersToJson(o.parameters());
  EXPECT_EQ(j, nlohmann::json::parse(
                   R"({"range_max_m": 3.5, "num_beams": 90, "noise": true, "model": "lds01"})"));
  EXPECT_TRUE(j["num_beams"].is_number_integer());
  EXPECT_TRUE(j["range_max_m"].is_number_float());
  EXPECT_EQ(parametersToJson({}), nlohmann::json::object());
}

TEST(ApplyConfigFile, AppliesGroupsAndRejectsUnknownGroup) {
  const TempDir dir;
  LaserOptions laser;
  RobotOptions robot;
  std::vector<ParameterGroup> groups = {{"laser", laser.parameters()},
                                        {"robot", robot.parameters()}};
  const auto good = dir.write("cfg.yaml",
                              "# comment\nlaser:\n  num_beams: 180\nrobot:\n"
                              "  radius_m: 0.2\n");
  applyConfigFile(good, groups);
  EXPECT_EQ(laser.num_beams, 180);
  EXPECT_DOUBLE_EQ(robot.radius_m, 0.2);
  EXPECT_EQ(parametersToJson(groups[1].parameters), nlohmann::json::parse(R"({"radius_m": 0.2})"));

  const auto unknown = dir.write("unknown.yaml", "lasr:\n  num_beams: 1\n");
  EXPECT_EQ(optionErrorOf([&] { applyConfigFile(unknown, groups); }),
            unknown.string() + ": unknown group 'lasr' (known: laser, robot)");

  const auto bad_value = dir.write("bad.yaml", "laser:\n  num_beams: abc\n");
  EXPECT_EQ(optionErrorOf([&] { applyConfigFile(bad_value, groups); }),
            bad_value.string() + ": laser.num_beams: expected an integer, got 'abc'");
  const auto bad_key = dir.write("badkey.yaml", "robot:\n  radius: 1\n");
  EXPECT_EQ(optionErrorOf([&] { applyConfigFile(bad_key, groups); }),
            bad_key.string() + ": robot: unknown option 'radius' (known: radius_m)");
  EXPECT_EQ(laser.num_beams, 180);

  const auto empty = dir.write("empty.yaml", "");
  applyConfigFile(empty, groups);
  EXPECT_EQ(laser.num_beams, 180);
}

TEST(ApplyConfigFile, SyntaxErrorsAndMissingFilesAreInputErrors) {
  const TempDir dir;
  LaserOptions laser;
  std::vector<ParameterGroup> groups = {{"laser", laser.parameters()}};
  const auto broken = dir.write("broken.yaml", "laser:\n  num_beams: 10\n  noise: [true\n");
  const std::string message = test::messageOf<InputError>([&] { applyConfigFile(broken, groups); });
  EXPECT_TRUE(Contains(message, broken.string() + ": line "));
  EXPECT_TRUE(
      Contains(test::messageOf<InputError>([&] { applyConfigFile(dir / "missing.yaml", groups); }),
               (dir / "missing.yaml").string() + ": file not found"));
  const auto list = dir.write("list.yaml", "- laser\n");
  EXPECT_TRUE(Contains(test::messageOf<InputError>([&] { applyConfigFile(list, groups); }),
                       list.string() + ": expected a map of option groups (laser)"));
}

TEST(ApplyConfigFile, LoadsTheExplorersOptionsFromItsOwnGroups) {
  const TempDir dir;
  ExplorerOptions options;
  std::vector<ParameterGroup> groups = options.groups();
  const auto file = dir.write(
      "robot.yaml",
      "costmap:\n  robot_radius_m: 0.2\n  inflation_margin_m: 0.08\nplanner:\n  allow_unknown: "
      "false\nexplorer:\n  no_progress_timeout_s: 30\n  arrival_tolerance_m: 0.3\n  "
      "sensor_range_m: 8\nmaps:\n  period_s: 2\nsegmentation:\n  door_cut_max_width_m: 1.2\n");
  EXPECT_TRUE(applyConfigFile(file, groups).empty());
  EXPECT_DOUBLE_EQ(options.costmap.robot_radius_m, 0.2);
  EXPECT_DOUBLE_EQ(options.costmap.inflation_margin_m, 0.08);
  EXPECT_FALSE(options.planner.allow_unknown);
  EXPECT_DOUBLE_EQ(options.goals.no_progress_timeout_s, 30.0);
  EXPECT_DOUBLE_EQ(options.goals.arrival_tolerance_m, 0.3);
  EXPECT_DOUBLE_EQ(options.goals.sensor_range_m, 8.0);
  EXPECT_DOUBLE_EQ(options.maps.period_s, 2.0);
  EXPECT_DOUBLE_EQ(options.maps.segmentation.door_cut_max_width_m, 1.2);
  EXPECT_NO_THROW(options.validate());
  const auto bad = dir.write("bad.yaml", "explorer:\n  stall_min_new_area_m2: -1\n");
  applyConfigFile(bad, groups);
  EXPECT_THROW(options.validate(), OptionError);
}

TEST(ApplyConfigFile, ReadsARenamedOptionUnderItsNewNameWithAWarning) {
  const TempDir dir;
  ExplorerOptions options;
  std::vector<ParameterGroup> groups = options.groups();
  const auto file = dir.write("old.yaml", "episode:\n  no_progress_timeout_s: 30\n");
  const std::vector<std::string> warnings =
      applyConfigFile(file, groups, ExplorerOptions::renamedOptions());
  EXPECT_DOUBLE_EQ(options.goals.no_progress_timeout_s, 30.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(Contains(warnings[0],
                       "episode.no_progress_timeout_s is now "
                       "explorer.no_progress_timeout_s"));
  const auto both =
      dir.write("both.yaml",
                "episode:\n  no_progress_timeout_s: 30\nexplorer:\n  no_progress_timeout_s: 20\n");
  EXPECT_THROW(applyConfigFile(both, groups, ExplorerOptions::renamedOptions()), OptionError);
}

}  // namespace
}  // namespace roomscout::io
