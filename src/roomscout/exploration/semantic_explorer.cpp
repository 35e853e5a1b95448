#include "roomscout/exploration/detail/semantic_explorer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/random.hpp"
#include "roomscout/exploration/frontier_cells.hpp"
#include "roomscout/maps/semantic_map.hpp"

namespace roomscout {

void SemanticExplorerOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finiteAtLeast(k, 0.0)) throw OptionError("semantic.k must be >= 0");
  if (!finiteAtLeast(gain_weight, 0.0) || !finiteAtLeast(cost_weight, 0.0)) {
    throw OptionError("semantic: gain_weight and cost_weight must be >= 0");
  }
  if (!finiteAtLeast(room_reward, 0.0)) throw OptionError("semantic.room_reward must be >= 0");
  if (!positive(gain_half_side_m)) throw OptionError("semantic.gain_half_side_m must be > 0");
  if (!finiteAtLeast(min_unknown_m2, 0.0))
    throw OptionError("semantic.min_unknown_m2 must be >= 0");
  if (!finiteAtLeast(goal_min_unknown_m2, 0.0))
    throw OptionError("semantic.goal_min_unknown_m2 must be >= 0");
  if (!finiteAtLeast(pocket_area_m2, 0.0))
    throw OptionError("semantic.pocket_area_m2 must be >= 0");
  if (!finiteAtLeast(pocket_area_fraction, 0.0)) {
    throw OptionError("semantic.pocket_area_fraction must be >= 0");
  }
  if (!finiteAtLeast(min_frontier_m, 0.0))
    throw OptionError("semantic.min_frontier_m must be >= 0");
  if (!positive(eta_m)) throw OptionError("semantic.eta_m must be > 0");
  if (!positive(iterations_per_s)) throw OptionError("semantic.iterations_per_s must be > 0");
  if (!finiteAtLeast(replan_period_s, 0.0))
    throw OptionError("semantic.replan_period_s must be >= 0");
  if (!finiteAtLeast(switch_margin, 0.0)) throw OptionError("semantic.switch_margin must be >= 0");
  if (!finiteAtLeast(label_search_m, 0.0))
    throw OptionError("semantic.label_search_m must be >= 0");
  if (!finiteAtLeast(blacklist_radius_m, 0.0))
    throw OptionError("semantic.blacklist_radius_m must be >= 0");
  if (!positive(end_check_period_s)) throw OptionError("semantic.end_check_period_s must be > 0");
  if (end_checks < 1 || end_min_frontier_cells < 1) {
    throw OptionError("semantic: end_checks and end_min_frontier_cells must be >= 1");
  }
  if (!finiteAtLeast(end_pocket_area_m2, 0.0))
    throw OptionError("semantic.end_pocket_area_m2 must be >= 0");
  if (!finiteAtLeast(observed_radius_m, 0.0))
    throw OptionError("semantic.observed_radius_m must be >= 0");
  if (!finiteAtLeast(idle_end_s, 0.0)) throw OptionError("semantic.idle_end_s must be >= 0");
  if (max_iterations_per_call < 1)
    throw OptionError("semantic.max_iterations_per_call must be >= 1");
  if (hub_min_neighbours < 0) throw OptionError("semantic.hub_min_neighbours must be >= 0");
  if (!finiteAtLeast(next_room_cost_factor, 0.0))
    throw OptionError("semantic.next_room_cost_factor must be >= 0");
  if (!finiteAtLeast(hub_sample_radius_m, 0.0))
    throw OptionError("semantic.hub_sample_radius_m must be >= 0");
  if (!finiteAtLeast(heading_weight, 0.0))
    throw OptionError("semantic.heading_weight must be >= 0");
  if (!finiteAtLeast(segment_weight, 0.0))
    throw OptionError("semantic.segment_weight must be >= 0");
  if (!finiteAtLeast(segment_cap_m, 0.0)) throw OptionError("semantic.segment_cap_m must be >= 0");
  if (!finiteAtLeast(mass_weight, 0.0)) throw OptionError("semantic.mass_weight must be >= 0");
  if (!positive(mass_half_side_m)) throw OptionError("semantic.mass_half_side_m must be > 0");
  if (!finiteAtLeast(mass_cap_m, 0.0)) throw OptionError("semantic.mass_cap_m must be >= 0");
}

SemanticExplorerOptions SemanticExplorerOptions::paper() {
  SemanticExplorerOptions o;
  // The tree of improved_rrt (ImprovedRrtOptions: eta_m 1 m, 100 iterations /s).
  o.eta_m = 1.0;
  o.iterations_per_s = 100.0;
  // C as the paper states it: the Euclidean distance.
  o.geodesic_cost = false;
  // Every addition of `semantic` off (see the header).
  o.min_unknown_m2 = 0.0;
  o.min_frontier_m = 0.0;
  o.pocket_area_m2 = 0.0;
  o.pocket_area_fraction = 0.0;
  o.label_search_m = 0.0;
  o.hub_min_neighbours = 0;
  o.next_room_cost_factor = 1.0;
  o.mass_weight = 0.0;
  o.heading_weight = 0.0;
  o.segment_weight = 0.0;
  o.leaf_rooms = false;
  o.idle_end_s = 0.0;
  // improved_rrt's end test, pocket search included (its min_unknown_area_m2): without the end
  // phase nothing else leaves out the frontier cells of cupboards and wall cracks that no tree
  // point leads to, and the robot would wait for the end test until the time limit.
  o.end_pocket_area_m2 = 4.0;
  // Kept to run and to end, at `semantic`'s values: goal persistence (goal_min_unknown_m2,
  // replan_period_s, switch_margin), the blacklist (blacklist_radius_m) and the end test
  // (end_check_period_s, end_checks, end_min_frontier_cells, observed_radius_m, and the pocket
  // search above).
  return o;
}

