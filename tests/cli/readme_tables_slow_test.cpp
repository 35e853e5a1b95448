// Label "slow" (outside the default test run; `ctest -L slow`): the binary still gives the
// README tables' CSV episodes in the medium house and the large office, at each CSV's lowest
// seed. Several minutes on two cores.

#include <gtest/gtest.h>

#include <filesystem>

#include "../support/temp_dir.hpp"
#include "readme_tables.hpp"

namespace roomscout::test {
namespace {

TEST(ReadmeTablesSlow, TheBinaryStillGivesTheMediumHouseAndOfficeEpisodes) {
  const std::vector<std::filesystem::path> csvs = readmeTableCsvs();
  ASSERT_GE(csvs.size(), 2u);
  const TempDir dir;
  for (const std::filesystem::path& csv : csvs)
    expectTheBinaryGivesTheEpisodes(csv, {"medium_house", "large_office"}, dir.path() / csv.stem());
}

}  // namespace
}  // namespace roomscout::test
