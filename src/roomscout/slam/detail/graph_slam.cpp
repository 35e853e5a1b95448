#include "roomscout/slam/detail/graph_slam.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace roomscout::slam::detail {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

struct GraphSlam::Node {
  Pose2 global;              ///< optimised
  Pose2 odometry;            ///< where the odometry put it
  std::vector<Vec2> points;  ///< the scan's returns, sensor frame
  int graph_id = 0;
};

struct GraphSlam::SubmapEntry {
  explicit SubmapEntry(const Pose2& pose, const OccupancyGridOptions& cells)
      : submap(pose, cells) {}
  Submap submap;
  ProbabilityGrid probability;  ///< kept in step while the submap takes scans
  int probability_version = -1;
  std::unique_ptr<CorrelativeMatcher> matcher;  ///< built when first searched, once finished
  std::vector<int> nodes;
  int graph_id = 0;
  double odometry_var_m = 0.0;  ///< summed over its nodes: the odometry chain's variance
  double odometry_var_rad = 0.0;
};

GraphSlam::GraphSlam(const GraphSlamOptions& options, const OccupancyGridOptions& cells,
                     std::optional<GridGeometry> map_geometry)
    : options_(options), cells_(cells), graph_(options.graph) {
  if (map_geometry) {
    map_.emplace(*map_geometry, cells);
    sums_.assign(map_geometry->cellCount(), 0.0f);
  }
  samples_.reserve(1024);
}

GraphSlam::~GraphSlam() = default;

std::vector<Vec2> GraphSlam::pointsOf(const LaserScan& scan) const {
  std::vector<Vec2> points;
  points.reserve(scan.ranges_m.size());
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (!(std::isfinite(r) && r >= scan.range_min_m && r <= scan.range_max_m)) continue;
    const double a = scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
    points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return points;
}

void GraphSlam::addSubmap(const Pose2& at) {
  // The submap frame: the robot's position, on the map's cell lattice when there is a map,
  // unrotated, so that it renders onto the map cell for cell until optimisation moves it.
  Pose2 frame{at.x_m, at.y_m, 0.0};
  const double res = cells_.resolution_m;
  const Vec2 lattice = map_ ? map_->geometry().origin_m() : Vec2::Zero();
  frame.x_m = lattice.x() + std::round((at.x_m - lattice.x()) / res) * res;
  frame.y_m = lattice.y() + std::round((at.y_m - lattice.y()) / res) * res;
  auto entry = std::make_unique<SubmapEntry>(frame, cells_);
  entry->graph_id = graph_.addPose(frame);
  if (submaps_.empty()) graph_.fix(entry->graph_id);
  active_.push_back(static_cast<int>(submaps_.size()));
  submaps_.push_back(std::move(entry));
  ++stats_.submaps;
}

void GraphSlam::insertNode(const LaserScan& scan, const Pose2& odometry, const Pose2& estimate,
                           std::vector<Vec2> points, double sd_m, double sd_rad,
                           CellRect& changed) {
  const int id = static_cast<int>(nodes_.size());
  auto node = std::make_unique<Node>();
  node->global = estimate;
  node->odometry = odometry;
  node->points = std::move(points);
  node->graph_id = graph_.addPose(estimate);
  nodes_.push_back(std::move(node));
  ++stats_.nodes;

  if (active_.empty() || submaps_[active_.back()]->submap.scans() >= options_.submap_scans / 2) {
    addSubmap(estimate);
  }
  for (int s : active_) {
    SubmapEntry& e = *submaps_[s];
    const Pose2 local = between(e.submap.global_pose, estimate);
    const CellRect local_changed = e.submap.insert(scan, local);
    if (e.probability_version != e.submap.geometryVersion()) {
      e.probability = ProbabilityGrid(e.submap.grid());
      e.probability_version = e.submap.geometryVersion();
    } else {
      e.probability.update(e.submap.grid(), local_changed);
    }
    e.nodes.push_back(id);
    // A node sits in its submap as surely as the odometry chain since the submap began placed
    // it, at worst as the scan matcher does: with exact odometry a loop closure cannot shift a
    // submap under its nodes.
    e.odometry_var_m += sd_m * sd_m;
    e.odometry_var_rad += sd_rad * sd_rad;
    graph_.addConstraint({e.graph_id, nodes_[id]->graph_id, local,
                          std::min(options_.intra_sd_m, std::sqrt(e.odometry_var_m)),
                          std::min(options_.intra_sd_rad, std::sqrt(e.odometry_var_rad)), false});
    if (s % 2 == 0 && map_) changed.unite(renderSubmapRect(s, local_changed));
  }
  // The older submap is finished once full.
  std::erase_if(active_, [&](int s) {
    SubmapEntry& e = *submaps_[s];
    if (e.submap.scans() < options_.submap_scans) return false;
    e.submap.finished = true;
    return true;
  });
}

