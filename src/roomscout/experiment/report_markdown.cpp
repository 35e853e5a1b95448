#include "roomscout/experiment/report_markdown.hpp"

#include <algorithm>
#include <optional>

#include "roomscout/experiment/report_tables.hpp"
#include "roomscout/experiment/result_record.hpp"

namespace roomscout::experiment {
namespace {

/// "# title\n\ndescription\n\nsources.\n\n" + the table in markdown.
std::string markdownSection(const std::string& heading, const std::string& description,
                            const std::string& sources, const plots::HtmlTable& table) {
  std::string md = heading + "\n\n" + description + "\n\n";
  if (!sources.empty()) md += sources + ".\n\n";
  return md + plots::markdownTable(table);
}

}  // namespace

std::string table1Markdown(const Report& report) {
  const std::string same = sameEverySeedLine(report);
  const std::string starts = startPosesLine(report);
  const std::string pairing = pairingLine(report);
  const std::string intro =
      "# Table I: exploration time and trajectory length\n\n" + table1Description() + "\n\n" +
      (pairing.empty() ? "" : pairing + "\n\n") + (same.empty() ? "" : same + "\n\n") +
      (starts.empty() ? "" : starts + "\n\n") + sourcesLine(report) + ".\n\n";
  if (report.rows.empty()) return intro + "No episodes.\n";
  plots::HtmlTable table = table1Cells(report);
  table.caption.clear();
  plots::HtmlTable revisits = revisitsCells(report);
  revisits.caption.clear();
  std::string md = intro + plots::markdownTable(table) + "\n" +
                   markdownSection("## Revisits", revisitsDescription(), "", revisits);
  if (std::optional<plots::HtmlTable> oracle = oracleCells(report)) {
    oracle->caption.clear();
    md += "\n";
    md += markdownSection("## Oracle reference", oracleDescription(), "", *oracle);
  }
  return md;
}

std::string table2Markdown(const Report& report) {
  plots::HtmlTable table = table2Cells(report);
  table.caption.clear();
  return markdownSection("# Table II: map types built", table2Description(), sourcesLine(report),
                         table);
}

std::string table3Markdown(const Report& report) {
  const std::string intro = "# Table III: storage and update time of each map\n\n" +
                            table3Description() + "\n\n" + sourcesLine(report) + ".\n\n";
  if (report.rows.empty()) return intro + "No episodes.\n";
  plots::HtmlTable table = table3Cells(report);
  table.caption.clear();
  std::string md = intro + plots::markdownTable(table) + "\nEpisodes per world:";
  const std::vector<std::string>& types = mapTypes();
  for (const ReportRow& row : report.rows) {
    std::size_t n = 0;
    for (const std::string& t : types) {
      const auto it = report.table3.find({row.name, t});
      if (it != report.table3.end()) n = std::max(n, it->second.episodes);
    }
    md += " ";
    md += rowTitle(row) + " " + std::to_string(n) + (&row == &report.rows.back() ? "." : ";");
  }
  return md + "\n";
}

std::string slamMarkdown(const Report& report) {
  std::optional<plots::HtmlTable> table = slamCells(report);
  if (!table) return {};
  table->caption.clear();
  return markdownSection("# Table IV: exploration under noise and SLAM", slamDescription(),
                         sourcesLine(report), *table);
}

}  // namespace roomscout::experiment
