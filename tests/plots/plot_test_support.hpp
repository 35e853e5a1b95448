#pragma once
// Helpers for the plots tests: counting substrings, a tag-balance check for SVG/HTML text, and
// example figures.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "roomscout/plots/bar_chart.hpp"
#include "roomscout/plots/line_chart.hpp"
#include "roomscout/plots/map_panels.hpp"

#include "../support/temp_dir.hpp"

namespace roomscout::plots::test {

using roomscout::test::TempDir;

inline std::size_t count(std::string_view text, std::string_view part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

/// Succeeds when every element tag in `xml` is closed in order (self-closing tags and HTML
/// void elements need no end tag); comments, doctype and text are skipped. An XML-ish check:
/// no entity or attribute validation.
inline ::testing::AssertionResult TagsBalanced(const std::string& xml) {
  static const std::vector<std::string> kVoid = {"meta", "img", "br", "hr", "link", "input"};
  std::vector<std::string> open;
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos) {
    if (xml.compare(at, 4, "<!--") == 0) {
      at = xml.find("-->", at);
      if (at == std::string::npos) return ::testing::AssertionFailure() << "unclosed comment";
      continue;
    }
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag at " << at;
    const std::string tag = xml.substr(at + 1, end - at - 1);
    at = end + 1;
    if (tag.empty() || tag[0] == '!' || tag[0] == '?') continue;
    const bool closing = tag[0] == '/';
    const std::size_t name_start = closing ? 1 : 0;
    const std::size_t name_end = tag.find_first_of(" \t\n/", name_start);
    const std::string name = tag.substr(
        name_start, name_end == std::string::npos ? std::string::npos : name_end - name_start);
    if (closing) {
      if (open.empty() || open.back() != name) {
        return ::testing::AssertionFailure()
               << "</" << name << "> closes <" << (open.empty() ? "nothing" : open.back()) << ">";
      }
      open.pop_back();
    } else if (tag.back() != '/' && std::find(kVoid.begin(), kVoid.end(), name) == kVoid.end()) {
      open.push_back(name);
      if (name == "style" || name == "script") {  // raw text up to the end tag
        const std::size_t close = xml.find("</" + name, at);
        if (close == std::string::npos) return ::testing::AssertionFailure() << "unclosed " << name;
        at = close;
      }
    }
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> never closed";
  return ::testing::AssertionSuccess();
}

/// Values of attribute `name` of every element whose tag contains `marker`.
inline std::vector<double> attributeValues(const std::string& xml, std::string_view marker,
                                           const std::string& name) {
  std::vector<double> values;
  std::size_t at = 0;
  while ((at = xml.find(marker, at)) != std::string::npos) {
    const std::size_t start = xml.rfind('<', at);
    const std::size_t end = xml.find('>', at);
    const std::string tag = xml.substr(start, end - start);
    const std::size_t attr = tag.find(" " + name + "=\"");
    if (attr != std::string::npos) values.push_back(std::stod(tag.substr(attr + name.size() + 3)));
    at = end;
  }
  return values;
}

/// Number of pixels within `tolerance` of `color` (per channel).
inline int pixelsNear(const cv::Mat& bgr, Rgb color, int tolerance = 12) {
  int n = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      n += std::abs(p[0] - color.b) <= tolerance && std::abs(p[1] - color.g) <= tolerance &&
           std::abs(p[2] - color.r) <= tolerance;
    }
  }
  return n;
}

/// Exploration-rate curves of three methods in one world, as Fig. 5 draws them.
inline LineChart exampleLineChart() {
  LineChart chart;
  chart.title = "small_house: exploration rate";
  chart.x_label = "trajectory length [m]";
  chart.y_label = "exploration rate [%]";
  const char* names[] = {"semantic", "nearest_frontier", "rrt"};
  for (int k = 0; k < 3; ++k) {
    LineSeries s;
    s.name = names[k];
    for (int i = 0; i <= 40; ++i) {
      const double length = i * 5.0;
      s.points.push_back({length, 100.0 * (1.0 - std::exp(-length / (30.0 + 15.0 * k)))});
    }
    chart.series.push_back(s);
  }
  chart.reference = ReferenceLine{98.0, "98 %"};
  chart.y_min = 0.0;
  chart.y_max = 100.0;
  chart.size = {720, 420};
  return chart;
}

/// Revisits per method (series) and world (category), as the revisit table's chart.
inline BarChart exampleBarChart() {
  BarChart chart;
  chart.title = "Room revisits";
  chart.y_label = "revisits";
  chart.categories = {"small_house", "medium_house", "large_office"};
  chart.series = {{"semantic", {1, 3, 8}, {}},
                  {"nearest_frontier", {2, 6, 15}, {}},
                  {"rrt", {4, 9, std::nan("")}, {}}};
  chart.size = {640, 360};
  return chart;
}

/// A synthetic occupancy-like map image: grey unknown, a white room, black walls.
inline cv::Mat exampleMap(int width, int height, cv::Scalar room_bgr = {255, 255, 255}) {
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(205, 205, 205));
  cv::rectangle(image, {5, 5}, {width - 6, height - 6}, cv::Scalar(0, 0, 0), cv::FILLED);
  cv::rectangle(image, {8, 8}, {width - 9, height - 9}, room_bgr, cv::FILLED);
  return image;
}

/// Four panels in two rows, each with a trajectory across its room.
inline MapPanelFigure exampleMapPanels(cv::Scalar room_bgr = {255, 255, 255}) {
  MapPanelFigure figure;
  figure.title = "Trajectories";
  figure.columns = 2;
  figure.size = {800, 640};
  const char* names[] = {"semantic", "nearest_frontier", "rrt", "mmpf"};
  for (int k = 0; k < 4; ++k) {
    MapPanel panel;
    panel.title = names[k];
    panel.image = exampleMap(160 + 40 * k, 100, room_bgr);
    PanelTrack track;
    track.points_px = {{12, 12}, {60, 50}, {100.0 + 30 * k, 80}};
    panel.tracks.push_back(track);
    figure.panels.push_back(panel);
  }
  return figure;
}

}  // namespace roomscout::plots::test
