#include "roomscout/explorer/analysis_maps.hpp"

#include <chrono>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {

void AnalysisMapsOptions::validate() const {
  if (!(period_s > 0.0)) throw OptionError("maps.period_s must be > 0");
  if (!(min_new_area_m2 >= 0.0)) throw OptionError("maps.min_new_area_m2 must be >= 0");
  if (topology_every < 1) throw OptionError("maps.topology_every must be >= 1");
  rooms.validate();
  skeleton.validate();
  segmentation.validate();
  topology.validate();
}

std::vector<ParameterRef> AnalysisMapsOptions::parameters() {
  return {
      {"period_s", &period_s, "simulated time between update checks [s]"},
      {"min_new_area_m2", &min_new_area_m2,
       "an update runs only when this much of the grid became known since the last one [m^2] "
       "(re-traversing known space changes nothing worth 10-30 ms of analysis)"},
      {"topology_every", &topology_every,
       "rebuild the topological map on every n-th due update only (always on the first and at the "
       "end); no strategy reads it, so its final map is the same for any n"},
      {"rooms_margin_m", &rooms.margin_m,
       "an update segments again only the rooms within this distance of a changed cell, in a "
       "window this much wider than them [m]"},
      {"rooms_reach_m", &rooms.reach_m,
       "... taken whole as far as they lie within this distance of a changed cell; a room "
       "reaching farther keeps its cells beyond [m]"},
      {"rooms_full_share", &rooms.full_share,
       "... and the whole map when that window would cover more than this share of the known "
       "map's bounding box (0: always the whole map)"},
      {"rooms_min_overlap_m2", &rooms.min_overlap_m2,
       "a room reaching beyond the window is merged with another when one window segment "
       "covers this much of each, or, split by the window, makes the whole map be segmented "
       "[m^2]"},
      {"rooms_full_interval", &rooms.full_interval,
       "... though not within this many updates of the last time [updates]"},
      {"skeleton_margin_m", &skeleton.margin_m,
       "an update rebuilds the skeleton within this distance of a changed cell (more where the "
       "free space is wider than twice this), from a window twice as far [m]"},
      {"skeleton_full_share", &skeleton.full_share,
       "... and the whole map's when that window would cover more than this share of the known "
       "map's bounding box (0: always the whole map)"},
  };
}

AnalysisMap::AnalysisMap(AnalysisMapKind kind, const AnalysisMapsOptions& options,
                         const AnalysisMap* rooms, MapWorker* worker)
    : kind_(kind),
      options_(options),
      rooms_(kind == AnalysisMapKind::kTopological ? rooms : nullptr),
      worker_(worker != nullptr && worker->background() ? worker : nullptr),
      segmenter_(options.segmentation, options.rooms),
      builder_(options.topology, options.skeleton) {
  options_.validate();
}

AnalysisMap::~AnalysisMap() {
  if (worker_ != nullptr) worker_->wait();  // jobs still queued refer to this observer
}

std::string_view AnalysisMap::name() const {
  return kind_ == AnalysisMapKind::kSemantic ? "semantic" : "topological";
}

int AnalysisMap::fullUpdates() const {
  return kind_ == AnalysisMapKind::kSemantic ? segmenter_.fullUpdates() : builder_.fullUpdates();
}

int AnalysisMap::windowUpdates() const {
  return kind_ == AnalysisMapKind::kSemantic ? segmenter_.windowUpdates()
                                             : builder_.windowUpdates();
}

const SemanticMap* AnalysisMap::semanticMap() const {
  return kind_ == AnalysisMapKind::kSemantic ? &semantic_ : nullptr;
}

void AnalysisMap::observe(const OccupancyGrid& grid, double time_s, bool grid_changed) {
  changed_ = changed_ || grid_changed;
  if (kind_ == AnalysisMapKind::kTopological && rooms_ != nullptr) {
    // Follow the schedule of the rooms that label the nodes: rebuild right after they were
    // rebuilt, instead of counting the known cells a second time for the same decision.
    if (rooms_->updates_ != rooms_updates_seen_) {
      rooms_updates_seen_ = rooms_->updates_;
      if (due_updates_++ % options_.topology_every == 0) update(grid);
    }
    return;
  }
  if (time_s + 1e-9 < next_update_s_ || !changed_) return;
  next_update_s_ = time_s + options_.period_s;
  const std::size_t known = maps::knownCellCount(grid);
  const double res = grid.geometry().resolution_m();
  const double new_area_m2 =
      std::abs(static_cast<double>(known) - static_cast<double>(known_at_update_)) * res * res;
  if (updated_once_ && new_area_m2 < options_.min_new_area_m2) return;
  known_at_update_ = known;
  if (kind_ == AnalysisMapKind::kTopological && due_updates_++ % options_.topology_every != 0)
    return;
  update(grid);
}

void AnalysisMap::finish(const OccupancyGrid& grid, bool grid_changed) {
  if (changed_ || grid_changed || !updated_once_) update(grid);
  if (worker_ != nullptr) worker_->drain();
}

void AnalysisMap::update(const OccupancyGrid& grid) {
  ++updates_;
  changed_ = false;
  updated_once_ = true;
  // Rooms built on another thread are read once that thread has built them.
  if (rooms_ != nullptr && rooms_->worker_ != nullptr && rooms_->worker_ != worker_)
    rooms_->worker_->drain();
  if (worker_ == nullptr) {
    maps::stateImage(grid, states_);
    build(states_, grid.geometry(), nullptr);
    return;
  }
  // The rooms that label the nodes are those of the rooms' latest update. Rooms built on this
  // worker are read when this job runs, after theirs; others are copied now (the copy shares
  // their label image, which an update replaces rather than writes into).
  std::shared_ptr<const SemanticMap> rooms;
  if (rooms_ != nullptr && rooms_->worker_ != worker_)
    rooms = std::make_shared<const SemanticMap>(rooms_->semantic_);
  worker_->post([this, states = maps::stateImage(grid), geometry = grid.geometry(),
                 rooms = std::move(rooms)] { build(states, geometry, rooms); });
}

void AnalysisMap::build(const cv::Mat& states, const GridGeometry& geometry,
                        std::shared_ptr<const SemanticMap> rooms) {
  const auto t0 = std::chrono::steady_clock::now();
  if (kind_ == AnalysisMapKind::kSemantic) {
    semantic_.update(geometry, segmenter_.update(states, geometry).labels, states);
  } else {
    topology_ = builder_.update(states, geometry,
                                rooms    ? rooms.get()
                                : rooms_ ? rooms_->semanticMap()
                                         : nullptr);
  }
  update_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  const double res = geometry.resolution_m();
  update_known_m2_.push_back(static_cast<double>(maps::knownCellCount(states)) * res * res);
}

}  // namespace roomscout
