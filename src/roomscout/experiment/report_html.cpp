#include "roomscout/experiment/report_html.hpp"

#include <optional>

#include "roomscout/experiment/report_tables.hpp"

namespace roomscout::experiment {
namespace {

/// Markdown emphasis and code marks taken out, for the HTML page.
std::string plain(std::string text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '`' || text[i] == '*') continue;
    out += text[i];
  }
  return out;
}

plots::HtmlTable plainTable(plots::HtmlTable table) {
  for (std::string& h : table.header) h = plain(h);
  for (auto& row : table.rows) {
    for (std::string& cell : row) cell = plain(cell);
  }
  return table;
}

}  // namespace

plots::HtmlPage reportPage(const Report& report, const std::vector<ReportFigure>& figures,
                           const std::vector<std::string>& notes) {
  plots::HtmlPage page;
  page.title = "roomscout report";
  page.intro.push_back({plain(sourcesLine(report)) + "."});
  for (const std::string& n : notes) page.intro.push_back({"Note: " + n});

  plots::HtmlSection t1{"Table I: exploration time and trajectory length", {}};
  t1.blocks.push_back(plots::HtmlParagraph{plain(table1Description())});
  if (const std::string pairing = pairingLine(report); !pairing.empty()) {
    t1.blocks.push_back(plots::HtmlParagraph{plain(pairing)});
  }
  if (const std::string same = sameEverySeedLine(report); !same.empty()) {
    t1.blocks.push_back(plots::HtmlParagraph{plain(same)});
  }
  if (const std::string starts = startPosesLine(report); !starts.empty()) {
    t1.blocks.push_back(plots::HtmlParagraph{plain(starts)});
  }
  t1.blocks.push_back(plainTable(table1Cells(report)));
  t1.blocks.push_back(plots::HtmlParagraph{plain(revisitsDescription())});
  t1.blocks.push_back(plainTable(revisitsCells(report)));
  if (std::optional<plots::HtmlTable> oracle = oracleCells(report)) {
    t1.blocks.push_back(plots::HtmlParagraph{plain(oracleDescription())});
    t1.blocks.push_back(plainTable(*oracle));
  }
  plots::HtmlSection t2{"Table II: map types built", {}};
  t2.blocks.push_back(plots::HtmlParagraph{plain(table2Description())});
  t2.blocks.push_back(plainTable(table2Cells(report)));
  plots::HtmlSection t3{"Table III: storage and update time of each map", {}};
  t3.blocks.push_back(plots::HtmlParagraph{plain(table3Description())});
  t3.blocks.push_back(plainTable(table3Cells(report)));
  page.sections = {t1, t2, t3};
  if (std::optional<plots::HtmlTable> slam = slamCells(report)) {
    plots::HtmlSection t4{"Table IV: exploration under noise and SLAM", {}};
    t4.blocks.push_back(plots::HtmlParagraph{plain(slamDescription())});
    t4.blocks.push_back(plainTable(*slam));
    page.sections.push_back(std::move(t4));
  }

  struct Kind {
    const char* kind;
    const char* title;
  };
  static constexpr Kind kKinds[] = {
      {"rate", "Fig. 5: exploration rate against trajectory length"},
      {"trajectories", "Fig. 6: trajectories of the methods"},
      {"maps", "Fig. 7: the four maps of one run"},
      {"revisits", "Room revisits"},
  };
  for (const Kind& k : kKinds) {
    plots::HtmlSection section{k.title, {}};
    for (const ReportFigure& f : figures) {
      if (f.kind == k.kind) section.blocks.push_back(plots::htmlFigure(f.figure, f.caption));
    }
    if (!section.blocks.empty()) page.sections.push_back(std::move(section));
  }
  return page;
}

}  // namespace roomscout::experiment
