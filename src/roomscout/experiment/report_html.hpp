#pragma once
// The report as one self-contained HTML page (report.html): the tables of report_tables.hpp,
// their descriptions, and the figures of report_figures.hpp.

#include <string>
#include <vector>

#include "roomscout/experiment/report.hpp"
#include "roomscout/experiment/report_figures.hpp"
#include "roomscout/plots/html_report.hpp"

namespace roomscout::experiment {

/// The HTML page of a report: Tables I (with revisits and oracle reference), II, III and, when
/// the results hold other settings than the main one, IV, then the figures by kind (Fig. 5, 6,
/// 7, revisits; of the main setting); `notes` under the title.
plots::HtmlPage reportPage(const Report& report, const std::vector<ReportFigure>& figures,
                           const std::vector<std::string>& notes = {});

}  // namespace roomscout::experiment
