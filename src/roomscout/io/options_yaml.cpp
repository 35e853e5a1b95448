#include "roomscout/io/options_yaml.hpp"

#include <set>
#include <type_traits>
#include <utility>
#include <variant>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/yaml_support.hpp"

namespace roomscout::io {
namespace {

/// A converted value waiting to be stored, so that a bad value later in the map leaves every
/// parameter unchanged.
using PendingValue = std::variant<double, int, bool, std::string>;

PendingValue convert(const ParameterRef& param, const YAML::Node& value, const std::string& where) {
  const auto fail = [&](const std::string& expected) -> void {
    throw OptionError(where + ": expected " + expected + ", got " + describeYamlNode(value));
  };
  return std::visit(
      [&](auto* storage) -> PendingValue {
        using T = std::remove_pointer_t<decltype(storage)>;
        if constexpr (std::is_same_v<T, double>) {
          const std::optional<double> v = yamlDouble(value);
          if (!v) fail("a finite number");
          return *v;
        } else if constexpr (std::is_same_v<T, int>) {
          const std::optional<int> v = yamlInt(value);
          if (!v) fail("an integer");
          return *v;
        } else if constexpr (std::is_same_v<T, bool>) {
          const std::optional<bool> v = yamlBool(value);
          if (!v) fail("true or false");
          return *v;
        } else {
          if (!value.IsScalar()) fail("a string");
          return value.Scalar();
        }
      },
      param.value);
}

/// "group.name" split at its first dot; a name without a dot is a whole group.
std::pair<std::string, std::string> splitOptionName(const std::string& name) {
  const std::size_t dot = name.find('.');
  if (dot == std::string::npos) return {name, ""};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

/// A copy of `root` with every option of `renamed` moved to its new name or dropped, and
/// groups left empty by that dropped.
YAML::Node moveRenamedOptions(const YAML::Node& root, const std::vector<RenamedOption>& renamed,
                              const std::string& source, std::vector<std::string>& warnings) {
  YAML::Node out = YAML::Clone(root);
  for (const RenamedOption& r : renamed) {
    const auto [group, key] = splitOptionName(r.old_name);
    const YAML::Node& lookup_old = out;
    if (!lookup_old[group].IsDefined()) continue;
    if (!key.empty() && !(lookup_old[group].IsMap() && lookup_old[group][key].IsDefined()))
      continue;
    YAML::Node old_group = out[group];
    std::string warning = source + ": " + r.old_name;
    if (r.new_name.empty()) {
      warning += " is ignored: " + r.note;
    } else {
      const auto [new_group, new_key] = splitOptionName(r.new_name);
      const YAML::Node& lookup = out;
      if (lookup[new_group].IsDefined() && lookup[new_group].IsMap() &&
          lookup[new_group][new_key].IsDefined()) {
        throw OptionError(source + ": " + r.old_name + " and " + r.new_name +
                          " are the same option: give only " + r.new_name);
      }
      out[new_group][new_key] = YAML::Clone(old_group[key]);
      warning += " is now " + r.new_name + "; the old name will be removed in the next release";
    }
    if (key.empty()) {
      out.remove(group);
    } else {
      old_group.remove(key);
      if (old_group.size() == 0) out.remove(group);
    }
    warnings.push_back(warning);
  }
  return out;
}

}  // namespace

void applyParameters(const YAML::Node& node, std::vector<ParameterRef> params,
                     const std::string& context) {
  const std::string prefix = context.empty() ? "" : context + ": ";
  const auto place = [&](const std::string& key) {
    return context.empty() ? key : context + "." + key;
  };
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap()) {
    throw OptionError(prefix + "expected a map of options, got " + describeYamlNode(node));
  }
  std::vector<std::string_view> known;
  for (const ParameterRef& p : params) known.push_back(p.name);

