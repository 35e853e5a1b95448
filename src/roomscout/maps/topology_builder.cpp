#include "roomscout/maps/topology_builder.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/detail/run_components.hpp"
#include "roomscout/maps/detail/thinning.hpp"
#include "roomscout/maps/grid_image.hpp"
#include "roomscout/maps/semantic_map.hpp"

namespace roomscout {
namespace {

// The 8-ring around a pixel, in circular order (for crossing numbers).
constexpr int kRingX[8] = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr int kRingY[8] = {-1, -1, 0, 1, 1, 1, 0, -1};

struct WorkNode {
  cv::Point px;
  float clearance_px = 0.0f;
  bool alive = true;
};

struct WorkEdge {
  int u = 0, v = 0;
  std::vector<cv::Point> path;  // from u's pixel to v's pixel
  double length_px = 0.0;
  float min_clearance_px = 0.0f;
  bool alive = true;
};

double pathLength(const std::vector<cv::Point>& path) {
  double l = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int dx = std::abs(path[i].x - path[i - 1].x), dy = std::abs(path[i].y - path[i - 1].y);
    l += (dx && dy) ? M_SQRT2 : static_cast<double>(dx + dy);
  }
  return l;
}

}  // namespace

void TopologyBuilderOptions::validate() const {
  if (!(opening_radius_m >= 0.0)) throw OptionError("topology.opening_radius_m must be >= 0");
  if (!(furniture_max_area_m2 >= 0.0))
    throw OptionError("topology.furniture_max_area_m2 must be >= 0");
  if (!(furniture_max_extent_m >= 0.0))
    throw OptionError("topology.furniture_max_extent_m must be >= 0");
  if (!(min_free_area_m2 >= 0.0)) throw OptionError("topology.min_free_area_m2 must be >= 0");
  if (!(spur_min_length_m >= 0.0)) throw OptionError("topology.spur_min_length_m must be >= 0");
  if (!(spur_disc_factor >= 0.0)) throw OptionError("topology.spur_disc_factor must be >= 0");
  if (!(simplify_tolerance_m >= 0.0))
    throw OptionError("topology.simplify_tolerance_m must be >= 0");
}

std::vector<ParameterRef> TopologyBuilderOptions::parameters() {
  return {
      {"opening_radius_m", &opening_radius_m,
       "opening of the free space; keep it below half the narrowest door, or doors get cut [m]"},
      {"furniture_max_area_m2", &furniture_max_area_m2,
       "enclosed obstacle blobs up to this area are filled, so furniture makes no loops [m^2]"},
      {"furniture_max_extent_m", &furniture_max_extent_m,
       "... and up to this bounding-box side [m]"},
      {"min_free_area_m2", &min_free_area_m2, "smaller free patches get no skeleton [m^2]"},
      {"spur_min_length_m", &spur_min_length_m, "dead-end edges shorter than this are pruned [m]"},
      {"spur_disc_factor", &spur_disc_factor,
       "dead ends within this many times a junction's clearance of it are pruned too (room "
       "corners)"},
      {"simplify_tolerance_m", &simplify_tolerance_m,
       "polyline simplification (Douglas-Peucker) tolerance [m]"},
  };
}

TopologyBuilder::TopologyBuilder(const TopologyBuilderOptions& options) : options_(options) {
  options_.validate();
}

TopologicalMap TopologyBuilder::build(const OccupancyGrid& grid,
                                      const SemanticMap* semantic) const {
  return build(maps::stateView(grid), grid.geometry(), semantic);
}

TopologicalMap TopologyBuilder::build(const cv::Mat& states, const GridGeometry& geometry,
                                      const SemanticMap* semantic) const {
  if (states.type() != CV_8U || states.rows != geometry.height() ||
      states.cols != geometry.width()) {
    throw InvalidArgument("TopologyBuilder: states must be CV_8U of the geometry's size");
  }
  if (states.empty()) return TopologicalMap(geometry, {}, {});
  // Work on the known part only (a partial map is mostly unknown); positions are in metres.
  const cv::Rect known = maps::knownBounds(states, 2);
  if (known.empty()) return TopologicalMap(geometry, {}, {});
  const double res = geometry.resolution_m();
  const Vec2 origin = geometry.origin_m() + Vec2(known.x, known.y) * res;
  const cv::Mat crop = states(known);
  const TopologicalMap graph_of_crop = graph(
      skeleton(crop, res), crop, GridGeometry(origin, res, known.width, known.height), semantic);
  return TopologicalMap(geometry, graph_of_crop.nodes(), graph_of_crop.edges());
}

