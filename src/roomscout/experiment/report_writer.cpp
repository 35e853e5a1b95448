#include "roomscout/experiment/report_writer.hpp"

#include <utility>

#include "roomscout/experiment/oracle_references.hpp"
#include "roomscout/experiment/report_csv.hpp"
#include "roomscout/experiment/report_figures.hpp"
#include "roomscout/experiment/report_html.hpp"
#include "roomscout/experiment/report_markdown.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/html_report.hpp"

namespace roomscout::experiment {
namespace fs = std::filesystem;

std::vector<fs::path> writeReport(const Report& report, const fs::path& directory) {
  io::ensureWritableDirectory(directory);
  std::vector<std::pair<std::string, std::string>> files = {
      {"table1.md", table1Markdown(report)},
      {"table1.csv", table1Csv(report)},
      {"table2.md", table2Markdown(report)},
      {"table3.md", table3Markdown(report)},
  };
  if (report.hasTable4()) files.emplace_back("table4_slam.md", slamMarkdown(report));
  std::vector<fs::path> written;
  for (const auto& [name, text] : files) {
    io::writeFileAtomic(directory / name, text);
    written.push_back(directory / name);
  }
  return written;
}

ReportOutput runReport(const std::vector<fs::path>& inputs, const fs::path& out,
                       const ReportSettings& settings) {
  ResultSet results = loadResults(inputs);
  // Temporary files of a report (or bench) killed while writing; the report rewrites all.
  io::removeStaleTempFiles(out);
  io::removeStaleTempFiles(out / "figures");
  ReportOutput output;
  output.episodes = results.episodes.size();
  output.duplicates = results.duplicates;
  output.truncated = results.truncated;
  if (settings.oracle) {
    OracleSummary oracle = attachOracleTours(results, {settings.threads});
    output.notes = std::move(oracle.notes);
  }
  const Report report = buildReport(results);
  output.files = writeReport(report, out);
  ReportFigures figures;
  if (settings.figures) {
    // The figures show what Tables I-III do: the main setting's episodes.
    figures = renderReportFigures(
        report.hasTable4() ? episodesOfSetting(results, report.main_setting) : results, report);
    for (std::string& n : figures.notes) output.notes.push_back(std::move(n));
    for (fs::path& f : writeReportFigures(figures.figures, out / "figures"))
      output.files.push_back(std::move(f));
  }
  plots::writeHtml(reportPage(report, figures.figures, output.notes), out / "report.html");
  output.files.push_back(out / "report.html");
  return output;
}

}  // namespace roomscout::experiment
