// scripts/make_building.py: the generated buildings load as worlds of about the asked area, the
// same seed gives the same file, one is explored to the end, and bad input is refused.

#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

using test::Contains;
using test::readText;
using test::runCommand;
using test::runRoomscout;

std::string script() {
  return "python3 " + (fs::path(ROOMSCOUT_SOURCE_DIR) / "scripts" / "make_building.py").string();
}

TEST(MakeBuilding, OfficesAndHousesOfTheAskedArea) {
  test::TempDir dir;
  for (const std::string kind : {"office", "house"}) {
    for (const int area : {400, 1500}) {
      SCOPED_TRACE(kind + " " + std::to_string(area));
      const fs::path yaml = dir.path() / (kind + std::to_string(area) + ".yaml");
      const test::CommandResult r =
          runCommand(script() + " " + yaml.string() + " --kind " + kind + " --area-m2 " +
                         std::to_string(area) + " --seed 4",
                     dir.path());
      ASSERT_EQ(r.exit_code, 0) << r.output;
      const sim::WorldModel model(sim::loadWorld(yaml.string()));
      EXPECT_NEAR(model.freeArea_m2(), area, 0.1 * area);
      EXPECT_TRUE(model.hasRooms());
      EXPECT_GE(model.world().rooms.size(), static_cast<std::size_t>(area / 60));
      EXPECT_TRUE(model.robotFits(model.start().position()));
    }
  }
}

TEST(MakeBuilding, TheSameSeedGivesTheSameBuilding) {
  test::TempDir dir;
  for (const std::string name : {"a", "b", "c"}) {
    const std::string seed = name == "c" ? "2" : "1";
    fs::create_directories(dir.path() / name);
    ASSERT_EQ(runCommand("cd " + (dir.path() / name).string() + " && " + script() +
                             " x.yaml --kind office --area-m2 800 --seed " + seed,
                         dir.path())
                  .exit_code,
              0);
  }
  const std::string a = readText(dir.path() / "a" / "x.yaml");
  EXPECT_TRUE(a == readText(dir.path() / "b" / "x.yaml"));
  EXPECT_FALSE(a == readText(dir.path() / "c" / "x.yaml"));
}

TEST(MakeBuilding, AGeneratedOfficeIsExploredToTheEnd) {
  test::TempDir dir;
  const fs::path yaml = dir.path() / "office.yaml";
  ASSERT_EQ(runCommand(script() + " " + yaml.string() + " --kind office --area-m2 500 --seed 7",
                       dir.path())
                .exit_code,
            0);
  const test::CommandResult r =
      runRoomscout("explore --world " + yaml.string() +
                       " --method nearest_frontier --seed 1 --out " + (dir.path() / "run").string(),
                   dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json m = nlohmann::json::parse(readText(dir.path() / "run" / "metrics.json"));
  EXPECT_GE(m.at("exploration_rate").get<double>(), 0.98);
  EXPECT_FALSE(m.at("timed_out").get<bool>());
}

TEST(MakeBuilding, RefusesAreasItCannotBuild) {
  test::TempDir dir;
  const fs::path yaml = dir.path() / "x.yaml";
  const test::CommandResult small =
      runCommand(script() + " " + yaml.string() + " --kind office --area-m2 50", dir.path());
  EXPECT_EQ(small.exit_code, 2);
  EXPECT_TRUE(Contains(small.output, "--area-m2"));
  const test::CommandResult large =
      runCommand(script() + " " + yaml.string() + " --kind house --area-m2 40000", dir.path());
  EXPECT_EQ(large.exit_code, 2);
  EXPECT_TRUE(Contains(large.output, "25000000") || Contains(large.output, "25 000 000"))
      << large.output;
  EXPECT_FALSE(fs::exists(yaml));
}

}  // namespace
}  // namespace roomscout
