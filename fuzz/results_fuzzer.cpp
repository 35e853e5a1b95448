// Fuzz target: a bench's results.jsonl as `roomscout report` reads it (experiment::loadResults,
// then the report's tables built from the records) and as `roomscout bench` reads it when it
// resumes (experiment::ResultsFile: the keys recorded, a truncated last line cut off).
// Accepted failures: InputError (a bad line, naming file:line) and OptionError.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/report_tables.hpp"
#include "roomscout/experiment/results_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path path = fuzz::scratchDir() / "results.jsonl";
  fuzz::writeFile(path, fuzz::asText(data, size));
  try {
    const experiment::ResultSet results = experiment::loadResults({path});
    const experiment::Report report = experiment::buildReport(results);
    (void)experiment::table1Cells(report);
    (void)experiment::revisitsCells(report);
    (void)experiment::oracleCells(report);
    (void)experiment::table2Cells(report);
    (void)experiment::table3Cells(report);
    (void)experiment::slamCells(report);
    (void)experiment::pairingLine(report);
    (void)experiment::sourcesLine(report);
    (void)experiment::sameEverySeedLine(report);
    (void)experiment::startPosesLine(report);
  } catch (const InputError&) {
  } catch (const OptionError&) {
  }
  try {
    const experiment::ResultsFile file(path);
    (void)file.recorded();
  } catch (const InputError&) {
  }
  return 0;
}
