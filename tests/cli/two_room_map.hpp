#pragma once
// A tiny map_server world shared by the CLI tests that run whole benches on it.

#include <filesystem>
#include <fstream>
#include <string>

namespace roomscout::test {

/// Writes `folder`/rooms.pgm and rooms.yaml: a 6 x 4 m room split by a wall with a 1 m door
/// (explored in ~10 s of simulated time). `folder` must exist.
inline void writeTwoRoomMap(const std::filesystem::path& folder) {
  const int w = 120, h = 80;
  std::string pixels(static_cast<std::size_t>(w * h), static_cast<char>(254));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool wall = y < 2 || y >= h - 2 || x < 2 || x >= w - 2 ||
                        (x >= 60 && x < 62 && !(y >= 30 && y < 50));
      if (wall) pixels[static_cast<std::size_t>(y * w + x)] = 0;
    }
  }
  std::ofstream(folder / "rooms.pgm", std::ios::binary) << "P5\n" << w << " " << h << "\n255\n" << pixels;
  std::ofstream(folder / "rooms.yaml") << "image: rooms.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"
                                          "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
}

}  // namespace roomscout::test
