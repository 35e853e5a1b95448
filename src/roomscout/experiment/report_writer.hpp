#pragma once
// Everything `roomscout report` (and the end of `bench`) writes into its output folder: the
// tables as Markdown (report_markdown.hpp) and CSV (report_csv.hpp), the figures
// (report_figures.hpp) and report.html (report_html.hpp), one self-contained page with all of
// them.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "roomscout/experiment/report.hpp"

namespace roomscout::experiment {

struct ReportSettings {
  bool oracle = true;    ///< plan each world's oracle tour for Table I's L98 / oracle
  bool figures = true;   ///< draw the figures (PNG, SVG and PDF, and on the page)
  unsigned threads = 0;  ///< oracle tours planned at a time; 0: one per core
};

/// What a report wrote and what it wants to tell.
struct ReportOutput {
  std::vector<std::filesystem::path> files;  ///< every file written, tables first
  std::vector<std::string> notes;            ///< worlds without oracle, figures left out
  std::size_t episodes = 0;                  ///< episodes read, of every setting
  std::size_t duplicates = 0;  ///< records dropped because their key and setting came earlier
  std::size_t truncated = 0;   ///< results files that ended in a truncated line
};

/// Writes table1.md, table1.csv, table2.md, table3.md and, when the report has other settings,
/// table4_slam.md into `directory` (created if needed), each atomically; returns their paths.
/// Throws InputError when it cannot write.
std::vector<std::filesystem::path> writeReport(const Report& report,
                                               const std::filesystem::path& directory);

/// Loads the results of `inputs` (loadResults), plans the oracle tours, and writes into `out`
/// (created if needed): table1.md, table1.csv, table2.md, table3.md, table4_slam.md (when
/// there is a Table IV), figures/*.png, *.svg and *.pdf, and report.html. Throws as
/// loadResults for bad inputs and InputError when a file cannot be written.
ReportOutput runReport(const std::vector<std::filesystem::path>& inputs,
                       const std::filesystem::path& out, const ReportSettings& settings = {});

}  // namespace roomscout::experiment
