#include "roomscout/sim/analysis_maps_observer.hpp"

#include <chrono>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout::sim {

void AnalysisMapsOptions::validate() const {
  if (!(period_s > 0.0)) throw OptionError("maps.period_s must be > 0");
  if (!(min_new_area_m2 >= 0.0)) throw OptionError("maps.min_new_area_m2 must be >= 0");
  if (topology_every < 1) throw OptionError("maps.topology_every must be >= 1");
  segmentation.validate();
  topology.validate();
}

std::vector<ParameterRef> AnalysisMapsOptions::parameters() {
  return {
      {"period_s", &period_s, "simulated time between update checks [s]"},
      {"min_new_area_m2", &min_new_area_m2, "newly known area that triggers an update [m^2]"},
      {"topology_every", &topology_every, "rebuild the topological map on every n-th due update only"},
  };
}

AnalysisMapsObserver::AnalysisMapsObserver(AnalysisMapKind kind, const AnalysisMapsOptions& options,
                                           const AnalysisMapsObserver* rooms)
    : kind_(kind),
      options_(options),
      rooms_(rooms),
      segmenter_(options.segmentation),
      builder_(options.topology) {
  options_.validate();
}

std::string_view AnalysisMapsObserver::name() const {
  return kind_ == AnalysisMapKind::kSemantic ? "semantic" : "topological";
}

const SemanticMap* AnalysisMapsObserver::semanticMap() const {
  return kind_ == AnalysisMapKind::kSemantic ? &semantic_ : nullptr;
}

void AnalysisMapsObserver::onStep(const EpisodeSnapshot& snapshot) {
  changed_ = changed_ || snapshot.grid_changed;
  if (kind_ == AnalysisMapKind::kTopological && rooms_ != nullptr) {
    // Follow the schedule of the rooms that label the nodes: rebuild right after they were
    // rebuilt, instead of counting the known cells a second time for the same decision.
    if (rooms_->update_ms_.size() != rooms_updates_seen_) {
      rooms_updates_seen_ = rooms_->update_ms_.size();
      if (due_updates_++ % options_.topology_every == 0) update(snapshot.grid);
    }
    return;
  }
  if (snapshot.time_s + 1e-9 < next_update_s_ || !changed_) return;
  next_update_s_ = snapshot.time_s + options_.period_s;
  const std::size_t known = maps::knownCellCount(snapshot.grid);
  const double res = snapshot.grid.geometry().resolution_m();
  const double new_area_m2 =
      std::abs(static_cast<double>(known) - static_cast<double>(known_at_update_)) * res * res;
  if (updated_once_ && new_area_m2 < options_.min_new_area_m2) return;
  known_at_update_ = known;
  if (kind_ == AnalysisMapKind::kTopological && due_updates_++ % options_.topology_every != 0) return;
  update(snapshot.grid);
}

void AnalysisMapsObserver::onFinish(const EpisodeSnapshot& snapshot) {
  if (changed_ || snapshot.grid_changed || !updated_once_) update(snapshot.grid);
}

void AnalysisMapsObserver::update(const OccupancyGrid& grid) {
  const auto t0 = std::chrono::steady_clock::now();
  maps::stateImage(grid, states_);
  const cv::Mat& states = states_;
  if (kind_ == AnalysisMapKind::kSemantic) {
    const RoomSegmentation seg = segmenter_.segment(states, grid.geometry().resolution_m());
    semantic_.update(grid.geometry(), seg.labels, states);
  } else {
    const SemanticMap* rooms = rooms_ ? rooms_->semanticMap() : nullptr;
    topology_ = builder_.build(states, grid.geometry(), rooms);
  }
  update_ms_.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  changed_ = false;
  updated_once_ = true;
}

}  // namespace roomscout::sim