CellRect GraphSlam::update(const LaserScan& input, const Pose2& odometry) {
  const LaserScan scan =
      options_.max_range_m > 0.0 ? cappedToRange(input, options_.max_range_m) : input;
  std::vector<Vec2> points = pointsOf(scan);
  CellRect changed;

  if (nodes_.empty()) {
    // The odometry frame is the map frame until the first correction.
    insertNode(scan, odometry, odometry, std::move(points), options_.min_sd_m, options_.min_sd_rad,
               changed);
    samples_.push_back({0, Pose2{}});
    return changed;
  }
  const Node& last = *nodes_.back();
  const Pose2 delta = between(last.odometry, odometry);
  const double distance = std::hypot(delta.x_m, delta.y_m);
  const double turn = std::abs(delta.yaw_rad);
  if (distance < options_.node_distance_m && turn < options_.node_angle_rad) {
    samples_.push_back({static_cast<int>(nodes_.size()) - 1, delta});
    return changed;
  }

  // Predict from the odometry, then match against the older active submap. Even a node
  // reached by turning on the spot carries some position error (wheels slip as they turn):
  // a floor of 2 % of the per-metre errors, all but nothing for exact odometry.
  const Pose2 prediction = compose(last.global, delta);
  const double floor_m = options_.min_sd_m + 0.02 * options_.odometry_sd_per_m;
  const double floor_rad = options_.min_sd_rad + 0.02 * options_.odometry_rotation_sd_per_rad;
  const double turning_sd_rad = std::sqrt(
      options_.odometry_rotation_sd_per_rad * options_.odometry_rotation_sd_per_rad * turn +
      options_.odometry_rotation_sd_per_m * options_.odometry_rotation_sd_per_m * distance);
  const double sd_rad = std::hypot(floor_rad, turning_sd_rad);
  const double sd_m = std::hypot(
      floor_m,
      std::hypot(options_.odometry_sd_per_m * std::sqrt(distance), distance * turning_sd_rad));
  Pose2 estimate = prediction;
  const SubmapEntry& target = *submaps_[active_.front()];
  if (!points.empty()) {
    const Pose2 local_prediction = between(target.submap.global_pose, prediction);
    const ScanMatch m = matchScan(target.probability, target.submap.walls(), points,
                                  local_prediction, local_prediction, sd_m, sd_rad, options_.match);
    const double shift =
        std::hypot(m.pose.x_m - local_prediction.x_m, m.pose.y_m - local_prediction.y_m);
    const double rotation = std::abs(wrapAngle(m.pose.yaw_rad - local_prediction.yaw_rad));
    const bool consistent = shift <= options_.max_innovation_sd * sd_m &&
                            rotation <= options_.max_innovation_sd * sd_rad;
    if (m.accepted && consistent) {
      estimate = compose(target.submap.global_pose, m.pose);
      if (m.degenerate) ++stats_.matches_degenerate;
    } else {
      ++stats_.matches_rejected;
    }
  } else {
    ++stats_.matches_rejected;
  }
  const int previous_graph_id = last.graph_id;
  insertNode(scan, odometry, estimate, std::move(points), sd_m, sd_rad, changed);
  const int id = static_cast<int>(nodes_.size()) - 1;
  // The odometry between consecutive nodes, as uncertain as the odometry model says: with
  // good odometry a loop closure cannot bend the chain further than the odometry allows.
  graph_.addConstraint({previous_graph_id, nodes_[id]->graph_id, delta, sd_m, sd_rad, false});
  samples_.push_back({id, Pose2{}});

  if (options_.loop_every_n_nodes > 0 && id % options_.loop_every_n_nodes == 0) {
    searchLoopClosures(id);
  }
  ++nodes_since_optimisation_;
  if (pending_loops_ && nodes_since_optimisation_ >= options_.optimise_every_n_nodes) {
    changed.unite(optimise());
  }
  return changed;
}

