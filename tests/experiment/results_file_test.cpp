// results.jsonl: whole lines, a truncated last line ignored and cut off, other bad lines named.

#include "roomscout/experiment/results_file.hpp"
#include "roomscout/experiment/report_records.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::experiment {
namespace {

namespace fs = std::filesystem;
using roomscout::test::Contains;
using roomscout::test::messageOf;

/// Reads every record of `path`, doing nothing with them.
void readAll(const fs::path& path) {
  forEachRecord(path, [](const nlohmann::json&, const std::string&) {});
}

class ResultsFileTest : public ::testing::Test {
 protected:
  fs::path write(const std::string& text) {
    std::ofstream(dir_ / "results.jsonl", std::ios::binary) << text;
    return dir_ / "results.jsonl";
  }
  std::string read() {
    std::ifstream in(dir_ / "results.jsonl", std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

const char* kLine1 = R"({"world":"w","method":"m","seed":1,"x":1})";
const char* kLine2 = R"({"world":"w","method":"m","seed":2,"x":2})";

TEST_F(ResultsFileTest, TruncatedLastLineIsIgnoredThenCutOff) {
  const fs::path p = write(std::string(kLine1) + "\n" + kLine2 + "\n" + R"({"world":"w","meth)");
  std::vector<int> seen;
  const ResultsScan scan = forEachRecord(
      p, [&](const nlohmann::json& r, const std::string&) { seen.push_back(r["x"]); });
  EXPECT_EQ(seen, (std::vector<int>{1, 2}));
  EXPECT_TRUE(scan.truncated_tail);
  {
    ResultsFile file(p);
    EXPECT_TRUE(file.droppedTruncatedLine());
    EXPECT_EQ(file.recorded().size(), 2u);
    EXPECT_TRUE(file.recorded().count({"w", "m", 2}));
    file.append({{"world", "w"}, {"method", "m"}, {"seed", 3}});
  }
  EXPECT_EQ(read(), std::string(kLine1) + "\n" + kLine2 + "\n" +
                        R"({"method":"m","seed":3,"world":"w"})" + "\n");
}

TEST_F(ResultsFileTest, WholeLastLineWithoutNewlineIsKept) {
  const fs::path p = write(std::string(kLine1) + "\n" + kLine2);
  {
    ResultsFile file(p);
    EXPECT_FALSE(file.droppedTruncatedLine());
    EXPECT_EQ(file.recorded().size(), 2u);
    file.append({{"world", "w"}, {"method", "m"}, {"seed", 3}});
  }
  std::size_t n = 0;
  forEachRecord(p, [&](const nlohmann::json&, const std::string&) { ++n; });
  EXPECT_EQ(n, 3u);
}

TEST_F(ResultsFileTest, MalformedLineIsNamedWithItsLineNumber) {
  const fs::path p = write(std::string(kLine1) + "\n{not json\n" + kLine2 + "\n");
  EXPECT_TRUE(Contains(messageOf<InputError>([&] { readAll(p); }), "results.jsonl:2"));
  EXPECT_THROW(ResultsFile{p}, InputError);
  // A complete last line (with its newline) that is not JSON is malformed too, not truncated.
  write(std::string(kLine1) + "\n{oops\n");
  EXPECT_THROW(readAll(p), InputError);
  // A record without its key.
  write(R"({"world":"w","seed":1})"
        "\n");
  EXPECT_TRUE(Contains(messageOf<InputError>([&] { readAll(p); }), "method"));
}

// Found by the results fuzz target: nlohmann-json refuses a number beyond double's range with
// an out_of_range exception, not a parse_error.
TEST_F(ResultsFileTest, NumberOutOfRangeIsNamedWithItsLineNumber) {
  const fs::path p =
      write(std::string(kLine1) +
            "\n{\"world\": \"w\", \"method\": \"m\", \"seed\": 1, \"rate\": 0.2E658}\n");
  EXPECT_TRUE(Contains(messageOf<InputError>([&] { readAll(p); }), "results.jsonl:2"));
  EXPECT_THROW(ResultsFile{p}, InputError);
  EXPECT_THROW(loadResults({p}), InputError);
}

TEST_F(ResultsFileTest, ConcurrentAppendsGiveWholeLines) {
  {
    ResultsFile file(dir_ / "results.jsonl");
    std::vector<std::jthread> threads;
    for (int t = 0; t < 4; ++t) {
      threads.emplace_back([&file, t] {
        for (int i = 0; i < 50; ++i) {
          file.append({{"world", std::string("w").append(std::to_string(t))},
                       {"method", "m"},
                       {"seed", i + 1},
                       {"pad", std::string(5000, 'x')}});
        }
      });
    }
  }
  std::size_t n = 0;
  forEachRecord(dir_ / "results.jsonl", [&](const nlohmann::json&, const std::string&) { ++n; });
  EXPECT_EQ(n, 200u);
}

}  // namespace
}  // namespace roomscout::experiment