std::vector<ParameterRef> SemanticExplorerOptions::parameters() {
  return {
      {"k", &k,
       "weight of t, the time since the robot's room last changed, in P(P_sem) = kt/(1+kt) "
       "(paper Eq. 1); 0 = P_rad only, uniform sampling [1/s]"},
      {"gain_weight", &gain_weight,
       "w_g: weight of G, the (unknown - occupied) area in the square of half-side "
       "gain_half_side_m around the point [1/m^2]"},
      {"cost_weight", &cost_weight,
       "w_c: weight of C, the distance from the robot to the point (see geodesic_cost) [1/m]"},
      {"room_reward", &room_reward,
       "A: added to the score of a point whose anchor lies in the robot's room, subtracted "
       "elsewhere (a point in no room counts as elsewhere); 0 = plain score"},
      {"gain_half_side_m", &gain_half_side_m,
       "half-side of the square around a point in which G, slivers and the goal's persistence "
       "are measured [m]"},
      {"min_unknown_m2", &min_unknown_m2,
       "slivers: a point with less unknown area in its square is a goal only once idle "
       "(idle_end_s), and a frontier cell with less is no P_sem; 0 = off [m^2]"},
      {"goal_min_unknown_m2", &goal_min_unknown_m2,
       "goal persistence: the goal is kept until its square holds less unknown area than this "
       "(or it is reached, fails or turns lethal); 0 = until then [m^2]"},
      {"min_frontier_m", &min_frontier_m,
       "slivers: a point with less frontier (free cells next to unknown x cell size) in its "
       "square is a goal only once idle, and the goal's square counts as explored with less; 0 "
       "= off [m]"},
      {"pocket_area_m2", &pocket_area_m2,
       "slivers: a point opening onto less enclosed unknown, non-lethal area (4-connected) is a "
       "goal only once idle, and the end phase skips such cells; 0 = off [m^2]"},
      {"pocket_area_fraction", &pocket_area_fraction,
       "once idle, a pocket must also be smaller than this fraction of the known free area (in a "
       "small flat a wedge of floor seen past a door jamb is no cupboard); 0 = pocket_area_m2 "
       "alone"},
      {"geodesic_cost", &geodesic_cost,
       "C is the path length past the costmap's lethal cells; false = the Euclidean distance, "
       "as in the paper"},
      {"eta_m", &eta_m, "tree step [m]"},
      {"iterations_per_s", &iterations_per_s, "tree iterations per simulated second [1/s]"},
      {"replan_period_s", &replan_period_s,
       "period at which the goal may be replaced while the robot drives to it [s]"},
      {"switch_margin", &switch_margin,
       "another point must beat the goal's score by this much to replace it"},
      {"label_search_m", &label_search_m,
       "a free cell the segmentation has not labelled yet takes the room of the nearest labelled "
       "cell this far through free cells; 0 = off (an unlabelled cell is in no room) [m]"},
      {"blacklist_radius_m", &blacklist_radius_m,
       "reached or failed goals drop frontier points this close [m]"},
      {"end_check_period_s", &end_check_period_s, "period of the end test [s]"},
      {"end_checks", &end_checks, "consecutive failing end tests that end the exploration"},
      {"end_min_frontier_cells", &end_min_frontier_cells,
       "an end test fails when fewer reachable frontier cells are left"},
      {"end_pocket_area_m2", &end_pocket_area_m2,
       "the end test leaves out, for good, frontier cells opening onto less enclosed unknown, "
       "non-lethal area (improved_rrt's min_unknown_area_m2, searched every 10 s); 0 = off "
       "[m^2]"},
      {"observed_radius_m", &observed_radius_m,
       "the end test and the end phase ignore frontier cells that stayed unknown with the robot "
       "this close [m]"},
      {"idle_end_s", &idle_end_s,
       "with nothing to assign for this long the robot takes its room's slivers, then visits "
       "the remaining reachable frontier cells (end phase); 0 = off: it waits for the tree and "
       "the end test [s]"},
      {"max_iterations_per_call", &max_iterations_per_call,
       "cap on the owed tree iterations run in one call"},
      {"hub_min_neighbours", &hub_min_neighbours,
       "a room with this many neighbouring rooms is a hub (a hallway): no +-A there, P_sem near "
       "the robot (hub_sample_radius_m), C weighed by next_room_cost_factor; 0 = off"},
      {"next_room_cost_factor", &next_room_cost_factor,
       "choosing the next room (in a hub, or no point left in the room but slivers): C weighs "
       "this many times w_c; 1 = off"},
      {"hub_sample_radius_m", &hub_sample_radius_m,
       "in a hub, P_sem is drawn from the frontier cells (of any room) in the square of this "
       "half-side around the robot; 0 = no P_sem in a hub [m]"},
      {"heading_weight", &heading_weight,
       "S -= heading_weight (1 - cos d) / 2, d the angle between the robot's heading and the "
       "line to the point: turning back costs this much (the current goal never pays it); 0 = "
       "off"},
      {"segment_weight", &segment_weight,
       "S += segment_weight min(L, segment_cap_m), L the length of the frontier segment the "
       "point opens onto; 0 = off [1/m]"},
      {"segment_cap_m", &segment_cap_m, "cap on L, the frontier segment's length [m]"},
      {"mass_weight", &mass_weight,
       "choosing the next room: S += mass_weight min(M, mass_cap_m), M the frontier (free cells "
       "next to unknown x cell size) in the square of half-side mass_half_side_m around the "
       "point; 0 = off [1/m]"},
      {"mass_half_side_m", &mass_half_side_m, "half-side of the square M is counted in [m]"},
      {"mass_cap_m", &mass_cap_m, "cap on M [m]"},
      {"leaf_rooms", &leaf_rooms,
       "a room whose only neighbour is the current room, while the current room has another, "
       "counts as part of it (+A for its points, P_sem from its frontier); false = off"},
  };
}

double semanticSampleProbability(double k, double t_s) {
  const double kt = k * std::max(0.0, t_s);
  return kt / (1.0 + kt);
}

