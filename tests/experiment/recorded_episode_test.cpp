// runRecordedEpisode: the maps built on a background thread (as `explore` builds them) are
// byte for byte those built at once on the episode's thread (as `bench` builds them).

#include "roomscout/experiment/recorded_episode.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "../support/temp_dir.hpp"
#include "roomscout/sim/builtin_worlds.hpp"

namespace roomscout::experiment {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class RecordedEpisodeTest : public ::testing::Test {
 protected:
  RecordedEpisode run(const std::string& method, bool background, const fs::path& out) {
    RunSettings settings;
    settings.max_time_s = 120.0;  // small_house: about a third explored, dozens of map updates
    settings.background_maps = background;
    EpisodeSetup setup = makeEpisodeSetup(method, 2, settings);
    const sim::WorldModel model(sim::loadBuiltinWorld("small_house"), setup.config.world);
    return runRecordedEpisode(model, setup, settings, out);
  }

  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(RecordedEpisodeTest, MapsBuiltInTheBackgroundAreThoseBuiltAtOnce) {
  // semantic reads the rooms, so they are built at once and only the point cloud and the
  // skeleton go to the worker (which gets a copy of the rooms); mmpf does not, so all three
  // maps go to the worker, the skeleton after the rooms it reads.
  for (const std::string method : {"semantic", "mmpf"}) {
    SCOPED_TRACE(method);
    const RecordedEpisode at_once = run(method, false, dir_ / method / "at_once");
    const RecordedEpisode background = run(method, true, dir_ / method / "background");
    for (const char* file : {"pointcloud.pcd", "topology.json", "semantic.json",
                             "semantic_labels.png", "occupancy.pgm", "trajectory.csv"}) {
      const std::string a = slurp(dir_ / method / "at_once" / file);
      EXPECT_FALSE(a.empty()) << file;
      EXPECT_TRUE(a == slurp(dir_ / method / "background" / file)) << file << " differs";
    }
    for (const char* map : {"pointcloud", "semantic", "topological"}) {
      const std::size_t updates = at_once.result.map_updates.at(map).count;
      EXPECT_GE(updates, map == std::string("pointcloud") ? 50u : 10u) << map;
      EXPECT_EQ(background.result.map_updates.at(map).count, updates) << map;
    }
    EXPECT_EQ(background.result.length_m, at_once.result.length_m);
    EXPECT_EQ(background.result.goals, at_once.result.goals);
  }
}

}  // namespace
}  // namespace roomscout::experiment
