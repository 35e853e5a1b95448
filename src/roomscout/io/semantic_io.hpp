#pragma once
// Files of the semantic map (rooms): semantic.json, semantic.png (rooms coloured over the
// map) and semantic_labels.png (16-bit room ids, same size and frame as occupancy.pgm).

#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/semantic_map.hpp"

namespace roomscout::io {

/// {frame, resolution, origin, width, height, regions: [{id, colour "#rrggbb", label,
/// area_m2, centroid [x, y], polygon [[x, y], ...], open, neighbours}]}; metres, map frame.
nlohmann::json semanticJson(const SemanticMap& map);

/// Room ids as a 16-bit greyscale image, row 0 at the top (as occupancy.pgm), 0 = no room.
/// Ids above 65535 are clamped (never reached in practice).
cv::Mat semanticLabelImage(const SemanticMap& map);

/// `labels` (CV_32S, any orientation) coloured by SemanticMap::colourOf over a greyscale
/// background of the same size (CV_8U); unlabelled cells show the background.
cv::Mat colourLabels(const cv::Mat& labels, const cv::Mat& background_grey);

/// The rooms coloured over the occupancy grid, ids written at the centroids, open rooms
/// outlined; row 0 at the top, scaled up so small maps stay legible.
cv::Mat renderSemantic(const SemanticMap& map, const OccupancyGrid& grid);

/// Writes semantic.json, semantic.png and semantic_labels.png into `directory`, atomically.
/// `extra` members (e.g. a ground-truth score) are merged into semantic.json's top level.
void writeSemanticMap(const std::filesystem::path& directory, const SemanticMap& map,
                      const OccupancyGrid& grid,
                      const nlohmann::json& extra = nlohmann::json::object());

/// Occupancy grid as a greyscale image, row 0 at the top: free 254, occupied 0, unknown 205.
cv::Mat occupancyImage(const OccupancyGrid& grid);

}  // namespace roomscout::io
