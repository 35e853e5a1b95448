#include "roomscout/plots/text_encoding.hpp"

#include <gtest/gtest.h>

namespace roomscout::plots {
namespace {

TEST(TextEncoding, Base64MatchesRfc4648TestVectors) {
  EXPECT_EQ(encodeBase64(""), "");
  EXPECT_EQ(encodeBase64("f"), "Zg==");
  EXPECT_EQ(encodeBase64("fo"), "Zm8=");
  EXPECT_EQ(encodeBase64("foo"), "Zm9v");
  EXPECT_EQ(encodeBase64("foob"), "Zm9vYg==");
  EXPECT_EQ(encodeBase64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encodeBase64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(encodeBase64(std::string("\xff\x00\xfe", 3)), "/wD+");
}

TEST(TextEncoding, EscapesXmlSpecialCharacters) {
  EXPECT_EQ(escapeXml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escapeXml("98 % ± 1"), "98 % ± 1");
}

}  // namespace
}  // namespace roomscout::plots