void GraphSlam::searchLoopClosures(int id) {
  const auto t0 = Clock::now();
  const Node& node = *nodes_[id];
  if (node.points.size() < static_cast<std::size_t>(options_.match.min_points_on_walls)) return;
  // Finished submaps whose scans were taken near this node, nearest first, leaving out those
  // the last submap's worth of nodes went into (the local chain already ties them).
  std::vector<std::pair<double, int>> candidates;
  for (int s = 0; s < static_cast<int>(submaps_.size()); ++s) {
    const SubmapEntry& e = *submaps_[s];
    if (!e.submap.finished || e.nodes.back() >= id - options_.submap_scans) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (int n : e.nodes) {
      nearest = std::min(nearest, (nodes_[n]->global.position() - node.global.position()).norm());
    }
    if (nearest <= options_.loop_search_distance_m) candidates.emplace_back(nearest, s);
  }
  std::sort(candidates.begin(), candidates.end());
  if (candidates.size() > static_cast<std::size_t>(options_.loop_max_candidates)) {
    candidates.resize(static_cast<std::size_t>(options_.loop_max_candidates));
  }
  for (const auto& [distance, s] : candidates) {
    SubmapEntry& e = *submaps_[s];
    if (!e.matcher) {
      e.matcher = std::make_unique<CorrelativeMatcher>(e.probability, options_.loop_search_depth);
    }
    const Pose2 center = between(e.submap.global_pose, node.global);
    const auto found = e.matcher->match(node.points, center, options_.loop_window_m,
                                        options_.loop_window_rad, options_.loop_min_score);
    if (!found) continue;
    // Refine from the search's answer (known to a cell), then verify. Where the walls leave
    // the pose free within their cells, the weak prior keeps it nearest the current estimate.
    const ScanMatch m = matchScan(e.probability, e.submap.walls(), node.points, found->pose, center,
                                  options_.loop_window_m, options_.loop_window_rad, options_.match);
    if (!m.accepted || m.degenerate || m.score < options_.loop_min_score) continue;
    graph_.addConstraint(
        {e.graph_id, node.graph_id, m.pose, options_.loop_sd_m, options_.loop_sd_rad, true});
    ++stats_.loop_closures;
    pending_loops_ = true;
  }
  stats_.loop_search_ms.push_back(msSince(t0));
}

CellRect GraphSlam::optimise() {
  const auto t0 = Clock::now();
  pending_loops_ = false;
  nodes_since_optimisation_ = 0;
  CellRect changed;
  if (!graph_.optimise()) return changed;
  ++stats_.optimisations;
  double moved = 0.0;
  for (std::size_t s = 0; s < submaps_.size(); ++s) {
    SubmapEntry& e = *submaps_[s];
    const Pose2& p = graph_.pose(e.graph_id);
    if (s % 2 == 0) {
      moved = std::max({moved, (p.position() - e.submap.global_pose.position()).norm(),
                        std::abs(wrapAngle(p.yaw_rad - e.submap.global_pose.yaw_rad))});
    }
    e.submap.global_pose = p;
  }
  for (auto& n : nodes_) n->global = graph_.pose(n->graph_id);
  // Re-render when any submap of the map moved by more than a hundredth of a cell.
  if (map_ && moved > 0.01 * cells_.resolution_m) changed = render(map_->geometry().bounds());
  stats_.optimise_ms.push_back(msSince(t0));
  return changed;
}

CellRect GraphSlam::finish() {
  if (!pending_loops_) return {};
  return optimise();
}

