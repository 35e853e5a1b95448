#include "roomscout/mapping/keyframe_selector.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

TEST(KeyframeSelector, LioSamRuleByDefault) {
  KeyframeSelector k;
  EXPECT_TRUE(k.accept({0.0, 0.0, 0.0}));    // the first scan
  EXPECT_FALSE(k.accept({0.5, 0.0, 0.1}));   // 0.5 m, 0.1 rad
  EXPECT_FALSE(k.accept({0.99, 0.0, 0.19}));
  EXPECT_TRUE(k.accept({1.0, 0.0, 0.0}));    // 1 m from the last keyframe
  EXPECT_FALSE(k.accept({1.5, 0.0, 0.0}));
  EXPECT_TRUE(k.accept({1.0, 0.0, -0.2}));   // 0.2 rad
  EXPECT_TRUE(k.accept({1.0, 0.0, M_PI - 0.05}));
  EXPECT_TRUE(k.accept({1.0, 0.0, -M_PI + 0.2}));  // 0.25 rad across the wrap
  EXPECT_EQ(k.keyframes(), 5);
  EXPECT_NE(k.options().describe().find("1 m or 0.2 rad"), std::string::npos);
}

TEST(KeyframeSelector, EveryScan) {
  KeyframeOptions o;
  o.every_scan = true;
  KeyframeSelector k(o);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(k.accept({0.0, 0.0, 0.0}));
  EXPECT_EQ(o.describe(), "keyframes: every scan");
}

TEST(KeyframeSelector, RejectsBadOptions) {
  KeyframeOptions o;
  o.distance_m = 0.0;
  EXPECT_THROW(KeyframeSelector{o}, OptionError);
}

}  // namespace
}  // namespace roomscout
