// `roomscout slam` on bad input: one message naming the file or option, exit code 2, and no
// output folder left behind.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

using test::Contains;

TEST(SlamCliTest, AMissingLogIsNamedAndLeavesNoOutputFolder) {
  test::TempDir dir;
  const fs::path log = dir / "missing.rawlog";
  const test::CommandResult r = test::runRoomscout(
      "slam --rawlog " + log.string() + " --mode icp --out " + (dir / "out").string(), dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, log.string() + ": file not found"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(SlamCliTest, AFileThatIsNoRawlogIsNamed) {
  test::TempDir dir;
  const fs::path log = dir.write("map.yaml", "image: map.pgm\nresolution: 0.05\n");
  const test::CommandResult r = test::runRoomscout(
      "slam --rawlog " + log.string() + " --mode icp --out " + (dir / "out").string(), dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, log.string() + ": not an MRPT rawlog"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(SlamCliTest, NeedsASlamModeAndRejectsAnUnknownOne) {
  test::TempDir dir;
  const fs::path log = dir.write("x.rawlog", "");
  const std::string base = "slam --rawlog " + log.string() + " --out " + (dir / "out").string();
  const test::CommandResult none = test::runRoomscout(base, dir.path());
  EXPECT_EQ(none.exit_code, 2) << none.output;
  EXPECT_TRUE(Contains(none.output, "--mode"));
  const test::CommandResult unknown = test::runRoomscout(base + " --mode fastslam", dir.path());
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_TRUE(Contains(unknown.output, "--mode: slam.mode"));
  EXPECT_TRUE(Contains(unknown.output, "fastslam"));
  // From a config file: the file and the key are named.
  const fs::path config = dir.write("c.yaml", "slam:\n  particles: 0\n");
  const test::CommandResult bad =
      test::runRoomscout(base + " --mode rbpf --config " + config.string(), dir.path());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_TRUE(Contains(bad.output, config.string() + ": slam.particles"));
  const fs::path typo = dir.write("t.yaml", "slam:\n  mdoe: icp\n");
  const test::CommandResult typo_r =
      test::runRoomscout(base + " --config " + typo.string(), dir.path());
  EXPECT_EQ(typo_r.exit_code, 2) << typo_r.output;
  EXPECT_TRUE(Contains(typo_r.output, typo.string()));
  EXPECT_TRUE(Contains(typo_r.output, "mdoe"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace roomscout
