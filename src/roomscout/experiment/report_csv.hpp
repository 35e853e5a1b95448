#pragma once
// Table I as CSV (table1.csv): a line per row x method with every number of MethodStats, the
// paper's, the oracle's and the row's pairing, for analysis elsewhere.

#include <string>

#include "roomscout/experiment/report.hpp"

namespace roomscout::experiment {

std::string table1Csv(const Report& report);

}  // namespace roomscout::experiment
