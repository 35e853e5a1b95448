#include "roomscout/core/grid_limits.hpp"

#include <cmath>
#include <cstdio>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"

namespace roomscout {
namespace {

/// An integer-valued count as digits ("100000000"), a huge one in exponent notation.
std::string count(double n) { return formatString(n < 1e15 ? "%.0f" : "%.3g", n); }

/// An area in whole square metres, a small one to three significant digits.
std::string area(double m2) { return formatString(m2 >= 1000.0 ? "%.0f" : "%.3g", m2); }

std::string metres(double m) { return formatString("%g", m); }

}  // namespace

void checkGridSize(const std::string& source, const std::string& what, double width, double height,
                   double resolution_m, const std::string& setting) {
  const double cells = width * height;
  if (std::isfinite(cells) && cells <= static_cast<double>(kMaxGridCells)) return;
  const double area_m2 = static_cast<double>(kMaxGridCells) * resolution_m * resolution_m;
  std::string problem = what + " is " + count(width) + " x " + count(height) + " cells (" +
                        count(cells) + ") at " + metres(resolution_m) + " m";
  if (!setting.empty()) problem += " (" + setting + ")";
  problem += "; roomscout handles at most " + count(static_cast<double>(kMaxGridCells)) +
             " cells (about " + area(area_m2) + " m^2 at this resolution)";
  throw InputError(source, problem);
}

}  // namespace roomscout
