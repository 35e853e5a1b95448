#pragma once
// Small helpers shared by the YAML readers of the IO layer: parsing with line numbers,
// describing a node in an error message and strict scalar conversions.

#include <optional>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace roomscout::io {

/// Parses YAML text; a syntax error becomes
/// InputError(source, "line N: invalid YAML: <problem> (column M)"), N and M 1-based.
YAML::Node parseYaml(std::string_view text, const std::string& source);

/// How a node looks in an error message: 'text' for a scalar, "a list", "a map", "nothing".
std::string describeYamlNode(const YAML::Node& node);

/// Joins names as "a, b, c" ("none" when empty), for "(known: ...)" lists.
std::string joinNames(const auto& names) {
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out.empty() ? "none" : out;
}

/// Strict conversions of a scalar node; nullopt when the node is not a scalar of that type.
/// yamlDouble also rejects non-finite values (.inf, .nan) when `finite_only`.
std::optional<double> yamlDouble(const YAML::Node& node, bool finite_only = true);
std::optional<int> yamlInt(const YAML::Node& node);
std::optional<bool> yamlBool(const YAML::Node& node);

}  // namespace roomscout::io
