#include "roomscout/plots/svg_ids.hpp"

#include <gtest/gtest.h>

namespace roomscout::plots {
namespace {

TEST(SvgIds, NumbersIdsInDocumentOrderAndRenamesTheirReferences) {
  const std::string svg =
      "<svg><defs><symbol id=\"glyph0-1\"/><image id=\"image21\"/>"
      "<clipPath id=\"clip3\"><path/></clipPath></defs>"
      "<use xlink:href=\"#surface17\"/>"
      "<g id=\"surface17\" clip-path=\"url(#clip3)\"><use xlink:href=\"#glyph0-1\" x=\"1\"/>"
      "<use href=\"#image21\"/><use xlink:href=\"#elsewhere\"/></g></svg>";
  EXPECT_EQ(numberSvgIds(svg),
            "<svg><defs><symbol id=\"glyph1\"/><image id=\"image2\"/>"
            "<clipPath id=\"clip3\"><path/></clipPath></defs>"
            "<use xlink:href=\"#surface4\"/>"
            "<g id=\"surface4\" clip-path=\"url(#clip3)\"><use xlink:href=\"#glyph1\" x=\"1\"/>"
            "<use href=\"#image2\"/><use xlink:href=\"#elsewhere\"/></g></svg>");
  const std::string prefixed = numberSvgIds(svg, "fig2-");
  EXPECT_NE(prefixed.find("<g id=\"fig2-surface4\" clip-path=\"url(#fig2-clip3)\">"),
            std::string::npos);
  EXPECT_NE(prefixed.find("xlink:href=\"#fig2-glyph1\""), std::string::npos);
  // Numbering again gives the same document.
  EXPECT_EQ(numberSvgIds(numberSvgIds(svg)), numberSvgIds(svg));
  EXPECT_EQ(numberSvgIds("<svg/>"), "<svg/>");
}

}  // namespace
}  // namespace roomscout::plots
