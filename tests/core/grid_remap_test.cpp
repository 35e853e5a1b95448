// Per-cell state laid onto a grown or moved grid by map position.

#include "roomscout/core/grid_remap.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace roomscout {
namespace {

TEST(RemapCells, MovesEveryValueByTheCellOffsetOfTheOrigins) {
  const GridGeometry from({1.0, -2.0}, 0.05, 30, 20);
  std::vector<int> values(from.cellCount());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<int>(i) + 1;
  // Grown by 7 cells left, 3 below, 11 right and 5 above.
  const GridGeometry to(from.origin_m() - Vec2(7 * 0.05, 3 * 0.05), 0.05, 30 + 18, 20 + 8);
  const std::vector<int> out = remapCells(values, from, to, -1);
  ASSERT_EQ(out.size(), to.cellCount());
  int kept = 0;
  for (int y = 0; y < to.height(); ++y) {
    for (int x = 0; x < to.width(); ++x) {
      const Cell old{x - 7, y - 3};
      const int expected = from.contains(old) ? values[from.index(old)] : -1;
      ASSERT_EQ(out[to.index(Cell{x, y})], expected) << x << "," << y;
      kept += expected != -1;
    }
  }
  EXPECT_EQ(kept, 30 * 20);
  // Cropped and moved the other way: the values off the new grid are dropped.
  const GridGeometry cropped(from.origin_m() + Vec2(4 * 0.05, 2 * 0.05), 0.05, 10, 10);
  const std::vector<int> in = remapCells(values, from, cropped, -1);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x)
      EXPECT_EQ(in[cropped.index(Cell{x, y})], values[from.index(Cell{x + 4, y + 2})]);
  }
}

TEST(RemapCells, AnotherResolutionTakesTheOldCellUnderEachCentreAndBadInputGivesFill) {
  const GridGeometry from({0.0, 0.0}, 0.1, 4, 4);
  std::vector<std::uint8_t> marks(from.cellCount(), 0);
  marks[from.index(Cell{1, 2})] = 1;  // [0.1, 0.2) x [0.2, 0.3)
  const GridGeometry fine({0.0, 0.0}, 0.05, 8, 8);
  const std::vector<std::uint8_t> out = remapCells(marks, from, fine);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(out[fine.index(Cell{x, y})], (x / 2 == 1 && y / 2 == 2) ? 1 : 0);
  }
  // Values never laid on `from` (empty, or of another size) carry nothing over.
  EXPECT_EQ(remapCells(std::vector<std::uint8_t>{}, from, fine, std::uint8_t{7}),
            std::vector<std::uint8_t>(64, 7));
  EXPECT_EQ(remapCells(std::vector<std::uint8_t>(5, 1), from, fine),
            std::vector<std::uint8_t>(64, 0));
}

TEST(GeometryWatch, ReportsThePreviousGeometryOnlyWhenItChanged) {
  GeometryWatch watch;
  const GridGeometry a({0, 0}, 0.05, 10, 10), b({-0.05, 0}, 0.05, 11, 10);
  EXPECT_FALSE(watch.update(a).has_value());
  EXPECT_FALSE(watch.update(a).has_value());
  const auto previous = watch.update(b);
  ASSERT_TRUE(previous.has_value());
  EXPECT_EQ(*previous, a);
  EXPECT_FALSE(watch.update(b).has_value());
}

}  // namespace
}  // namespace roomscout