namespace {

/// Unknown space that reaches the known map's border through an opening this wide is no
/// pocket, whatever its area: it may go on beyond the map (improved_rrt's min_opening_m).
constexpr double kPocketOpening_m = EndTestPockets{}.min_opening_m;
/// Geodesic C is searched on blocks of this many cells a side (0.1 m at 0.05 m cells).
constexpr int kBlock = 2;

/// A frontier cell as this strategy counts them: known free, with an unknown 4-neighbour.
bool freeBesideUnknown(const OccupancyGrid& grid, int x, int y) {
  const int w = grid.geometry().width(), h = grid.geometry().height();
  const std::size_t i = static_cast<std::size_t>(y) * w + x;
  return grid.isFree(i) &&
         ((x > 0 && grid.isUnknown(i - 1)) || (x + 1 < w && grid.isUnknown(i + 1)) ||
          (y > 0 && grid.isUnknown(i - w)) || (y + 1 < h && grid.isUnknown(i + w)));
}

/// Unknown and occupied areas [m^2] in the square of half-side `half_m` centred on `p`'s cell,
/// and its frontier cells (free, with an unknown 4-neighbour; the grid's border cells are not
/// counted) up to `frontier_cap`: only whether a square holds that many matters.
struct SquareAreas {
  double unknown_m2 = 0.0;
  double occupied_m2 = 0.0;
  int frontier_cells = 0;
};

SquareAreas squareAreas(const OccupancyGrid& grid, const Vec2& p, double half_m,
                        int frontier_cap = 0) {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(p);
  const int r = static_cast<int>(std::lround(half_m / g.resolution_m()));
  const int w = g.width();
  const int x0 = std::max(0, c.x - r), x1 = std::min(w - 1, c.x + r);
  const int y0 = std::max(0, c.y - r), y1 = std::min(g.height() - 1, c.y + r);
  int unknown = 0, occupied = 0, frontier = 0;
  for (int y = y0; y <= y1; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (int x = x0; x <= x1; ++x) {
      const CellState s = grid.state(row + x);
      unknown += s == CellState::kUnknown;
      occupied += s == CellState::kOccupied;
    }
  }
  // Rows from the centre outwards: a frontier point's own frontier is near it, so a square
  // with enough frontier is usually told after a few rows.
  for (int k = 0; frontier < frontier_cap && k <= 2 * r; ++k) {
    const int y = c.y + (k % 2 == 0 ? k / 2 : -(k + 1) / 2);
    if (y < std::max(1, y0) || y > std::min(g.height() - 2, y1)) continue;
    for (int x = std::max(1, x0); x <= std::min(w - 2, x1) && frontier < frontier_cap; ++x) {
      frontier += freeBesideUnknown(grid, x, y);
    }
  }
  const double cell_m2 = g.resolution_m() * g.resolution_m();
  return {unknown * cell_m2, occupied * cell_m2, frontier};
}

/// The frontier cells a square must hold not to be exhausted.
int frontierCellsWanted(const SemanticExplorerOptions& o, double resolution_m) {
  return static_cast<int>(std::lround(o.min_frontier_m / resolution_m));
}

/// Whether a square holds too little to see to be worth a trip: less than `min_unknown_m2` of
/// unknown space (the sliver threshold or the goal's), or less than min_frontier_m of frontier
/// (its unknown space lies behind walls already seen, e.g. outside a room corner, and cannot be
/// seen from there).
bool exhausted(const SquareAreas& a, const SemanticExplorerOptions& o, double min_unknown_m2,
               double resolution_m) {
  return a.unknown_m2 < min_unknown_m2 || a.frontier_cells < frontierCellsWanted(o, resolution_m);
}

}  // namespace

template <class Test>
void SemanticExplorer::CellCounts::build(int x0, int y0, int x1, int y1, Test test) {
  x0_ = x0;
  y0_ = y0;
  x1_ = x1;
  y1_ = y1;
  mask_.create(y1 - y0 + 1, x1 - x0 + 1, CV_8U);
  for (int y = y0; y <= y1; ++y) {
    auto* row = mask_.ptr<std::uint8_t>(y - y0);
    for (int x = x0; x <= x1; ++x) row[x - x0] = test(x, y) ? 1 : 0;
  }
  cv::integral(mask_, sums_, CV_32S);
}

int SemanticExplorer::CellCounts::square(int cx, int cy, int r) const {
  const int qx0 = std::clamp(cx - r, x0_, x1_ + 1) - x0_,
            qx1 = std::clamp(cx + r + 1, x0_, x1_ + 1) - x0_;
  const int qy0 = std::clamp(cy - r, y0_, y1_ + 1) - y0_,
            qy1 = std::clamp(cy + r + 1, y0_, y1_ + 1) - y0_;
  auto at = [&](int x, int y) { return sums_.at<int>(y, x); };
  return at(qx1, qy1) - at(qx0, qy1) - at(qx1, qy0) + at(qx0, qy0);
}

SemanticExplorer::SemanticExplorer(std::uint64_t seed, const SemanticExplorerOptions& options,
                                   std::string name)
    : options_(options), name_(std::move(name)), rng_(seed) {}

SemanticExplorer::~SemanticExplorer() = default;

double SemanticExplorer::score(double gain_m2, double cost_m, bool in_current_room) const {
  const double base = options_.gain_weight * gain_m2 - options_.cost_weight * cost_m;
  if (hub_) return base;
  return in_current_room ? base + options_.room_reward : base - options_.room_reward;
}

bool SemanticExplorer::blacklisted(const Vec2& p) const {
  const double r2 = options_.blacklist_radius_m * options_.blacklist_radius_m;
  return std::any_of(blacklist_.begin(), blacklist_.end(),
                     [&](const Vec2& b) { return (b - p).squaredNorm() < r2; });
}

void SemanticExplorer::onGoalReached(const Vec2& goal_m) { onGoalFailed(goal_m); }

void SemanticExplorer::onGoalFailed(const Vec2& goal_m) {
  // Reached while still unknown (unobservable from there) or unreachable: not sent again.
  if (has_goal_ && (goal_m - goal_m_).norm() < 1e-9) blacklist_.push_back(goal_m);
  has_goal_ = false;
  if (end_cell_ && (goal_m - *end_cell_).norm() < 1e-9) {
    end_cells_done_.push_back(*end_cell_);
    end_cell_.reset();
  }
}

