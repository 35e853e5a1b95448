#pragma once
// The largest grid roomscout builds, checked before anything of that size is allocated, so
// that a too large map is refused up front with a clear error instead of exhausting memory.

#include <cstdint>
#include <string>

namespace roomscout {

/// The most cells of any one grid: a map_server image, a world's ground-truth raster, the
/// explored map. 5000 x 5000 cells, 62 500 m^2 at 0.05 m: `explore` peaks at about 2.3 GB
/// and `maps` at about 1.7 GB there (memory grows with the cell count; docs/cli.md).
constexpr std::int64_t kMaxGridCells = 25'000'000;

/// Throws InputError(source, ...) when a grid of `width` x `height` cells of `resolution_m`
/// is larger than kMaxGridCells; `what` names the grid ("map", "world raster", ...) and
/// `setting` (may be empty) the option or key its resolution comes from. Takes doubles so
/// that sizes computed from absurd resolutions are checked before they overflow an int. E.g.
/// "big.yaml: map is 10000 x 10000 cells (100000000) at 0.05 m; roomscout handles at most
/// 25000000 cells (about 62500 m^2 at this resolution)".
void checkGridSize(const std::string& source, const std::string& what, double width, double height,
                   double resolution_m, const std::string& setting = {});

}  // namespace roomscout
