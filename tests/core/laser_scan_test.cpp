// A scan cut to a shorter range, as a SLAM that trusts only its near returns reads it.

#include "roomscout/core/laser_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace roomscout {
namespace {

TEST(CappedToRange, ReturnsBeyondTheCapBecomeNoReturnAndInvalidReadingsStayInvalid) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  LaserScan scan;
  scan.range_max_m = 30.0;
  scan.ranges_m = {2.0f, 14.0f, 20.0f, 30.0f, 45.0f, inf, nan, 0.0f};
  const LaserScan capped = cappedToRange(scan, 15.0);
  EXPECT_EQ(capped.range_max_m, 15.0);
  EXPECT_EQ(capped.ranges_m[0], 2.0f);
  EXPECT_EQ(capped.ranges_m[1], 14.0f);
  EXPECT_EQ(capped.ranges_m[2], inf);  // seen free up to 15 m
  EXPECT_EQ(capped.ranges_m[3], inf);
  EXPECT_EQ(capped.ranges_m[4], 45.0f);  // beyond the sensor's own range: still invalid
  EXPECT_EQ(capped.ranges_m[5], inf);
  EXPECT_TRUE(std::isnan(capped.ranges_m[6]));
  EXPECT_EQ(capped.ranges_m[7], 0.0f);
  // A cap at or beyond the sensor's range changes nothing.
  const LaserScan same = cappedToRange(scan, 40.0);
  EXPECT_EQ(same.range_max_m, 30.0);
  EXPECT_EQ(same.ranges_m[2], 20.0f);
}

}  // namespace
}  // namespace roomscout
