#include "roomscout/mapping/keyframe_selector.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

TEST(KeyframeSelector, LioSamRuleWithoutTheTurnMargin) {
  KeyframeOptions o;
  o.turn_min_move_m = 0.0;
  KeyframeSelector k(o);
  EXPECT_TRUE(k.accept({0.0, 0.0, 0.0}));   // the first scan
  EXPECT_FALSE(k.accept({0.5, 0.0, 0.1}));  // 0.5 m, 0.1 rad
  EXPECT_FALSE(k.accept({0.99, 0.0, 0.19}));
  EXPECT_TRUE(k.accept({1.0, 0.0, 0.0}));  // 1 m from the last keyframe
  EXPECT_FALSE(k.accept({1.5, 0.0, 0.0}));
  EXPECT_TRUE(k.accept({1.0, 0.0, -0.2}));  // 0.2 rad
  EXPECT_TRUE(k.accept({1.0, 0.0, M_PI - 0.05}));
  EXPECT_TRUE(k.accept({1.0, 0.0, -M_PI + 0.2}));  // 0.25 rad across the wrap
  EXPECT_EQ(k.keyframes(), 5);
  EXPECT_EQ(k.options().describe(), "keyframes: every 1 m or 0.2 rad (LIO-SAM rule)");
}

TEST(KeyframeSelector, ATurnOnTheSpotMakesNoKeyframeByDefault) {
  KeyframeSelector k;
  EXPECT_TRUE(k.accept({0.0, 0.0, 0.0}));
  for (int i = 1; i <= 30; ++i)
    EXPECT_FALSE(k.accept({0.0, 0.0, 0.2 * i})) << i;  // a full turn and more
  EXPECT_FALSE(k.accept({0.09, 0.0, 1.0}));            // 9 cm and turned: still the same spot
  EXPECT_TRUE(k.accept({0.1, 0.0, 1.0}));              // 10 cm and turned 1 rad
  EXPECT_FALSE(k.accept({0.3, 0.0, 1.1}));             // 20 cm but only 0.1 rad
  EXPECT_TRUE(k.accept({1.1, 0.0, 1.0}));              // 1 m, no turn
  EXPECT_EQ(k.keyframes(), 3);
  EXPECT_NE(k.options().describe().find("no turns on the spot"), std::string::npos);
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
  o = {};
  o.turn_min_move_m = -0.1;
  EXPECT_THROW(KeyframeSelector{o}, OptionError);
  o.turn_min_move_m = 1.0;  // not below distance_m
  EXPECT_THROW(KeyframeSelector{o}, OptionError);
}

}  // namespace
}  // namespace roomscout
