#pragma once
// Reader of geometric world files (docs/world_format.md): walls with door openings cut out,
// furniture (tables expanded into a top and legs), labelled rooms and a start pose.

#include <filesystem>
#include <string>
#include <string_view>

#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// Thickness of a `kind: table` top [m].
inline constexpr double kTableTopThickness_m = 0.04;
/// Side of a table leg's square footprint [m].
inline constexpr double kTableLegSide_m = 0.05;
/// Distance from each box edge to the outer faces of a corner leg [m].
inline constexpr double kTableLegInset_m = 0.05;

/// Parses a world from YAML text. `source` names the input in errors ("builtin:NAME" or a
/// path). Throws InputError(source, problem) for malformed YAML (with the line), unknown or
/// missing keys, wrong types, non-finite numbers, non-positive sizes, short polygons and doors
/// touching no wall; problems name their place, e.g. "furniture[3]: unknown key 'hight_m'
/// (known: ...)" (list indices are 0-based). The start pose is not checked against the
/// world's bounds here (the simulator does that).
sim::World parseWorldYaml(std::string_view yaml_text, const std::string& source);

/// Reads and parses a world file; errors name the file's path.
sim::World loadWorldFile(const std::filesystem::path& path);

}  // namespace roomscout::sim