  std::vector<std::pair<const ParameterRef*, PendingValue>> pending;
  std::set<std::string> seen;
  for (const auto& entry : node) {
    if (!entry.first.IsScalar()) {
      throw OptionError(prefix + "option names must be plain names, got " +
                        describeYamlNode(entry.first));
    }
    const std::string key = entry.first.Scalar();
    const ParameterRef* param = nullptr;
    for (const ParameterRef& p : params) {
      if (p.name == key) param = &p;
    }
    if (param == nullptr) {
      throw OptionError(prefix + "unknown option '" + key + "' (known: " + joinNames(known) + ")");
    }
    if (!seen.insert(key).second) throw OptionError(place(key) + ": given twice");
    pending.emplace_back(param, convert(*param, entry.second, place(key)));
  }
  // A pair, not a structured binding: clang 14 (the fuzz and sanitizer build) cannot capture
  // structured bindings in a lambda.
  for (const auto& entry : pending) {
    std::visit(
        [&](auto* storage) {
          using T = std::remove_pointer_t<decltype(storage)>;
          *storage = std::get<T>(entry.second);
        },
        entry.first->value);
  }
}

nlohmann::json parametersToJson(const std::vector<ParameterRef>& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const ParameterRef& p : params) {
    std::visit([&](auto* storage) { out[std::string(p.name)] = *storage; }, p.value);
  }
  return out;
}

std::string parameterValueYaml(const ParameterRef& param) {
  return std::visit(
      [](auto* storage) -> std::string {
        using T = std::remove_pointer_t<decltype(storage)>;
        if constexpr (std::is_same_v<T, double>) {
          return formatDouble(*storage);
        } else if constexpr (std::is_same_v<T, int>) {
          return std::to_string(*storage);
        } else if constexpr (std::is_same_v<T, bool>) {
          return *storage ? "true" : "false";
        } else {
          const std::string& text = *storage;
          // Plain only when YAML cannot read it as anything but this string.
          bool plain = !text.empty() && !yamlBool(YAML::Node(text)).has_value() &&
                       !yamlDouble(YAML::Node(text), false).has_value() && text != "null" &&
                       text != "Null" && text != "NULL" && text != "~";
          for (const char c : text) {
            const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                              (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.' ||
                              c == '/';
            if (!word) plain = false;
          }
          if (!text.empty() && (text.front() == '-' || text.front() == '.')) plain = false;
          if (plain) return text;
          std::string quoted = "\"";
          for (const char c : text) {
            if (c == '"' || c == '\\') {
              quoted += '\\';
              quoted += c;
            } else if (c == '\n') {
              quoted += "\\n";
            } else if (c == '\t') {
              quoted += "\\t";
            } else {
              quoted += c;
            }
          }
          return quoted + "\"";
        }
      },
      param.value);
}

std::vector<std::string> applyConfigFile(const std::filesystem::path& path,
                                         std::vector<ParameterGroup>& groups,
                                         const std::vector<RenamedOption>& renamed) {
  const std::string source = path.string();
  YAML::Node root = parseYaml(readFile(path), source);
  std::vector<std::string> warnings;
  if (!root.IsDefined() || root.IsNull()) return warnings;
  std::vector<std::string> names;
  for (const ParameterGroup& g : groups) names.push_back(g.name);
  if (!root.IsMap()) {
    throw InputError(source, "expected a map of option groups (" + joinNames(names) + "), got " +
                                 describeYamlNode(root));
  }
  root = moveRenamedOptions(root, renamed, source, warnings);
  std::set<std::string> seen;
  for (const auto& entry : root) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    ParameterGroup* group = nullptr;
    for (ParameterGroup& g : groups) {
      if (g.name == key) group = &g;
    }
    if (group == nullptr) {
      throw OptionError(source + ": unknown group '" + key + "' (known: " + joinNames(names) + ")");
    }
    if (!seen.insert(key).second) throw OptionError(source + ": group '" + key + "' given twice");
    applyParameters(entry.second, group->parameters, source + ": " + group->name);
  }
  return warnings;
}

}  // namespace roomscout::io
