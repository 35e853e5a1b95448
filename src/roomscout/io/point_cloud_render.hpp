#pragma once
// Pictures of a point cloud map for people: a top view and an oblique view side by side,
// orthographic, z-buffered, coloured by height.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

namespace roomscout::io {

/// Renders `points_map` [m, map frame] as two panels of `panel_px` square pixels: looking
/// straight down (x right, y up) and from 35 degrees above the horizon at azimuth -60 degrees.
/// Points above clip_z_m are left out so the ceiling does not hide the rooms. Colour runs
/// from blue (lowest point drawn) to red (highest). An empty cloud gives blank panels.
cv::Mat renderPointCloud(const std::vector<Eigen::Vector3f>& points_map, double clip_z_m,
                         int panel_px = 900);

}  // namespace roomscout::io