std::optional<Vec2> SemanticExplorer::endPhaseCell(const ExplorationInput& input) {
  const GridGeometry& g = input.grid.geometry();
  // A cell reached, or failed from close by, was looked at: the disc around it is done. One
  // failed from afar (the stall watchdog fails whatever goal is current when the robot has
  // idled, even one just set) says nothing of its neighbours, so only the cell is done.
  const Vec2 robot = input.robot.position();
  for (const Vec2& f : end_cells_done_) {
    const bool near = (f - robot).norm() <= options_.observed_radius_m;
    markDisc(visited_, g, f, near ? options_.observed_radius_m : 0.5 * g.resolution_m());
  }
  end_cells_done_.clear();
  if (end_cell_ && g.contains(*end_cell_)) {
    const std::size_t i = g.index(g.cellOf(*end_cell_));
    if (input.grid.isUnknown(i) && !visited_[i] && !input.costmap.isLethal(i)) return end_cell_;
  }
  end_cell_.reset();
  const std::vector<Cell> cells =
      reachableFrontierCells(input.grid, input.costmap, 4, &visited_, &robot);
  // Not those opening onto a pocket (pocketArea_m2: relative to the map by now).
  std::vector<std::uint8_t> pockets;
  if (options_.pocket_area_m2 > 0.0) {
    markUnknownPockets(pockets, input.grid, input.costmap, cells, pocketArea_m2(input.grid),
                       kPocketOpening_m);
  }
  // Nearest by C (the path length with geodesic_cost): in a straight line the nearest cell may
  // lie behind a wall, in the next room.
  std::vector<Candidate>& cands = candidates_scored_;
  cands.clear();
  for (const Cell& c : cells) {
    if (pockets.empty() || !pockets[g.index(c)])
      cands.push_back({g.centerOf(c), 0, 0.0, false, false});
  }
  cost(input, cands, 1.0);
  double best_m = std::numeric_limits<double>::infinity();
  for (const Candidate& c : cands) {
    if (c.cost_m < best_m) {
      best_m = c.cost_m;
      end_cell_ = c.p;
    }
  }
  return end_cell_;
}

bool SemanticExplorer::stale(const ExplorationInput& input, const Vec2& p) const {
  const GridGeometry& g = input.grid.geometry();
  const Cell c = g.cellOf(p);
  if (!g.contains(c)) return true;
  const std::size_t i = g.index(c);
  return !input.grid.isUnknown(i) || input.costmap.isLethal(i);
}

bool SemanticExplorer::goalExplored(const ExplorationInput& input) const {
  if (blacklisted(goal_m_)) return true;
  const GridGeometry& g = input.grid.geometry();
  if (!g.contains(g.cellOf(goal_m_))) return true;
  const SquareAreas a = squareAreas(input.grid, goal_m_, options_.gain_half_side_m,
                                    frontierCellsWanted(options_, g.resolution_m()));
  return exhausted(a, options_, options_.goal_min_unknown_m2, g.resolution_m());
}

double SemanticExplorer::segmentLength(const OccupancyGrid& grid, const Vec2& p) const {
  const GridGeometry& g = grid.geometry();
  const int w = g.width(), h = g.height();
  // The segments of the frontier cells within two cells of p (p is unknown, its frontier runs
  // beside it), each followed through its 8-connected frontier cells until it is known to be
  // at least segment_cap_m long.
  const std::size_t cap =
      static_cast<std::size_t>(std::ceil(options_.segment_cap_m / g.resolution_m()));
  const Cell c = g.cellOf(p);
  segment_seen_.begin(g.cellCount());
  std::size_t longest = 0;
  for (int sy = std::max(0, c.y - 2); sy <= std::min(h - 1, c.y + 2); ++sy) {
    for (int sx = std::max(0, c.x - 2); sx <= std::min(w - 1, c.x + 2); ++sx) {
      const std::size_t s = static_cast<std::size_t>(sy) * w + sx;
      if (segment_seen_.marked(s) || !freeBesideUnknown(grid, sx, sy)) continue;
      segment_queue_.assign(1, Cell{sx, sy});
      segment_seen_.mark(s);
      for (std::size_t head = 0; head < segment_queue_.size() && segment_queue_.size() < cap;
           ++head) {
        const Cell q = segment_queue_[head];
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = q.x + dx, y = q.y + dy;
            if (x < 0 || y < 0 || x >= w || y >= h) continue;
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (segment_seen_.marked(i) || !freeBesideUnknown(grid, x, y)) continue;
            segment_seen_.mark(i);
            segment_queue_.push_back(Cell{x, y});
          }
        }
      }
      longest = std::max(longest, std::min(cap, segment_queue_.size()));
      if (longest >= cap) return options_.segment_cap_m;
    }
  }
  return std::min(options_.segment_cap_m, static_cast<double>(longest) * g.resolution_m());
}

int SemanticExplorer::roomOf(const ExplorationInput& input, const Vec2& p) const {
  if (input.semantic == nullptr) return 0;
  const SemanticMap& map = *input.semantic;
  const int id = map.roomAt(p);
  if (id != 0) return id;
  // A cell seen since the segmentation's last update has no label yet: it belongs to the room
  // of the nearest labelled cell reached through known-free cells within label_search_m (a
  // breadth-first search, nearest first; unknown space is in no room). Through free cells, not
  // the straight line: the fresh end of a corridor belongs to the corridor's room, not to the
  // room behind its wall.
  const GridGeometry& g = input.grid.geometry();
  const Cell c = g.cellOf(p);
  if (!g.contains(c) || !input.grid.isFree(g.index(c))) return 0;
  const int r = static_cast<int>(std::ceil(options_.label_search_m / g.resolution_m()));
  label_seen_.begin(g.cellCount());
  label_queue_.clear();
  label_queue_.push_back({c, 0});
  label_seen_.mark(g.index(c));
  for (std::size_t head = 0; head < label_queue_.size(); ++head) {
    const auto [q, steps] = label_queue_[head];
    if (head > 0) {
      if (const int label = map.roomAt(g.centerOf(q)); label != 0) return label;
    }
    if (steps >= r) continue;
    for (const Cell n :
         {Cell{q.x + 1, q.y}, Cell{q.x - 1, q.y}, Cell{q.x, q.y + 1}, Cell{q.x, q.y - 1}}) {
      if (!g.contains(n)) continue;
      const std::size_t i = g.index(n);
      if (label_seen_.marked(i) || !input.grid.isFree(i)) continue;
      label_seen_.mark(i);
      label_queue_.push_back({n, steps + 1});
    }
  }
  return 0;
}

