#pragma once
// Synthetic occupancy images for the map analysis tests: cell states drawn with rectangles,
// 0.05 m cells, row y = grid row y.

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::test {

constexpr double kRes = 0.05;

inline std::uint8_t v(CellState s) { return static_cast<std::uint8_t>(s); }

/// A canvas of `fill` cells, w x h metres.
inline cv::Mat canvas(double w_m, double h_m, CellState fill = CellState::kOccupied) {
  return cv::Mat(static_cast<int>(h_m / kRes), static_cast<int>(w_m / kRes), CV_8U,
                 cv::Scalar(v(fill)));
}

/// Sets the cells of the rectangle [x0, x1) x [y0, y1) (metres) to `s`.
inline void box(cv::Mat& m, double x0, double y0, double x1, double y1, CellState s) {
  const cv::Rect r(static_cast<int>(std::lround(x0 / kRes)),
                   static_cast<int>(std::lround(y0 / kRes)),
                   static_cast<int>(std::lround((x1 - x0) / kRes)),
                   static_cast<int>(std::lround((y1 - y0) / kRes)));
  m(r & cv::Rect(0, 0, m.cols, m.rows)).setTo(v(s));
}

/// An OccupancyGrid with these states, origin (0, 0).
inline OccupancyGrid gridOf(const cv::Mat& states) {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), kRes, states.cols, states.rows));
  for (int y = 0; y < states.rows; ++y) {
    for (int x = 0; x < states.cols; ++x) {
      grid.setState(grid.geometry().index(Cell{x, y}),
                    static_cast<CellState>(states.at<std::uint8_t>(y, x)));
    }
  }
  return grid;
}

/// A floor plan 16 x 10 m: three rooms along the top (5.2 m wide, 5.8 m deep), a corridor
/// 2 m wide along the bottom; 0.9 m doors; walls 0.1 m thick. Ground-truth room per cell
/// returned in `truth` (1..3 rooms, 4 corridor).
inline cv::Mat threeRoomsAndCorridor(cv::Mat* truth = nullptr) {
  cv::Mat m = canvas(16.4, 10.4);
  const auto F = CellState::kFree;
  box(m, 0.2, 0.2, 16.2, 2.2, F);  // corridor
  for (int i = 0; i < 3; ++i) {
    const double x0 = 0.2 + i * 5.35;
    box(m, x0, 2.3, x0 + 5.25, 10.2, F);      // room above the corridor wall (y 2.2 .. 2.3)
    box(m, x0 + 2.0, 2.2, x0 + 2.9, 2.3, F);  // door
  }
  if (truth) {
    *truth = cv::Mat::zeros(m.size(), CV_32S);
    for (int y = 0; y < m.rows; ++y) {
      for (int x = 0; x < m.cols; ++x) {
        if (m.at<std::uint8_t>(y, x) != v(F)) continue;
        const double ym = (y + 0.5) * kRes, xm = (x + 0.5) * kRes;
        truth->at<int>(y, x) = ym < 2.25 ? 4 : 1 + std::min(2, static_cast<int>((xm - 0.2) / 5.35));
      }
    }
  }
  return m;
}

/// A corridor 2 m wide along the bottom of a building `rooms` x 5 m long, rooms 4.9 m wide and
/// 5.8 m deep above it, each with a 0.9 m door; `truth` gets one label per room, corridor
/// last.
inline cv::Mat roomRow(int rooms, cv::Mat* truth) {
  const double length = rooms * 5.0 + 0.4;
  cv::Mat m = canvas(length, 8.4);
  const auto F = CellState::kFree;
  box(m, 0.2, 0.2, length - 0.2, 2.2, F);
  *truth = cv::Mat::zeros(m.size(), CV_32S);
  (*truth)(cv::Rect(4, 4, m.cols - 8, 40)).setTo(rooms + 1);
  for (int i = 0; i < rooms; ++i) {
    const double x0 = 0.2 + i * 5.0;
    box(m, x0, 2.3, x0 + 4.9, 8.2, F);
    box(m, x0 + 2.0, 2.2, x0 + 2.9, 2.3, F);
    const cv::Rect room(static_cast<int>(std::lround(x0 / kRes)), 46, 98, 118);
    (*truth)(room).setTo(i + 1);
  }
  truth->setTo(0, m != v(F));
  return m;
}

/// The map as a robot driving along +x sees it: everything up to x_m, the rest unknown.
inline cv::Mat seenUpTo(const cv::Mat& full, double x_m) {
  cv::Mat seen(full.size(), CV_8U, cv::Scalar(v(CellState::kUnknown)));
  const int cols = std::min(full.cols, static_cast<int>(x_m / kRes));
  if (cols > 0) full.colRange(0, cols).copyTo(seen.colRange(0, cols));
  return seen;
}

inline GridGeometry geometryOf(const cv::Mat& states, const Vec2& origin = Vec2::Zero()) {
  return GridGeometry(origin, kRes, states.cols, states.rows);
}

}  // namespace roomscout::test
