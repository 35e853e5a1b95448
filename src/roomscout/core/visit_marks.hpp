#pragma once
// Marks a search sets on the cells of a grid, cleared all at once when the next search begins:
// each search takes a new stamp and a cell is marked when it holds the current one, so a
// search costs what it visits, not the size of the grid.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace roomscout {

class VisitMarks {
 public:
  /// Starts a search over `n` cells: no cell is marked.
  void begin(std::size_t n) {
    if (marks_.size() != n) marks_.assign(n, 0);
    if (++stamp_ == 0) {  // wrapped: no stale mark may look current
      std::fill(marks_.begin(), marks_.end(), 0u);
      stamp_ = 1;
    }
  }
  bool marked(std::size_t i) const { return marks_[i] == stamp_; }
  void mark(std::size_t i) { marks_[i] = stamp_; }

 private:
  std::vector<std::uint32_t> marks_;
  std::uint32_t stamp_ = 0;
};

}  // namespace roomscout