void SemanticExplorer::updateRoom(const ExplorationInput& input) {
  const int room = roomOf(input, input.robot.position());
  // In a doorway or an unlabelled patch the robot stays in the room it was in.
  if (room != 0 && room != room_) {
    room_ = room;
    room_since_s_ = input.time_s;
  }
  time_in_room_s_ = room_ != 0 ? input.time_s - room_since_s_ : 0.0;
  const SemanticRegion* region =
      room_ != 0 && input.semantic != nullptr ? input.semantic->region(room_) : nullptr;
  hub_ = region != nullptr && options_.hub_min_neighbours > 0 &&
         static_cast<int>(region->neighbours.size()) >= options_.hub_min_neighbours;
  // Leaves: rooms that open onto the current room alone, while the current room has another way
  // out (in a world of two rooms neither is a leaf of the other).
  leaves_.clear();
  if (options_.leaf_rooms && region != nullptr && region->neighbours.size() >= 2) {
    for (const int n : region->neighbours) {
      const SemanticRegion* other = input.semantic->region(n);
      if (other != nullptr && other->neighbours.size() == 1 && other->neighbours.front() == room_) {
        leaves_.push_back(n);
      }
    }
  }
}

bool SemanticExplorer::inCurrentRoom(int room) const {
  return room != 0 &&
         (room == room_ || std::find(leaves_.begin(), leaves_.end(), room) != leaves_.end());
}

void SemanticExplorer::collectCandidates(const ExplorationInput& input) {
  candidates_.clear();
  const GridGeometry& g = input.grid.geometry();
  if (room_ == 0 || input.semantic == nullptr) return;
  // In a hub, P_sem is any frontier cell near the robot, whatever its room (see the header).
  const bool local = hub_;
  if (local && options_.hub_sample_radius_m <= 0.0) return;
  Vec2 lo, hi;
  if (local) {
    const Vec2 r(options_.hub_sample_radius_m, options_.hub_sample_radius_m);
    lo = input.robot.position() - r;
    hi = input.robot.position() + r;
  } else {
    const SemanticRegion* region = input.semantic->region(room_);
    if (region == nullptr || region->polygon_m.empty()) return;
    lo = region->polygon_m.front();
    hi = lo;
    for (const Vec2& v : region->polygon_m) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    // The room's leaves (see leaf_rooms) are part of it.
    for (const int n : leaves_) {
      for (const Vec2& v : input.semantic->region(n)->polygon_m) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
    }
  }
  // Cells labelled by the search for a label lie up to label_search_m outside the room's box.
  const double pad = (local ? 0.0 : options_.label_search_m) + g.resolution_m();
  const Cell a = g.cellOf(lo - Vec2(pad, pad));
  const Cell b = g.cellOf(hi + Vec2(pad, pad));
  const int w = g.width();
  const int x0 = std::max(1, a.x), x1 = std::min(w - 2, b.x);
  const int y0 = std::max(1, a.y), y1 = std::min(g.height() - 2, b.y);
  if (x0 > x1 || y0 > y1) return;
  // Unknown cells counted over the box grown by G's square, so that a frontier cell whose
  // square holds less than min_unknown_m2 of unknown space (a sliver) is no candidate.
  const int r = static_cast<int>(std::lround(options_.gain_half_side_m / g.resolution_m()));
  counts_.build(std::max(0, x0 - r), std::max(0, y0 - r), std::min(w - 1, x1 + r),
                std::min(g.height() - 1, y1 + r), [&](int x, int y) {
                  return input.grid.isUnknown(static_cast<std::size_t>(y) * w + x);
                });
  const double cell_m2 = g.resolution_m() * g.resolution_m();
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!freeBesideUnknown(input.grid, x, y) || input.costmap.isLethal(i)) continue;
      if (counts_.square(x, y, r) * cell_m2 < options_.min_unknown_m2) continue;
      const Vec2 p = g.centerOf(Cell{x, y});
      if (local || inCurrentRoom(roomOf(input, p))) candidates_.push_back(p);
    }
  }
}

void SemanticExplorer::grow(const ExplorationInput& input, long iterations) {
  const GridGeometry& g = input.grid.geometry();
  Vec2 box_min, box_max;
  // Unpadded: with the 5 cells improved_rrt pads the box by, L98 rose by 4, 12 and 1 % in
  // the three built-in worlds (10 seeds). P_sem reaches the current room's frontier on the
  // box's edge anyway.
  knownCellsBox(input.grid, input.robot.position(), 0, box_min, box_max);
  const RrtTree::Sampler uniform = uniformBoxSampler(box_min, box_max);
  const double p_sem = semanticSampleProbability(options_.k, time_in_room_s_);
  if (point_cells_.size() != g.cellCount()) point_cells_.assign(g.cellCount(), 0);
  for (long n = 0; n < iterations; ++n) {
    Vec2 sample;
    if (!candidates_.empty() && p_sem > 0.0 && unitDouble(rng_) < p_sem) {
      // P_sem: a frontier cell of the current room, approached by a full step so that the
      // edge crosses the frontier into unknown space.
      const Vec2 target = candidates_[std::min(
          candidates_.size() - 1, static_cast<std::size_t>(unitDouble(rng_) * candidates_.size()))];
      const Vec2 from = tree_->node(tree_->nearest(target));
      const Vec2 d = target - from;
      const double len = d.norm();
      sample = len > 1e-9 ? Vec2(from + d / len * options_.eta_m) : target;
      ++semantic_draws_;
    } else {
      sample = uniform(rng_);
      ++random_draws_;
    }
    const RrtExtension e = tree_->extend(input.grid, sample);
    if (e.status != EdgeStatus::kFrontier) continue;
    const Cell c = g.cellOf(e.new_m);
    if (!g.contains(c) || point_cells_[g.index(c)] || blacklisted(e.new_m)) continue;
    const Vec2 from = tree_->node(e.nearest);
    const Vec2 d = e.new_m - from;
    const double len = d.norm();
    const Vec2 anchor = len > g.resolution_m() ? Vec2(e.new_m - d / len * g.resolution_m()) : from;
    points_.push_back({e.new_m, anchor});
    point_cells_[g.index(c)] = 1;
  }
}

