#include "roomscout/io/yaml_support.hpp"

#include <charconv>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout::io {

YAML::Node parseYaml(std::string_view text, const std::string& source) {
  try {
    return YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    if (e.mark.is_null()) throw InputError(source, "invalid YAML: " + e.msg);
    throw InputError(source, "line " + std::to_string(e.mark.line + 1) + ": invalid YAML: " +
                                 e.msg + " (column " + std::to_string(e.mark.column + 1) + ")");
  }
}

std::string describeYamlNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "'" + node.Scalar() + "'";
}

std::optional<double> yamlDouble(const YAML::Node& node, bool finite_only) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value)) return std::nullopt;
  if (finite_only && !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> yamlInt(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  int value = 0;
  if (!YAML::convert<int>::decode(node, value)) return std::nullopt;
  return value;
}

std::optional<bool> yamlBool(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return std::nullopt;
  bool value = false;
  if (!YAML::convert<bool>::decode(node, value)) return std::nullopt;
  return value;
}

}  // namespace roomscout::io
