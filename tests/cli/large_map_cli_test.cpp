// Maps too large for roomscout (core/grid_limits.hpp) are refused by explore, maps and bench
// up front, with exit code 2, an error naming the file, its size and the limit, and no
// output folder left behind.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

class LargeMapCliTest : public ::testing::Test {
 protected:
  roomscout::test::CommandResult run(const std::string& args) {
    return roomscout::test::runRoomscout(args, dir_);
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }

  /// A map_server map whose PGM header claims `side` x `side` pixels (one row of data only).
  fs::path hugeMap(int side) {
    write("big.pgm", "P5\n" + std::to_string(side) + " " + std::to_string(side) + "\n255\n" +
                         std::string(static_cast<std::size_t>(side), '\xfe'));
    return write("big.yaml", "image: big.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  }

  /// `args` fails with exit code 2 and every one of `parts` in its message, and leaves no
  /// `out` folder.
  void expectRefused(const std::string& args, const fs::path& out,
                     const std::vector<std::string>& parts) {
    const auto [code, output] = run(args + " --out " + out.string());
    EXPECT_EQ(code, 2) << args << "\n" << output;
    for (const std::string& p : parts)
      EXPECT_NE(output.find(p), std::string::npos) << args << ": no '" << p << "' in\n" << output;
    EXPECT_FALSE(fs::exists(out)) << args << ": left " << out;
  }

  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(LargeMapCliTest, AQuarterSquareKilometreMapIsRefusedByEveryCommand) {
  const std::string yaml = hugeMap(10000).string();
  const std::vector<std::string> message = {
      yaml +
      ": map is 10000 x 10000 cells (100000000) at 0.05 m; roomscout handles at most "
      "25000000 cells (about 62500 m^2 at this resolution)"};
  expectRefused("explore --world " + yaml + " --max-time 10", dir_ / "explore", message);
  expectRefused("maps --map " + yaml, dir_ / "maps", message);
  expectRefused("bench --worlds " + yaml + " --methods mmpf --max-time 10", dir_ / "bench",
                message);
}

TEST_F(LargeMapCliTest, ResolutionsThatMakeAGridHugeAreRefused) {
  // A 40 x 40 image of 100 m pixels: a small image, but a 4 km map at 0.05 m.
  std::string pgm = "P5\n40 40\n255\n";
  for (int row = 0; row < 40; ++row) {
    for (int col = 0; col < 40; ++col) {
      const bool wall = row < 2 || row >= 38 || col < 2 || col >= 38;
      pgm += static_cast<char>(wall ? 0 : 254);
    }
  }
  write("coarse.pgm", pgm);
  const std::string coarse =
      write("coarse.yaml", "image: coarse.pgm\nresolution: 100\norigin: [0, 0, 0]\n").string();
  expectRefused("explore --world " + coarse + " --max-time 10", dir_ / "coarse",
                {coarse + ": explored map is 80000 x 80000 cells (6400000000) at 0.05 m "
                          "(mapping.resolution_m); roomscout handles at most 25000000 cells"});
  expectRefused("bench --worlds " + coarse + " --methods mmpf --max-time 10", dir_ / "bench",
                {"explored map is 80000 x 80000 cells"});

  // A world file rasterised at a needlessly fine resolution.
  const fs::path config = write("fine.yaml", "world:\n  raster_resolution_m: 0.0001\n");
  expectRefused("explore --world small_house --max-time 10 --config " + config.string(),
                dir_ / "fine",
                {"small_house: world raster is", "at 0.0001 m (world.raster_resolution_m)",
                 "at most 25000000 cells (about 0.25 m^2 at this resolution)"});
}

}  // namespace
