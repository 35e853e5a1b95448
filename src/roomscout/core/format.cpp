#include "roomscout/core/format.hpp"

#include <charconv>
#include <cstdarg>
#include <cstdio>

namespace roomscout {

std::string formatString(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, args);
  va_end(args);
  return out;
}

std::string formatDouble(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string formatPoint(const Vec2& p) {
  std::string out = "(";
  out.append(formatDouble(p.x())).append(", ").append(formatDouble(p.y())).append(")");
  return out;
}

}  // namespace roomscout
