#include "roomscout/io/point_cloud_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

namespace roomscout::io {

namespace {

/// One orthographic panel: image axes right/up and depth along `view` (smaller = nearer).
cv::Mat renderPanel(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& right,
                    const Eigen::Vector3f& up, const Eigen::Vector3f& view, float z_lo, float z_hi,
                    int px, const char* label) {
  cv::Mat image(px, px, CV_8UC3, cv::Scalar(255, 255, 255));
  if (!points.empty()) {
    float u_lo = std::numeric_limits<float>::infinity(), u_hi = -u_lo, v_lo = u_lo, v_hi = -u_lo;
    for (const Eigen::Vector3f& p : points) {
      const float u = p.dot(right), v = p.dot(up);
      u_lo = std::min(u_lo, u), u_hi = std::max(u_hi, u);
      v_lo = std::min(v_lo, v), v_hi = std::max(v_hi, v);
    }
    const float margin = 0.04f * px;
    const float scale = (px - 2 * margin) / std::max({u_hi - u_lo, v_hi - v_lo, 1e-3f});
    const float u0 = margin + 0.5f * ((px - 2 * margin) - (u_hi - u_lo) * scale);
    const float v0 = margin + 0.5f * ((px - 2 * margin) - (v_hi - v_lo) * scale);
    cv::Mat depth(px, px, CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
    cv::Mat lut(1, 256, CV_8UC1);
    for (int i = 0; i < 256; ++i) lut.at<std::uint8_t>(i) = static_cast<std::uint8_t>(i);
    cv::Mat colours;
    cv::applyColorMap(lut, colours, cv::COLORMAP_TURBO);
    const float z_span = std::max(z_hi - z_lo, 1e-3f);
    for (const Eigen::Vector3f& p : points) {
      const int col = static_cast<int>(u0 + (p.dot(right) - u_lo) * scale);
      const int row = static_cast<int>(px - 1 - (v0 + (p.dot(up) - v_lo) * scale));
      if (col < 0 || row < 0 || col >= px || row >= px) continue;
      const float d = p.dot(view);
      float& zb = depth.at<float>(row, col);
      if (d >= zb) continue;
      zb = d;
      const int level = std::clamp(static_cast<int>((p.z() - z_lo) / z_span * 255.0f), 0, 255);
      image.at<cv::Vec3b>(row, col) = colours.at<cv::Vec3b>(0, level);
    }
  }
  cv::putText(image, label, cv::Point(10, 28), cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0),
              2);
  return image;
}

}  // namespace

cv::Mat renderPointCloud(const std::vector<Eigen::Vector3f>& points_map, double clip_z_m,
                         int panel_px) {
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(points_map.size());
  float z_lo = std::numeric_limits<float>::infinity(), z_hi = -z_lo;
  for (const Eigen::Vector3f& p : points_map) {
    if (p.z() > clip_z_m || !p.allFinite()) continue;
    kept.push_back(p);
    z_lo = std::min(z_lo, p.z());
    z_hi = std::max(z_hi, p.z());
  }
  const cv::Mat top = renderPanel(kept, Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(),
                                  -Eigen::Vector3f::UnitZ(), z_lo, z_hi, panel_px, "top");
  const float az = static_cast<float>(-60.0 * M_PI / 180.0),
              el = static_cast<float>(35.0 * M_PI / 180.0);
  // Camera on the side of azimuth `az`, elevation `el`, looking at the cloud.
  const Eigen::Vector3f view =
      -Eigen::Vector3f(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  const Eigen::Vector3f right = view.cross(Eigen::Vector3f::UnitZ()).normalized();
  const Eigen::Vector3f up = right.cross(view);
  const cv::Mat oblique = renderPanel(kept, right, up, view, z_lo, z_hi, panel_px, "oblique");
  cv::Mat both;
  cv::hconcat(top, oblique, both);
  return both;
}

}  // namespace roomscout::io
