#pragma once
// Options from YAML and to JSON through the core's ParameterRef reflection: unknown keys and
// ill-typed values are rejected with messages naming the option and the bad value.

#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include "roomscout/core/parameters.hpp"

namespace roomscout::io {

/// Sets parameters from a YAML map {name: value}. `context` prefixes messages (e.g. "laser").
/// An empty node (null) sets nothing. Throws OptionError when the node is not a map
/// ("<context>: expected a map of options ..."), a key is unknown ("<context>: unknown option
/// 'foo' (known: a, b, c)"), given twice, or its value does not convert to the parameter's
/// type ("<context>.num_beams: expected an integer, got 'abc'"). Doubles must be finite.
/// Nothing is changed unless every value is valid.
void applyParameters(const YAML::Node& node, std::vector<ParameterRef> params,
                     const std::string& context);

/// The parameters' current values as a JSON object {name: value}.
nlohmann::json parametersToJson(const std::vector<ParameterRef>& params);

/// The parameter's current value as a YAML scalar that applyParameters reads back as the same
/// value: "0.05", "360", "true", and a string plain when YAML reads it as that string
/// ("fixed"), double-quoted otherwise ("\"\"", "\"true\"").
std::string parameterValueYaml(const ParameterRef& param);

/// Applies a config file whose top-level keys are group names, each holding a map of that
/// group's options. YAML syntax errors throw InputError(path, "line N: ..."); a top level that
/// is not a map throws InputError; an unknown group throws OptionError listing the groups;
/// option errors are prefixed with the path ("cfg.yaml: laser.num_beams: ...").
/// An empty file changes nothing. An option under a name of `renamed` is read under its new
/// name (or, with none, ignored); given under both names it throws OptionError. Returns one
/// warning per renamed option the file uses, naming the file, the old and the new name.
std::vector<std::string> applyConfigFile(const std::filesystem::path& path,
                                         std::vector<ParameterGroup>& groups,
                                         const std::vector<RenamedOption>& renamed = {});

}  // namespace roomscout::io
