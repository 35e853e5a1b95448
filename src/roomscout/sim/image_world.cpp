#include "roomscout/sim/image_world.hpp"

#include <cstdint>
#include <string>
#include <utility>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/io/map_server.hpp"

namespace roomscout::sim {

World loadImageWorld(const std::filesystem::path& yaml_path,
                     const std::optional<std::filesystem::path>& room_labels_png) {
  const io::MapServerMetadata m = io::loadMapServerYaml(yaml_path);
  const cv::Mat image = io::readMapImage(yaml_path, m);
  const cv::Mat states = io::classifyMapImage(image, m);

  ImageWorld image_world;
  image_world.resolution_m = m.resolution_m;
  image_world.origin_m = m.origin_m;
  image_world.solid = cv::Mat(states.rows, states.cols, CV_8U);
  int free_pixels = 0;
  for (int row = 0; row < states.rows; ++row) {
    const std::uint8_t* state = states.ptr<std::uint8_t>(row);
    std::uint8_t* solid = image_world.solid.ptr<std::uint8_t>(row);
    for (int col = 0; col < states.cols; ++col) {
      const bool is_free = state[col] == static_cast<std::uint8_t>(CellState::kFree);
      solid[col] = is_free ? 0 : 255;
      free_pixels += is_free ? 1 : 0;
    }
  }
  if (free_pixels == 0) {
    throw InputError(m.image.string(), "no free pixel (nothing is below free_thresh " +
                                           formatDouble(m.free_thresh) +
                                           "; is the image inverted? see 'negate')");
  }

  World world;
  world.name = yaml_path.stem().string();
  world.source = yaml_path.string();
  world.description = "map_server map " + m.image.filename().string();
  world.start_given = false;
  if (room_labels_png) {
    io::RoomLabelImage labels = io::readRoomLabelImage(*room_labels_png, image.size());
    image_world.room_labels = std::move(labels.labels);
    for (int id : labels.ids) world.rooms.push_back({id, "room_" + std::to_string(id), {}});
  }
  world.image = std::move(image_world);
  return world;
}

}  // namespace roomscout::sim
