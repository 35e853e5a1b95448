#pragma once
// The full-knowledge reference tour (sim/oracle_tour.hpp) of every world in a report's
// results, planned once per world and option set, for Table I's L98 / oracle ratio.

#include <cstddef>
#include <string>
#include <vector>

#include "roomscout/experiment/report_records.hpp"

namespace roomscout::experiment {

struct OracleSettings {
  /// Worlds planned at a time (one thread each); 0: one per core.
  unsigned threads = 0;
};

/// What attachOracleTours() did.
struct OracleSummary {
  std::size_t planned = 0;         ///< distinct (world, options) tours planned
  std::vector<std::string> notes;  ///< one per world that could not be loaded or planned
};

/// Sets `oracle` of every episode whose world can be loaded again: its EpisodeSummary::
/// world_spec through sim::loadWorld (a relative path as seen from the current directory),
/// modelled and planned with the episode's own options (world_setup; defaults where the
/// record has none, options the build does not know are ignored) and
/// experiment::oracleTourOptionsFor. Each distinct (world_spec, world_setup) is planned once;
/// several are planned in parallel. Deterministic. A world that does not load or plan leaves
/// its episodes without an oracle and adds a note; nothing throws for a bad world.
OracleSummary attachOracleTours(ResultSet& results, const OracleSettings& settings = {});

}  // namespace roomscout::experiment
