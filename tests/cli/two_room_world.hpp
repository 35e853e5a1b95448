#pragma once
// A tiny world shared by the tests that run whole benches on it.

#include <filesystem>
#include <fstream>

namespace roomscout::test {

/// Writes `folder`/rooms.yaml, a world file: a 6 x 4 m house split by a wall with a 1 m door
/// into two labelled rooms, so that benches on it count revisits (explored in ~10 s of
/// simulated time). `folder` must exist. Returns the file's path.
inline std::filesystem::path writeTwoRoomWorld(const std::filesystem::path& folder) {
  std::ofstream(folder / "rooms.yaml") << R"(name: rooms
wall_thickness_m: 0.1
wall_height_m: 2.5
start: [1.5, 2.0, 0]
walls:
  - [[-0.05, 0], [6.05, 0]]
  - [[6, 0], [6, 4]]
  - [[6.05, 4], [-0.05, 4]]
  - [[0, 4], [0, 0]]
  - [[3, 0], [3, 1.5]]
  - [[3, 2.5], [3, 4]]
rooms:
  - name: west
    polygon: [[0, 0], [3, 0], [3, 4], [0, 4]]
  - name: east
    polygon: [[3, 0], [6, 0], [6, 4], [3, 4]]
)";
  return folder / "rooms.yaml";
}

}  // namespace roomscout::test
