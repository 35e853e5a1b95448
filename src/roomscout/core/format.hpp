#pragma once
// Text formatting of numbers in one place: printf-style into a std::string, and the shortest
// decimal form of a double.

#include <string>

#include "roomscout/core/geometry.hpp"

namespace roomscout {

/// printf-style formatting into a string of any length ("%.2f", "%5.1f %s", ...).
[[gnu::format(printf, 1, 2)]] std::string formatString(const char* format, ...);

/// The shortest decimal text that reads back as `value` ("0.1", "1e+20"; std::to_chars).
std::string formatDouble(double value);

/// "(x, y)" with formatDouble, as error messages name a point.
std::string formatPoint(const Vec2& p);

}  // namespace roomscout
