// roomscout's Explorer without the simulator: a robot loop that feeds it a map and a pose and
// prints the commands it gets back. The "robot" here is a toy (it hops along the commanded
// path and measures its hand-drawn floor plan with a simple range finder), but the loop is the
// one a real robot runs: map and pose in, command out, the driver's outcome reported back.
//
// Usage: roomscout_explore_loop [method]      (default: semantic; see `roomscout methods`)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/explorer/explorer.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"

using namespace roomscout;

namespace {

/// The floor plan the toy sensor measures: two 5 x 4 m rooms joined by a 1 m door.
bool isWall(const Vec2& p) {
  const bool outside = p.x() < 0.0 || p.x() > 10.0 || p.y() < 0.0 || p.y() > 4.0;
  const bool border = p.x() < 0.1 || p.x() > 9.9 || p.y() < 0.1 || p.y() > 3.9;
  const bool partition = std::abs(p.x() - 5.0) < 0.05 && std::abs(p.y() - 2.0) > 0.5;
  return outside || border || partition;
}

/// A 360-beam range finder with a 3.5 m range, marched in 2 cm steps.
LaserScan measure(const Pose2& pose) {
  LaserScan scan;
  scan.angle_increment_rad = 2.0 * M_PI / 360;
  for (int i = 0; i < 360; ++i) {
    const double a = pose.yaw_rad + i * scan.angle_increment_rad;
    float range = INFINITY;
    for (double r = 0.0; r <= scan.range_max_m; r += 0.02) {
      if (isWall(pose.position() + r * Vec2(std::cos(a), std::sin(a)))) {
        range = static_cast<float>(r);
        break;
      }
    }
    scan.ranges_m.push_back(range);
  }
  return scan;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string method = argc > 1 ? argv[1] : "semantic";
  // The robot's own map, as a SLAM package keeps it; the Explorer is shown only the part
  // that is known, plus a margin, so the map it sees grows and its origin moves.
  OccupancyGrid slam(GridGeometry(Vec2(-1.0, -1.0), 0.05, 240, 120));
  OccupancyMapper mapper(slam);
  Explorer explorer(createStrategy(method, /*seed=*/1));
  Pose2 robot{1.0, 2.0, 0.0};
  CellRect known;

  for (double t = 0.0; t < 600.0; t += 0.5) {
    known.unite(mapper.integrate(measure(robot), robot));
    const int m = 20;  // 1 m of unknown border
    const CellRect crop =
        CellRect{known.min_x - m, known.min_y - m, known.max_x + m, known.max_y + m}.clippedTo(
            slam.geometry().width(), slam.geometry().height());
    const GridGeometry& g = slam.geometry();
    const OccupancyGrid map = slam.reframed(
        GridGeometry(g.centerOf({crop.min_x, crop.min_y}) - Vec2(0.025, 0.025), g.resolution_m(),
                     crop.max_x - crop.min_x, crop.max_y - crop.min_y));

    const ExplorerCommand command = explorer.update({map, robot, t});
    if (command.kind == ExplorerCommand::Kind::kDone) {
      const auto known_cells = std::count_if(map.states().begin(), map.states().end(),
                                             [](CellState c) { return c != CellState::kUnknown; });
      const double cell_m2 = map.geometry().resolution_m() * map.geometry().resolution_m();
      const double plan_m2 = 10.0 * 4.0;  // the floor plan's walls and floor
      std::printf("%6.1f s  done: %.1f %% of the floor plan known (%.1f m^2), %d goals\n", t,
                  100.0 * known_cells * cell_m2 / plan_m2, known_cells * cell_m2,
                  explorer.stats().goals);
      return 0;
    }
    if (command.kind != ExplorerCommand::Kind::kDrive) continue;
    if (command.new_path) {
      std::printf("%6.1f s  drive to (%.2f, %.2f), %zu waypoints, map %d x %d at (%.2f, %.2f)\n", t,
                  command.goal_m.x(), command.goal_m.y(), command.path->waypoints_m.size(),
                  map.geometry().width(), map.geometry().height(), map.geometry().origin_m().x(),
                  map.geometry().origin_m().y());
    }
    // The toy driver: hop 0.1 m along the path, facing the way it goes.
    const std::vector<Vec2>& w = command.path->waypoints_m;
    std::size_t i = 0;
    for (std::size_t j = 1; j < w.size(); ++j) {
      if ((w[j] - robot.position()).norm() < (w[i] - robot.position()).norm()) i = j;
    }
    while (i + 1 < w.size() && (w[i] - robot.position()).norm() < 0.1) ++i;
    const Vec2 step = w[i] - robot.position();
    if (step.norm() > 1e-9) {
      const Vec2 next = robot.position() + step.normalized() * std::min(0.1, step.norm());
      robot = Pose2{next.x(), next.y(), std::atan2(step.y(), step.x())};
    }
  }
  std::printf("time limit reached\n");
  return 1;
}
