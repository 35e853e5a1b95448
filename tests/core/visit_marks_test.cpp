// Marks that a new search clears all at once, without touching every cell.

#include "roomscout/core/visit_marks.hpp"

#include <gtest/gtest.h>

namespace roomscout {
namespace {

TEST(VisitMarks, ASearchSeesOnlyItsOwnMarks) {
  VisitMarks marks;
  marks.begin(4);
  EXPECT_FALSE(marks.marked(1));
  marks.mark(1);
  marks.mark(3);
  EXPECT_TRUE(marks.marked(1));
  EXPECT_TRUE(marks.marked(3));
  EXPECT_FALSE(marks.marked(0));
  marks.begin(4);  // the next search
  for (std::size_t i = 0; i < 4; ++i) EXPECT_FALSE(marks.marked(i)) << i;
  marks.mark(2);
  marks.begin(6);  // a grid of another size
  for (std::size_t i = 0; i < 6; ++i) EXPECT_FALSE(marks.marked(i)) << i;
  marks.mark(5);
  EXPECT_TRUE(marks.marked(5));
}

}  // namespace
}  // namespace roomscout