void SemanticExplorer::cost(const ExplorationInput& input, std::vector<Candidate>& candidates,
                            double w_c) {
  const Vec2 robot = input.robot.position();
  for (Candidate& c : candidates) c.cost_m = (c.p - robot).norm();
  if (!options_.geodesic_cost) return;
  // Dijkstra from the robot (8-connected) over blocks of kBlock x kBlock cells; a block is
  // passable when one of its cells is not lethal (a wall's lethal band is wider than a block,
  // so no path leaks through). Every block whose distance is at most the queue's smallest is
  // final; a candidate not final yet costs at least that much (and at least its straight-line
  // distance), which bounds its score. The search stops once the goal's cost is final and no
  // candidate still open can beat the best final one of its kind: the choice is that of a
  // search over the whole map (same episodes, 20-30x less time per decision in the houses).
  // Open candidates keep an infinite cost (they cannot win). Blocks of 2 x 2 cells instead of
  // single cells take about half the time on large maps, with lengths and revisits within the
  // seeds' noise.
  const GridGeometry& g = input.grid.geometry();
  const int gw = g.width(), gh = g.height();
  const int w = (gw + kBlock - 1) / kBlock, h = (gh + kBlock - 1) / kBlock;
  const std::size_t blocks = static_cast<std::size_t>(w) * h;
  if (dist_.size() != blocks) dist_.assign(blocks, 0.0f);
  dist_valid_.begin(blocks);
  const float inf = std::numeric_limits<float>::infinity();
  auto distOf = [&](std::size_t i) { return dist_valid_.marked(i) ? dist_[i] : inf; };
  auto blockOf = [&](const Vec2& p) -> std::size_t {
    const Cell c = g.cellOf(p);
    if (!g.contains(c)) return blocks;
    return static_cast<std::size_t>(c.y / kBlock) * w + c.x / kBlock;
  };
  auto passable = [&](int bx, int by) {
    for (int y = by * kBlock; y < std::min(gh, (by + 1) * kBlock); ++y) {
      for (int x = bx * kBlock; x < std::min(gw, (bx + 1) * kBlock); ++x) {
        if (!input.costmap.isLethal(static_cast<std::size_t>(y) * gw + x)) return true;
      }
    }
    return false;
  };
  for (Candidate& c : candidates) c.block = blockOf(c.p);
  heap_.clear();
  const std::size_t start = blockOf(robot);
  if (start < blocks) {
    dist_[start] = 0.0f;
    dist_valid_.mark(start);
    heap_.push_back({0.0f, start});
  }
  // True when nothing still open can change the choice, given that every block up to d is final.
  auto settled = [&](double d) {
    const double none = -std::numeric_limits<double>::infinity();
    double best[2] = {none, none}, open_bound[2] = {none, none};
    bool open[2] = {false, false};
    for (const Candidate& c : candidates) {
      const double dc = c.block < blocks ? distOf(c.block) : inf;
      if (dc <= d) {
        if (!c.goal) best[c.sliver] = std::max(best[c.sliver], c.without_cost - w_c * dc);
        continue;
      }
      if (c.goal) return false;
      open[c.sliver] = true;
      open_bound[c.sliver] =
          std::max(open_bound[c.sliver], c.without_cost - w_c * std::max(d, c.cost_m));
    }
    const bool points_done = !open[0] || open_bound[0] < best[0];
    // Slivers matter only when no other point can be chosen.
    const bool slivers_done =
        !open[1] || open_bound[1] < best[1] || (best[0] > none && points_done);
    return points_done && slivers_done;
  };
  const float step = static_cast<float>(kBlock * g.resolution_m());
  const float diag = step * std::sqrt(2.0f);
  constexpr double kCheckStep_m = 0.25;  // the stop test runs once per this much of radius
  double next_check_m = 0.0;
  const auto later = std::greater<>();
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const auto [d, i] = heap_.back();
    heap_.pop_back();
    if (d > dist_[i]) continue;
    if (d >= next_check_m) {
      if (settled(d)) break;
      next_check_m = d + kCheckStep_m;
    }
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h)
          continue;
        const std::size_t j = static_cast<std::size_t>(y + dy) * w + (x + dx);
        const float nd = d + ((dx != 0 && dy != 0) ? diag : step);
        if (nd < distOf(j) && passable(x + dx, y + dy)) {
          dist_[j] = nd;
          dist_valid_.mark(j);
          heap_.push_back({nd, j});
          std::push_heap(heap_.begin(), heap_.end(), later);
        }
      }
    }
  }
  // Final distances: those not above the smallest distance still queued (all when it is empty).
  const float final_up_to =
      heap_.empty() ? inf : std::min_element(heap_.begin(), heap_.end())->first;
  for (Candidate& c : candidates) {
    const float dc = c.block < blocks ? distOf(c.block) : inf;
    c.cost_m = dc <= final_up_to ? dc : std::numeric_limits<double>::infinity();
  }
}

void SemanticExplorer::addFrontierMass(const OccupancyGrid& grid,
                                       std::vector<Candidate>& candidates) {
  if (options_.mass_weight <= 0.0 || candidates.empty()) return;
  // The frontier cells counted over the candidates' squares (freeBesideUnknown leaves out the
  // grid's border cells).
  const GridGeometry& g = grid.geometry();
  const int r = static_cast<int>(std::lround(options_.mass_half_side_m / g.resolution_m()));
  int x0 = g.width(), x1 = -1, y0 = g.height(), y1 = -1;
  for (const Candidate& c : candidates) {
    const Cell q = g.cellOf(c.p);
    x0 = std::min(x0, q.x - r);
    x1 = std::max(x1, q.x + r);
    y0 = std::min(y0, q.y - r);
    y1 = std::max(y1, q.y + r);
  }
  x0 = std::max(1, x0);
  y0 = std::max(1, y0);
  x1 = std::min(g.width() - 2, x1);
  y1 = std::min(g.height() - 2, y1);
  if (x0 > x1 || y0 > y1) return;
  counts_.build(x0, y0, x1, y1, [&](int x, int y) { return freeBesideUnknown(grid, x, y); });
  for (Candidate& c : candidates) {
    const Cell q = g.cellOf(c.p);
    const int cells = counts_.square(q.x, q.y, r);
    c.without_cost +=
        options_.mass_weight * std::min(options_.mass_cap_m, cells * g.resolution_m());
  }
}

