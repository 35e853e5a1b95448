#pragma once
// The 2D occupancy grid every other map and strategy reads: log-odds per cell.

#include <cstdint>
#include <vector>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

/// What is known of a cell. The values are fixed: code indexes tables by them, ORs them as
/// bits and counts with them (free 1, occupied 2; e.g. mmpf's coarse grid, improved_rrt's gain
/// table: 1 - state).
enum class CellState : std::uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };
static_assert(sizeof(CellState) == 1);
static_assert(static_cast<int>(CellState::kUnknown) == 0 &&
              static_cast<int>(CellState::kFree) == 1 &&
              static_cast<int>(CellState::kOccupied) == 2);

/// Log-odds update and classification constants of an OccupancyGrid.
/// Its fields are documented in parameters() and printed by `roomscout options`.
struct OccupancyGridOptions {
  double resolution_m = 0.05;
  double log_odds_hit = 1.6;
  double log_odds_miss = -0.41;
  double log_odds_min = -2.0;
  double log_odds_max = 3.5;
  double occupied_threshold = 0.62;
  double free_threshold = -0.35;

  /// Throws OptionError when a value is out of range.
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// A grid of log-odds occupancy values. Unknown cells hold exactly 0. Each cell's state (its
/// log-odds classified by the thresholds) is kept beside it, one byte per cell, updated on
/// every write: readers that ask for states (strategies, costmap, analysis) read bytes.
/// Not thread-safe for concurrent writes; concurrent reads are fine.
class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  OccupancyGrid(const GridGeometry& geometry, const OccupancyGridOptions& options = {});

  const GridGeometry& geometry() const { return geometry_; }
  const OccupancyGridOptions& options() const { return options_; }

  CellState state(std::size_t index) const { return states_[index]; }
  CellState state(Cell c) const { return state(geometry_.index(c)); }
  bool isFree(std::size_t index) const { return state(index) == CellState::kFree; }
  bool isUnknown(std::size_t index) const { return state(index) == CellState::kUnknown; }
  bool isOccupied(std::size_t index) const { return state(index) == CellState::kOccupied; }

  float logOdds(std::size_t index) const { return log_odds_[index]; }

  /// Raw updates, clamped to the options' range.
  void addHit(std::size_t index) { add(index, hit_); }
  void addMiss(std::size_t index) { add(index, miss_); }
  /// Sets a cell's log-odds, clamped to the options' range (a map rendered from others).
  void setLogOdds(std::size_t index, float value) {
    float& l = log_odds_[index];
    l = std::min(max_, std::max(min_, value));
    states_[index] = classify(l);
  }

  /// Marks every cell with the given state (used to build grids from existing maps).
  void setState(std::size_t index, CellState state);

  /// This map laid on another geometry of the same resolution whose origin lies a whole number
  /// of cells away (as a SLAM map that grows or is cropped): cells both cover keep their
  /// log-odds, the others are unknown. Throws InvalidArgument for another resolution or an
  /// origin off the cell lattice.
  OccupancyGrid reframed(const GridGeometry& geometry) const;
  /// Copies the cells of `source` inside `rect` (source cells) onto the cells at the same map
  /// positions here, where this grid has them. Same conditions as reframed().
  void copyCells(const OccupancyGrid& source, const CellRect& rect);

  /// Cell states as one byte per cell, row-major (for bulk analysis).
  const std::vector<CellState>& states() const { return states_; }
  /// The same bytes as plain integers (the CellState values), for counting and comparing.
  const std::uint8_t* stateBytes() const {
    return reinterpret_cast<const std::uint8_t*>(states_.data());
  }

 private:
  void add(std::size_t index, float delta) {
    float& l = log_odds_[index];
    l = std::min(max_, std::max(min_, l + delta));
    states_[index] = classify(l);
  }
  CellState classify(float l) const {
    // free_threshold < 0 < occupied_threshold (validated), so at most one term is 1.
    return static_cast<CellState>((l > occupied_threshold_) * 2 + (l < free_threshold_));
  }

  /// Cells from this grid's cell (0,0) to `other`'s; throws unless the lattices coincide.
  Cell latticeOffset(const GridGeometry& other) const;

  GridGeometry geometry_;
  OccupancyGridOptions options_;
  std::vector<float> log_odds_;
  std::vector<CellState> states_;  ///< classify(log_odds_[i]), kept in step with it
  float hit_ = 0, miss_ = 0, min_ = 0, max_ = 0, occupied_threshold_ = 0, free_threshold_ = 0;
};

}  // namespace roomscout
