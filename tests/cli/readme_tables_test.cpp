// The README's result tables are what their committed commands print from the CSVs in
// docs/tables/, and the binary still gives those CSVs' small-house episodes (the other worlds:
// readme_tables_slow_test.cpp).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"
#include "readme_tables.hpp"

namespace roomscout::test {
namespace {

TEST(ReadmeTables, EachIsWhatItsCommandPrints) {
  const std::filesystem::path source(ROOMSCOUT_SOURCE_DIR);
  const std::vector<GeneratedTable> tables = generatedTables(readText(source / "README.md"));
  ASSERT_GE(tables.size(), 2u) << "README.md: the method tables' markers are gone";
  const TempDir dir;
  for (const GeneratedTable& t : tables) {
    SCOPED_TRACE(t.command);
    const CommandResult r =
        runCommand("cd " + source.string() + " && python3 " + t.command, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(t.content, trimmed(r.output)) << "README.md's table differs from what " << t.command
                                            << " prints: paste the command's output in";
  }
}

TEST(ReadmeTables, TheBinaryStillGivesTheSmallHouseEpisodes) {
  const std::vector<std::filesystem::path> csvs = readmeTableCsvs();
  ASSERT_GE(csvs.size(), 2u);
  const TempDir dir;
  for (const std::filesystem::path& csv : csvs)
    expectTheBinaryGivesTheEpisodes(csv, {"small_house"}, dir.path() / csv.stem());
}

}  // namespace
}  // namespace roomscout::test
