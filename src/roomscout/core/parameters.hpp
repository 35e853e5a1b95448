#pragma once
// A tiny reflection of options structs: each struct lists its fields by name so that the IO
// layer can fill them from YAML (rejecting unknown keys) and write them to JSON, without the
// core knowing either format.

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace roomscout {

/// One named, documented field of an options struct, pointing at its storage.
struct ParameterRef {
  std::string_view name;
  std::variant<double*, int*, bool*, std::string*> value;
  std::string_view doc;
};

/// A named group of parameters (e.g. "laser", "robot"), as they appear in a config file.
struct ParameterGroup {
  std::string name;
  std::vector<ParameterRef> parameters;
};

/// An option's former name, accepted for one release with a warning: "group.name" each. An
/// empty new_name: the old option is no longer read, and is ignored with the warning `note`.
struct RenamedOption {
  std::string old_name;
  std::string new_name;
  std::string note;
};

}  // namespace roomscout