double SemanticExplorer::pocketArea_m2(const OccupancyGrid& grid) const {
  if (!idle_ || options_.pocket_area_fraction <= 0.0) return options_.pocket_area_m2;
  const std::uint8_t* states = grid.stateBytes();
  const auto free_value = static_cast<std::uint8_t>(CellState::kFree);
  const auto free_cells = std::count(states, states + grid.geometry().cellCount(), free_value);
  const double res = grid.geometry().resolution_m();
  const double free_m2 = static_cast<double>(free_cells) * res * res;
  return std::min(options_.pocket_area_m2, options_.pocket_area_fraction * free_m2);
}

bool SemanticExplorer::endTest(const ExplorationInput& input) {
  if (input.time_s - last_end_check_s_ < options_.end_check_period_s - 1e-9) return false;
  last_end_check_s_ = input.time_s;
  // improved_rrt's pocket search (its opening and period), when end_pocket_area_m2 is on:
  // frontier cells opening onto a pocket are left out of the test for good, as those the robot
  // came near are.
  EndTestPockets pockets;
  pockets.min_area_m2 = options_.end_pocket_area_m2;
  const std::size_t cells =
      countEndTestFrontierCells(input.grid, input.costmap, 4, visited_, input.robot.position(),
                                static_cast<std::size_t>(options_.end_min_frontier_cells), pockets,
                                input.time_s, last_end_pocket_check_s_);
  if (cells < static_cast<std::size_t>(options_.end_min_frontier_cells)) {
    return ++failed_end_checks_ >= options_.end_checks;
  }
  failed_end_checks_ = 0;
  return false;
}

void SemanticExplorer::followGeometry(const ExplorationInput& input, const GridGeometry& previous) {
  const GridGeometry& g = input.grid.geometry();
  const auto onGrid = [&g](const Vec2& p) { return g.contains(p); };
  if (tree_ && tree_->rebound(g.origin_m(), farCorner(g), onGrid) == 0)
    tree_->reset(input.robot.position());
  std::erase_if(points_, [&](const FrontierPoint& f) { return !onGrid(f.p); });
  // A point's mark is where it lies (one point per marked cell), so the marks are laid anew from
  // the points; with another resolution two points may now share a cell.
  point_cells_.assign(g.cellCount(), 0);
  for (const FrontierPoint& f : points_) point_cells_[g.index(g.cellOf(f.p))] = 1;
  visited_ = remapCells(visited_, previous, g);
  if (end_cell_ && !onGrid(*end_cell_)) end_cell_.reset();
}