CellRect GraphSlam::renderSubmapRect(int s, const CellRect& local) {
  if (local.empty()) return {};
  const Submap& submap = submaps_[s]->submap;
  const GridGeometry& lg = submap.grid().geometry();
  const GridGeometry& mg = map_->geometry();
  const double res = lg.resolution_m();
  const std::array<Vec2, 4> corners = {Vec2(lg.origin_m() + Vec2(local.min_x, local.min_y) * res),
                                       Vec2(lg.origin_m() + Vec2(local.max_x, local.min_y) * res),
                                       Vec2(lg.origin_m() + Vec2(local.min_x, local.max_y) * res),
                                       Vec2(lg.origin_m() + Vec2(local.max_x, local.max_y) * res)};
  CellRect global;
  for (const Vec2& corner : corners) {
    const Cell c = mg.cellOf(transformPoint(submap.global_pose, corner));
    global.unite(CellRect{c.x - 1, c.y - 1, c.x + 2, c.y + 2});
  }
  return render(global.clippedTo(mg.width(), mg.height()));
}

CellRect GraphSlam::render(const CellRect& rect) {
  if (rect.empty()) return rect;
  const GridGeometry& mg = map_->geometry();
  for (int y = rect.min_y; y < rect.max_y; ++y)
    std::fill_n(sums_.begin() + static_cast<std::ptrdiff_t>(mg.index(Cell{rect.min_x, y})),
                rect.max_x - rect.min_x, 0.0f);
  for (std::size_t s = 0; s < submaps_.size(); s += 2) {
    const Submap& submap = submaps_[s]->submap;
    const GridGeometry& lg = submap.grid().geometry();
    // The submap's extent in map cells, within the rectangle.
    CellRect box;
    const Vec2 lo = lg.origin_m();
    const Vec2 hi = lo + Vec2(lg.width(), lg.height()) * lg.resolution_m();
    const std::array<Vec2, 4> corners = {lo, Vec2(hi.x(), lo.y()), Vec2(lo.x(), hi.y()), hi};
    for (const Vec2& corner : corners) {
      const Cell c = mg.cellOf(transformPoint(submap.global_pose, corner));
      box.unite(CellRect{c.x - 1, c.y - 1, c.x + 2, c.y + 2});
    }
    box = CellRect{std::max(box.min_x, rect.min_x), std::max(box.min_y, rect.min_y),
                   std::min(box.max_x, rect.max_x), std::min(box.max_y, rect.max_y)};
    if (box.empty()) continue;
    // Each map cell's centre, in the submap's frame: the cell it falls in.
    const Pose2 to_local = inverse(submap.global_pose);
    const double c = std::cos(to_local.yaw_rad), sn = std::sin(to_local.yaw_rad);
    const OccupancyGrid& grid = submap.grid();
    for (int y = box.min_y; y < box.max_y; ++y) {
      for (int x = box.min_x; x < box.max_x; ++x) {
        const Vec2 p = mg.centerOf(Cell{x, y});
        const Vec2 q(to_local.x_m + c * p.x() - sn * p.y(), to_local.y_m + sn * p.x() + c * p.y());
        const Cell lc = lg.cellOf(q);
        if (!lg.contains(lc)) continue;
        sums_[mg.index(Cell{x, y})] += grid.logOdds(lg.index(lc));
      }
    }
  }
  OccupancyGrid& map = *map_;
  for (int y = rect.min_y; y < rect.max_y; ++y) {
    for (int x = rect.min_x; x < rect.max_x; ++x) {
      const std::size_t i = mg.index(Cell{x, y});
      map.setLogOdds(i, sums_[i]);
    }
  }
  return rect;
}

Pose2 GraphSlam::pose(const Pose2& odometry) const {
  if (nodes_.empty()) return odometry;
  const Node& last = *nodes_.back();
  return compose(last.global, between(last.odometry, odometry));
}

std::vector<Pose2> GraphSlam::trajectory() const {
  std::vector<Pose2> poses;
  poses.reserve(samples_.size());
  for (const Sample& s : samples_)
    poses.push_back(compose(nodes_[s.node]->global, s.odometry_since));
  return poses;
}

}  // namespace roomscout::slam::detail
