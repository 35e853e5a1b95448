#pragma once
// The report's tables as cells, and the text that explains them: what the Markdown files
// (report_markdown.hpp) and the HTML page (report_html.hpp) both show.

#include <optional>
#include <string>

#include "roomscout/experiment/report.hpp"
#include "roomscout/plots/html_report.hpp"

namespace roomscout::experiment {

/// The report's tables as cells, shared by the markdown files and the HTML page: Table I
/// (method rows, per world T98, paper T, L98, paper L (T98 and L98 over the row's paired
/// episodes, "no shared pair" when there are none), L98 and T98 over the reference's, L98 /
/// oracle when known, the share of pairs that beat semantic when semantic is there, success),
/// the revisits, the oracle reference (rows with an oracle; none when there is none),
/// Table II and Table III, and Table IV (none when every episode is of the main setting).
plots::HtmlTable table1Cells(const Report& report);
plots::HtmlTable revisitsCells(const Report& report);
std::optional<plots::HtmlTable> oracleCells(const Report& report);
plots::HtmlTable table2Cells(const Report& report);
plots::HtmlTable table3Cells(const Report& report);
/// Table IV: a line per row x method with episodes in another setting; World, Method, then the
/// main setting's T98, L98 and success, then per other setting (in order of first appearance)
/// its T98, L98, success (with the diverged runs counted when there are any), ATE and L98
/// ratio (its mean L98 over the main setting's).
std::optional<plots::HtmlTable> slamCells(const Report& report);

/// The text that explains each table (also on the HTML page).
std::string table1Description();
/// Which episodes Table I's means are over in this report: per row the paired (world, seed)
/// pairs out of all, the reference method of the ratios, what "beats semantic" counts.
std::string pairingLine(const Report& report);
std::string revisitsDescription();
std::string oracleDescription();
std::string table2Description();
std::string table3Description();
std::string slamDescription();
/// "N episodes from `file`, ...", and how many episodes of other settings Table IV holds.
std::string sourcesLine(const Report& report);
/// Names the methods of methodsSameEverySeed() and why their sd is 0; empty when none.
std::string sameEverySeedLine(const Report& report);
/// The sentence saying that (some) episodes started at poses drawn from their seed, or empty.
std::string startPosesLine(const Report& report);

}  // namespace roomscout::experiment