TopologyBuilder::Skeleton TopologyBuilder::skeleton(const cv::Mat& states,
                                                    double resolution_m) const {
  if (states.type() != CV_8U) throw InvalidArgument("TopologyBuilder: states must be CV_8U");
  const double res = resolution_m;
  Skeleton out;
  // 1. Free space, furniture filled, opened, tiny patches dropped; one-pixel frame.
  cv::Mat space = maps::fillableFreeSpace(
      states, static_cast<int>(options_.furniture_max_area_m2 / (res * res)),
      static_cast<int>(std::ceil(options_.furniture_max_extent_m / res)));
  out.filled = space.clone();  // unknown cells in here are enclosed, not frontiers
  const int r = static_cast<int>(std::lround(options_.opening_radius_m / res));
  if (r > 0) {
    const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
    cv::morphologyEx(space, space, cv::MORPH_OPEN, kernel);
  }
  {
    const maps::RunComponents patches = maps::runComponents(space, 4);
    const int min_cells = static_cast<int>(options_.min_free_area_m2 / (res * res));
    for (const maps::PixelRun& run : patches.runs) {
      if (patches.components[run.component].area < min_cells) {
        std::uint8_t* row = space.ptr<std::uint8_t>(run.y);
        std::fill(row + run.x_begin, row + run.x_end, std::uint8_t{0});
      }
    }
  }
  cv::copyMakeBorder(space, space, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
  cv::distanceTransform(space, out.clearance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  // 2. Skeleton.
  out.skel = maps::thinZhangSuen(space);
  return out;
}

TopologicalMap TopologyBuilder::graph(const Skeleton& skeleton, const cv::Mat& states,
                                      const GridGeometry& geometry,
                                      const SemanticMap* semantic) const {
  if (states.type() != CV_8U || states.rows != geometry.height() ||
      states.cols != geometry.width() || skeleton.skel.rows != states.rows + 2 ||
      skeleton.skel.cols != states.cols + 2 || skeleton.clearance.size() != skeleton.skel.size() ||
      skeleton.filled.size() != states.size()) {
    throw InvalidArgument("TopologyBuilder: skeleton and states must be of the geometry's size");
  }
  const double res = geometry.resolution_m();
  const cv::Mat& skel = skeleton.skel;
  const cv::Mat& clearance = skeleton.clearance;
  const cv::Mat& filled = skeleton.filled;
  const int w = skel.cols, h = skel.rows;
  auto on = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && skel.ptr<std::uint8_t>(y)[x] != 0;
  };

  // 3. Node pixels: crossing number 1 or 0 (ends, isolated points) or >= 3 (junctions). The
  // crossing number ignores the staircase pixels thinning leaves on diagonals, which have
  // three neighbours but only two branches.
  cv::Mat node_of(h, w, CV_32S, cv::Scalar(-1));
  std::vector<cv::Point> node_pixels;
  std::vector<int> crossing;
  for (int y = 1; y + 1 < h; ++y) {
    const std::uint8_t* skel_row = skel.ptr<std::uint8_t>(y);
    for (int x = 1; x + 1 < w; ++x) {
      if (!skel_row[x]) continue;
      int cn = 0;
      for (int k = 0; k < 8; ++k) {
        const bool a = on(x + kRingX[k], y + kRingY[k]),
                   b = on(x + kRingX[(k + 1) % 8], y + kRingY[(k + 1) % 8]);
        cn += (!a && b);
      }
      if (cn != 2) {
        node_pixels.push_back({x, y});
        crossing.push_back(cn);
      }
    }
  }
  // Junction pixels within two pixels of each other form one node; ends are nodes of their own.
  std::vector<WorkNode> nodes;
  std::vector<std::vector<cv::Point>> node_members;
  std::vector<std::uint8_t> is_end_node;
  {
    cv::Mat is_junction = cv::Mat::zeros(h, w, CV_8U);
    for (std::size_t i = 0; i < node_pixels.size(); ++i) {
      if (crossing[i] >= 3) is_junction.at<std::uint8_t>(node_pixels[i]) = 1;
    }
    std::vector<cv::Point> stack, members;
    for (std::size_t i = 0; i < node_pixels.size(); ++i) {
      const cv::Point p = node_pixels[i];
      if (node_of.at<int>(p) >= 0) continue;
      const int id = static_cast<int>(nodes.size());
      members.clear();
      node_of.at<int>(p) = id;
      if (crossing[i] >= 3) {
        stack.assign(1, p);
        while (!stack.empty()) {
          const cv::Point q = stack.back();
          stack.pop_back();
          members.push_back(q);
          for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
              const cv::Point nq(q.x + dx, q.y + dy);
              if (nq.x < 0 || nq.y < 0 || nq.x >= w || nq.y >= h) continue;
              if (is_junction.at<std::uint8_t>(nq) && node_of.at<int>(nq) < 0) {
                node_of.at<int>(nq) = id;
                stack.push_back(nq);
              }
            }
          }
        }
      } else {
        members.push_back(p);
      }
      // The node sits on its member closest to the members' centroid.
      cv::Point2d c(0, 0);
      for (const cv::Point& m : members) c += cv::Point2d(m.x, m.y);
      c *= 1.0 / static_cast<double>(members.size());
      cv::Point best = members.front();
      double best_d = 1e18;
      for (const cv::Point& m : members) {
        const double d = (m.x - c.x) * (m.x - c.x) + (m.y - c.y) * (m.y - c.y);
        if (d < best_d) {
          best_d = d;
          best = m;
        }
      }
      nodes.push_back({best, clearance.at<float>(best), true});
      node_members.push_back(members);
      is_end_node.push_back(crossing[i] < 3);
    }
  }

  // 4. Edges: walk the skeleton from every node until another node pixel is reached.
  std::vector<WorkEdge> edges;
  cv::Mat visited = cv::Mat::zeros(h, w, CV_8U);
  auto trace = [&](int start_node, cv::Point first, std::vector<cv::Point> prefix) {
    std::vector<cv::Point> path = std::move(prefix);
    cv::Point cur = first;
    visited.at<std::uint8_t>(cur) = 1;
    path.push_back(cur);
    int end_node = -1;
    for (int steps = 1;; ++steps) {
      // A node pixel next to us ends the edge (our own start only after a few steps: a loop).
      cv::Point next(-1, -1);
      for (int k = 0; k < 8 && end_node < 0; ++k) {
        const cv::Point q(cur.x + kRingX[k], cur.y + kRingY[k]);
        if (!on(q.x, q.y)) continue;
        const int nid = node_of.at<int>(q);
        if (nid >= 0 && (nid != start_node || steps >= 3)) {
          end_node = nid;
          path.push_back(nodes[nid].px);
        }
      }
      if (end_node >= 0) break;
      for (const int k : {0, 2, 4, 6, 1, 3, 5, 7}) {  // 4-neighbours first: no staircase skipped
        const cv::Point q(cur.x + kRingX[k], cur.y + kRingY[k]);
        if (on(q.x, q.y) && node_of.at<int>(q) < 0 && !visited.at<std::uint8_t>(q)) {
          next = q;
          break;
        }
      }
      if (next.x < 0) break;  // dead end inside a cluster's leftovers
      visited.at<std::uint8_t>(next) = 1;
      path.push_back(next);
      cur = next;
    }
    if (end_node < 0) return;
    WorkEdge e;
    e.u = start_node;
    e.v = end_node;
    e.path = std::move(path);
    e.length_px = pathLength(e.path);
    e.min_clearance_px = nodes[start_node].clearance_px;
    for (const cv::Point& p : e.path)
      e.min_clearance_px = std::min(e.min_clearance_px, clearance.at<float>(p));
    edges.push_back(std::move(e));
  };
  for (int id = 0; id < static_cast<int>(nodes.size()); ++id) {
    // Every skeleton pixel of this node's cluster: its non-node neighbours start edges.
    const std::vector<cv::Point> members = node_members[id];
    for (const cv::Point& m : members) {
      for (const int k : {0, 2, 4, 6, 1, 3, 5, 7}) {
        const cv::Point q(m.x + kRingX[k], m.y + kRingY[k]);
        if (on(q.x, q.y) && node_of.at<int>(q) < 0 && !visited.at<std::uint8_t>(q)) {
          trace(id, q, {nodes[id].px});
        }
      }
      // Two node pixels side by side (e.g. two ends of a two-pixel skeleton) share an edge.
      for (int k = 0; k < 8; ++k) {
        const cv::Point q(m.x + kRingX[k], m.y + kRingY[k]);
        if (!on(q.x, q.y)) continue;
        const int other = node_of.at<int>(q);
        if (other > id) {
          WorkEdge e;
          e.u = id;
          e.v = other;
          e.path = {nodes[id].px, nodes[other].px};
          e.length_px = pathLength(e.path);
          e.min_clearance_px = std::min(nodes[id].clearance_px, nodes[other].clearance_px);
          bool dup = false;
          for (const WorkEdge& x : edges) dup |= (x.u == id && x.v == other && x.path.size() == 2);
          if (!dup) edges.push_back(std::move(e));
        }
      }
    }
  }
  // Loops without any node (a ring around an island): give each a node.
  for (int y = 1; y + 1 < h; ++y) {
    const std::uint8_t* skel_row = skel.ptr<std::uint8_t>(y);
    for (int x = 1; x + 1 < w; ++x) {
      if (!skel_row[x] || node_of.at<int>(y, x) >= 0 || visited.at<std::uint8_t>(y, x)) continue;
      const int id = static_cast<int>(nodes.size());
      nodes.push_back({{x, y}, clearance.at<float>(y, x), true});
      node_members.push_back({cv::Point(x, y)});
      is_end_node.push_back(0);
      node_of.at<int>(y, x) = id;
      for (int k = 0; k < 8; ++k) {
        const cv::Point q(x + kRingX[k], y + kRingY[k]);
        if (on(q.x, q.y) && node_of.at<int>(q) < 0 && !visited.at<std::uint8_t>(q)) {
          trace(id, q, {cv::Point(x, y)});
          break;
        }
      }
    }
  }

  // 5. Prune: tiny self-loops, then spurs, then nodes left with two edges are merged away.
  const double spur_px = options_.spur_min_length_m / res;
  for (WorkEdge& e : edges) {
    if (e.u == e.v && e.length_px * res < 0.5) e.alive = false;
  }
  // Incident edge lists; a self-loop is listed once and counts twice.
  std::vector<std::vector<int>> incident(nodes.size());
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) {
    incident[edges[i].u].push_back(i);
    if (edges[i].v != edges[i].u) incident[edges[i].v].push_back(i);
  }
  auto degree = [&](int id) {
    int d = 0;
    for (const int i : incident[id]) {
      if (edges[i].alive) d += edges[i].u == edges[i].v ? 2 : 1;
    }
    return d;
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<int> deg(nodes.size());
    for (int id = 0; id < static_cast<int>(nodes.size()); ++id) deg[id] = degree(id);
    std::vector<int> removed_at(nodes.size(), 0);
    for (WorkEdge& e : edges) {
      if (!e.alive || e.u == e.v) continue;
      int end = -1, junction = -1;
      if (deg[e.u] == 1 && deg[e.v] >= 3) end = e.u, junction = e.v;
      if (deg[e.v] == 1 && deg[e.u] >= 3) end = e.v, junction = e.u;
      if (end < 0) continue;
      // Never prune every edge of a junction in one pass: leave it at least one.
      if (deg[junction] - removed_at[junction] <= 1) continue;
      const double reach = cv::norm(nodes[end].px - nodes[junction].px);
      if (e.length_px < spur_px ||
          reach <= options_.spur_disc_factor * nodes[junction].clearance_px) {
        e.alive = false;
        nodes[end].alive = false;
        ++removed_at[junction];
        changed = true;
      }
    }
    for (int id = 0; id < static_cast<int>(nodes.size()); ++id) {
      if (!nodes[id].alive || degree(id) != 2) continue;
      int a = -1, b = -1;
      for (const int i : incident[id]) {
        if (edges[i].alive) (a < 0 ? a : b) = i;
      }
      if (a < 0 || b < 0 || a == b) continue;  // a self-loop: keep its node
      WorkEdge& ea = edges[a];
      WorkEdge& eb = edges[b];
      if (ea.v != id) {
        std::reverse(ea.path.begin(), ea.path.end());
        std::swap(ea.u, ea.v);
      }
      if (eb.u != id) {
        std::reverse(eb.path.begin(), eb.path.end());
        std::swap(eb.u, eb.v);
      }
      ea.path.insert(ea.path.end(), eb.path.begin() + 1, eb.path.end());
      ea.v = eb.v;
      ea.length_px += eb.length_px;
      ea.min_clearance_px = std::min(ea.min_clearance_px, eb.min_clearance_px);
      eb.alive = false;
      if (ea.v != ea.u) incident[ea.v].push_back(a);
      nodes[id].alive = false;
      changed = true;
    }
  }

  // 6. Output in metres; ends facing unknown space are frontier nodes.
  std::vector<int> new_id(nodes.size(), -1);
  std::vector<TopoNode> out_nodes;
  // A frontier cell: unknown next to free (not unknown behind a wall).
  auto isFrontierCell = [&](int x, int y) {
    const auto free_state = static_cast<std::uint8_t>(CellState::kFree);
    return (x > 0 && states.ptr<std::uint8_t>(y)[x - 1] == free_state) ||
           (x + 1 < states.cols && states.ptr<std::uint8_t>(y)[x + 1] == free_state) ||
           (y > 0 && states.ptr<std::uint8_t>(y - 1)[x] == free_state) ||
           (y + 1 < states.rows && states.ptr<std::uint8_t>(y + 1)[x] == free_state);
  };
  const auto unknown = static_cast<std::uint8_t>(CellState::kUnknown);
  for (int id = 0; id < static_cast<int>(nodes.size()); ++id) {
    if (!nodes[id].alive) continue;
    TopoNode n;
    n.id = static_cast<int>(out_nodes.size());
    new_id[id] = n.id;
    const Cell cell{nodes[id].px.x - 1, nodes[id].px.y - 1};
    n.position_m = geometry.centerOf(cell);
    n.clearance_m = nodes[id].clearance_px * res;
    const int d = degree(id);
    n.kind = d >= 3 ? TopoNodeKind::kJunction : TopoNodeKind::kEndpoint;
    if (d == 2 && !is_end_node[id]) n.kind = TopoNodeKind::kJunction;
    if (n.kind == TopoNodeKind::kEndpoint) {
      const int reach = static_cast<int>(std::ceil(nodes[id].clearance_px)) + 2;
      for (int dy = -reach; dy <= reach && n.kind != TopoNodeKind::kFrontier; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const int x = cell.x + dx, y = cell.y + dy;
          if (dx * dx + dy * dy > reach * reach || x < 0 || y < 0 || x >= states.cols ||
              y >= states.rows)
            continue;
          if (states.ptr<std::uint8_t>(y)[x] == unknown && !filled.ptr<std::uint8_t>(y)[x] &&
              isFrontierCell(x, y)) {
            n.kind = TopoNodeKind::kFrontier;
            break;
          }
        }
      }
    }
    n.region_id = semantic ? semantic->roomAt(n.position_m) : 0;
    out_nodes.push_back(n);
  }
  std::vector<TopoEdge> out_edges;
  const double eps_px = options_.simplify_tolerance_m / res;
  for (const WorkEdge& e : edges) {
    if (!e.alive || new_id[e.u] < 0 || new_id[e.v] < 0) continue;
    TopoEdge te;
    te.id = static_cast<int>(out_edges.size());
    te.u = new_id[e.u];
    te.v = new_id[e.v];
    te.length_m = e.length_px * res;
    te.min_clearance_m = e.min_clearance_px * res;
    std::vector<cv::Point> simple;
    if (e.path.size() > 2 && eps_px > 0.0) {
      cv::approxPolyDP(e.path, simple, eps_px, false);
    } else {
      simple = e.path;
    }
    for (const cv::Point& p : simple)
      te.polyline_m.push_back(geometry.centerOf(Cell{p.x - 1, p.y - 1}));
    out_edges.push_back(std::move(te));
  }
  return TopologicalMap(geometry, std::move(out_nodes), std::move(out_edges));
}

}  // namespace roomscout
