#pragma once
// The figures of `roomscout report`, drawn from the merged results and the full outputs that
// a bench keeps for seed 1 (DIR/runs/<world>/<method>/seed1/):
//  - Fig. 5: exploration rate against trajectory length, one line per method;
//  - Fig. 6: one panel per method, its trajectory over its final map with the rooms coloured;
//  - Fig. 7: the four maps of one run side by side (occupancy, point cloud, topological,
//    semantic);
//  - room revisits per method and world (bar chart).
// Rows with one world (built-in worlds, and a folder holding one world file) get all of them;
// a group of worlds (e.g. 50 HouseExpo plans) gets a mean-curve Fig. 5 and its bars only.

#include <filesystem>
#include <string>
#include <vector>

#include "roomscout/experiment/report.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::experiment {

/// One report figure and where it goes.
struct ReportFigure {
  std::string stem;     ///< file name without extension, e.g. "fig5_rate_small_house"
  std::string kind;     ///< "rate", "trajectories", "maps" or "revisits"
  std::string row;      ///< the report row it shows (empty for figures over all rows)
  std::string caption;  ///< what it shows, for the HTML page
  plots::Figure figure;
};

struct ReportFigures {
  std::vector<ReportFigure> figures;  ///< per row in report order (rate, trajectories, maps),
                                      ///< then the revisits
  std::vector<std::string> notes;     ///< figures left out or incomplete, and why
};

/// Draws every figure `results` and the run outputs on disk allow. Fig. 5 of a world shows,
/// per method, the episode of median L98 (the lower median; episodes that never reached 98 %
/// rank last, ties by seed), with its seed in the legend; a group's Fig. 5 shows, per method,
/// the mean rate of all its episodes against length divided by each world's oracle tour
/// length (in metres when some world has no oracle). Fig. 6 uses, per method, the lowest-seed
/// episode whose outputs folder exists, its record's trajectory over occupancy.pgm with the
/// rooms of its semantic_labels.png; Fig. 7 the run of method "semantic" if there is one,
/// else of the first method in report order. Missing files leave a figure or panel out, with
/// a note. Methods have the same colour in every figure.
ReportFigures renderReportFigures(const ResultSet& results, const Report& report);

/// Writes each figure as `directory`/stem.png, .svg and .pdf (directory created if needed);
/// returns the paths. Throws InputError when a file cannot be written.
std::vector<std::filesystem::path> writeReportFigures(const std::vector<ReportFigure>& figures,
                                                      const std::filesystem::path& directory);

}  // namespace roomscout::experiment
