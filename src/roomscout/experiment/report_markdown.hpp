#pragma once
// The report's tables as Markdown files: table1.md (Table I with the revisits and the oracle
// reference), table2.md, table3.md and table4_slam.md, each with its description and sources.

#include <string>

#include "roomscout/experiment/report.hpp"

namespace roomscout::experiment {

std::string table1Markdown(const Report& report);
std::string table2Markdown(const Report& report);
std::string table3Markdown(const Report& report);
/// Table IV's heading, description, sources and table; empty when there is no Table IV.
std::string slamMarkdown(const Report& report);

}  // namespace roomscout::experiment