Decision SemanticExplorer::decide(const ExplorationInput& input) {
  const GridGeometry& g = input.grid.geometry();
  const Vec2 robot = input.robot.position();
  if (const auto previous = geometry_.update(g)) followGeometry(input, *previous);
  if (!tree_) {
    const Vec2 max_m =
        g.origin_m() + Vec2(g.width() * g.resolution_m(), g.height() * g.resolution_m());
    tree_ = std::make_unique<RrtTree>(options_.eta_m, g.origin_m(), max_m, 0.5);
    tree_->reset(robot);
    grown_until_s_ = input.time_s;
  }
  markDisc(visited_, g, robot, options_.observed_radius_m);
  updateRoom(input);
  idle_ = options_.idle_end_s > 0.0 && idle_since_s_ >= 0.0 &&
          input.time_s - idle_since_s_ >= options_.idle_end_s - 1e-9;
  if (end_phase_) {
    // The robot idled for idle_end_s with no point and no sliver of its room left: from here
    // it visits the reachable frontier cells (as the end test counts them) it has not come
    // within observed_radius_m of and that open onto no pocket, nearest first, and ends when
    // none is left (or the end test passes). Tree points found on the way (on walls the laser
    // only grazed, mostly) restarted the idling every idle_end_s, so the tree stops growing.
    if (endTest(input)) return Decision::done();
    if (const std::optional<Vec2> cell = endPhaseCell(input)) return Decision::goal(*cell);
    return Decision::done();
  }
  collectCandidates(input);

  const double owed = (input.time_s - grown_until_s_) * options_.iterations_per_s;
  long n = static_cast<long>(std::floor(owed + 1e-9));
  if (n > options_.max_iterations_per_call) {
    n = options_.max_iterations_per_call;
    grown_until_s_ = input.time_s;
  } else if (n > 0) {
    grown_until_s_ += static_cast<double>(n) / options_.iterations_per_s;
  }
  if (n > 0) grow(input, n);

  // The goal is kept until its square is explored (less than goal_min_unknown_m2 of unknown
  // space or min_frontier_m of frontier left), not merely until its own cell is seen: the laser's
  // edge recedes as the robot drives, so the first unknown cell of an edge is seen long before
  // the space behind it. A goal dropped because its cell turned lethal (a wall seen beside
  // it from close by) is blacklisted: walls seen only from close by can fade back to unknown
  // once the robot leaves, the tree then found the same cell again, and on one HouseExpo plan
  // the robot shuttled between two such points until its time limit.
  if (has_goal_) {
    const Cell c = g.cellOf(goal_m_);
    if (g.contains(c) && input.costmap.isLethal(g.index(c))) {
      blacklist_.push_back(goal_m_);
      has_goal_ = false;
    } else if (goalExplored(input)) {
      has_goal_ = false;
    }
  }
  // Points seen since (no longer unknown) or inside the inflation are dropped.
  std::erase_if(points_, [&](const FrontierPoint& f) {
    if (!stale(input, f.p) && !blacklisted(f.p)) return false;
    if (const Cell c = g.cellOf(f.p); g.contains(c)) point_cells_[g.index(c)] = 0;
    return true;
  });
  if (endTest(input)) return Decision::done();
  const bool periodic = input.time_s - last_eval_s_ >= options_.replan_period_s - 1e-9;
  if (!points_.empty() && (!has_goal_ || periodic)) {
    last_eval_s_ = input.time_s;
    // Slivers (less than min_unknown_m2 of unknown space or min_frontier_m of frontier in the
    // square, or a pocket) are not worth the trip while anything else is left. When nothing else
    // was found while idling for idle_end_s, rather than end short of the last percent, the robot
    // takes the best sliver in the current room that it has not come within observed_radius_m of
    // (the corners of a room the laser saw from its middle, say), then the next, until none is
    // left. Other rooms' slivers and those looked at from close by stay out, so that it does not
    // tour the building's furniture faces at the end. A sliver goal's square is explored already,
    // so it is chosen afresh each call.
    const bool slivers_wanted = !has_goal_ && (chasing_slivers_ || idle_);
    if (options_.pocket_area_m2 > 0.0) {
      std::vector<Cell> cells;
      cells.reserve(points_.size());
      for (const FrontierPoint& f : points_) cells.push_back(g.cellOf(f.p));
      pockets_.assign(g.cellCount(), 0);
      markUnknownPockets(pockets_, input.grid, input.costmap, cells, pocketArea_m2(input.grid),
                         kPocketOpening_m);
    }
    // The points that may become the goal, with the score's part that does not depend on C.
    std::vector<Candidate>& cands = candidates_scored_;
    cands.clear();
    const int frontier_wanted = frontierCellsWanted(options_, g.resolution_m());
    // The cost of turning away from the way the robot is driving (see the header); the goal
    // itself never pays it: where the path to it bends round a wall the robot faces away from
    // it, and charging it then made the robot swing between goals until the time limit.
    const Vec2 heading(std::cos(input.robot.yaw_rad), std::sin(input.robot.yaw_rad));
    auto turn = [&](const Vec2& p) {
      const Vec2 d = p - robot;
      const double len = d.norm();
      if (options_.heading_weight <= 0.0 || len < 1e-9) return 0.0;
      return options_.heading_weight * 0.5 * (1.0 - heading.dot(d) / len);
    };
    auto segmentTerm = [&](const Vec2& p) {
      return options_.segment_weight > 0.0 ? options_.segment_weight * segmentLength(input.grid, p)
                                           : 0.0;
    };
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const std::size_t cell = g.index(g.cellOf(points_[i].p));
      const SquareAreas a =
          squareAreas(input.grid, points_[i].p, options_.gain_half_side_m, frontier_wanted);
      const bool sliver = exhausted(a, options_, options_.min_unknown_m2, g.resolution_m()) ||
                          (options_.pocket_area_m2 > 0.0 && pockets_[cell]);
      if (sliver && (!slivers_wanted || visited_[cell])) continue;
      const bool inside = inCurrentRoom(roomOf(input, points_[i].anchor));
      if (sliver && !inside) continue;
      const double without_cost = score(a.unknown_m2 - a.occupied_m2, 0.0, inside) -
                                  turn(points_[i].p) + segmentTerm(points_[i].p);
      cands.push_back({points_[i].p, i, without_cost, sliver, false});
      cands.back().inside = inside;
    }
    if (has_goal_) {
      const SquareAreas a = squareAreas(input.grid, goal_m_, options_.gain_half_side_m);
      const bool inside = inCurrentRoom(roomOf(input, goal_anchor_));
      cands.push_back({goal_m_, points_.size(),
                       score(a.unknown_m2 - a.occupied_m2, 0.0, inside) + segmentTerm(goal_m_),
                       false, true});
    }
    // Choosing the next room: in a hub, or no point left in this room but slivers.
    const bool next_room = hub_ || std::none_of(cands.begin(), cands.end(), [](const Candidate& k) {
                             return k.inside && !k.sliver && !k.goal;
                           });
    const double w_c = options_.cost_weight * (next_room ? options_.next_room_cost_factor : 1.0);
    if (next_room) addFrontierMass(input.grid, cands);
    cost(input, cands, w_c);
    double best_score = -std::numeric_limits<double>::infinity();
    double best_sliver_score = -std::numeric_limits<double>::infinity();
    double goal_score = -std::numeric_limits<double>::infinity();
    std::size_t best = points_.size(), best_sliver = points_.size();
    for (const Candidate& c : cands) {
      if (!std::isfinite(c.cost_m)) continue;  // no path through the costmap (or cannot win)
      const double s = c.without_cost - w_c * c.cost_m;
      if (c.goal) {
        goal_score = s;
        continue;
      }
      double& best_of_kind = c.sliver ? best_sliver_score : best_score;
      if (s > best_of_kind) {
        best_of_kind = s;
        (c.sliver ? best_sliver : best) = c.point;
      }
    }
    const bool fallback = best == points_.size() && slivers_wanted;
    if (fallback) best = best_sliver;
    if (best < points_.size() && (!has_goal_ || best_score > goal_score + options_.switch_margin)) {
      goal_m_ = points_[best].p;
      goal_anchor_ = points_[best].anchor;
      has_goal_ = true;
      chasing_slivers_ = fallback;
    }
  }
  if (has_goal_) {
    idle_since_s_ = -1.0;
    return Decision::goal(goal_m_);
  }
  // Nothing to assign: wait where we are while the tree grows, or, idle for idle_end_s, the
  // end phase (see its block above).
  if (idle_since_s_ < 0.0) idle_since_s_ = input.time_s;
  if (idle_) {
    end_phase_ = true;
    if (const std::optional<Vec2> cell = endPhaseCell(input)) return Decision::goal(*cell);
    return Decision::done();
  }
  if (const auto wait = nearestGoalCell(input.grid, input.costmap, robot, 3.0))
    return Decision::goal(*wait);
  return Decision::done();
}

std::vector<Vec2> SemanticExplorer::candidateGoals() const {
  std::vector<Vec2> out;
  out.reserve(points_.size());
  for (const FrontierPoint& f : points_) out.push_back(f.p);
  return out;
}

}  // namespace roomscout
