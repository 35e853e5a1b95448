// Components found on runs against cv::connectedComponentsWithStats.

#include "roomscout/maps/detail/run_components.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {
namespace {

/// Random blobs and specks, so that components touch diagonally, wrap around holes and meet
/// the image border.
cv::Mat randomImage(int rows, int cols, std::uint32_t seed) {
  std::mt19937 rng(seed);
  cv::Mat image = cv::Mat::zeros(rows, cols, CV_8U);
  std::uniform_int_distribution<int> ux(0, cols - 1), uy(0, rows - 1), size(1, 12);
  for (int i = 0; i < rows * cols / 40; ++i) {
    cv::rectangle(image, cv::Rect(ux(rng), uy(rng), size(rng), size(rng)), cv::Scalar(255),
                  cv::FILLED);
  }
  std::bernoulli_distribution speck(0.05);
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      if (speck(rng)) image.at<std::uint8_t>(y, x) ^= 255;
    }
  }
  return image;
}

void expectSameAsOpenCv(const cv::Mat& image, int connectivity) {
  cv::Mat labels, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(image, labels, stats, centroids, connectivity, CV_32S);
  const RunComponents runs = runComponents(image, connectivity);
  ASSERT_EQ(static_cast<int>(runs.components.size()), n - 1);
  // The same partition: each run's pixels carry one OpenCV label, one-to-one with components.
  std::map<int, int> cv_of;  // our component -> OpenCV label
  int pixels = 0;
  for (const PixelRun& r : runs.runs) {
    for (int x = r.x_begin; x < r.x_end; ++x) {
      const int l = labels.at<int>(r.y, x);
      ASSERT_GT(l, 0);
      const auto [it, inserted] = cv_of.emplace(r.component, l);
      ASSERT_EQ(it->second, l);
      ++pixels;
    }
  }
  EXPECT_EQ(pixels, cv::countNonZero(image));
  std::map<int, int> ours_of;
  for (const auto& [ours, l] : cv_of) ASSERT_TRUE(ours_of.emplace(l, ours).second);
  for (const auto& [ours, l] : cv_of) {
    const RunComponent& c = runs.components[ours];
    EXPECT_EQ(c.area, stats.at<int>(l, cv::CC_STAT_AREA));
    EXPECT_EQ(c.min_x, stats.at<int>(l, cv::CC_STAT_LEFT));
    EXPECT_EQ(c.min_y, stats.at<int>(l, cv::CC_STAT_TOP));
    EXPECT_EQ(c.max_x - c.min_x + 1, stats.at<int>(l, cv::CC_STAT_WIDTH));
    EXPECT_EQ(c.max_y - c.min_y + 1, stats.at<int>(l, cv::CC_STAT_HEIGHT));
  }
}

TEST(RunComponents, SameComponentsAndStatsAsOpenCv) {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const cv::Mat image =
        randomImage(60 + 7 * static_cast<int>(seed), 90 - 5 * static_cast<int>(seed), seed);
    expectSameAsOpenCv(image, 4);
    expectSameAsOpenCv(image, 8);
  }
}

TEST(RunComponents, DiagonalNeighboursJoinOnlyWithEightConnectivity) {
  cv::Mat image = cv::Mat::zeros(4, 4, CV_8U);
  image.at<std::uint8_t>(0, 0) = image.at<std::uint8_t>(1, 1) = image.at<std::uint8_t>(2, 2) = 1;
  image.at<std::uint8_t>(3, 0) = 1;
  EXPECT_EQ(runComponents(image, 4).components.size(), 4u);
  EXPECT_EQ(runComponents(image, 8).components.size(), 2u);
  // An empty image and a full one, and a predicate instead of "non-zero".
  EXPECT_TRUE(runComponents(cv::Mat::zeros(3, 5, CV_8U), 8).components.empty());
  const RunComponents full =
      runComponents(cv::Mat::zeros(3, 5, CV_8U), 4, [](std::uint8_t v) { return v == 0; });
  ASSERT_EQ(full.components.size(), 1u);
  EXPECT_EQ(full.components[0].area, 15);
  EXPECT_EQ(full.runs.size(), 3u);
}

TEST(RunComponents, RejectsBadInput) {
  EXPECT_THROW(runComponents(cv::Mat::zeros(3, 3, CV_32S), 4), InvalidArgument);
  EXPECT_THROW(runComponents(cv::Mat::zeros(3, 3, CV_8U), 6), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::maps
