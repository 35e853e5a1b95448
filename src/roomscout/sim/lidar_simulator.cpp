#include "roomscout/sim/lidar_simulator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <span>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_ray.hpp"

namespace roomscout::sim {

void LidarOptions::validate() const {
  if (num_rings < 1 || num_rings > 64) throw OptionError("lidar.num_rings must be in [1, 64]");
  if (!(elevation_min_deg >= -89.0 && elevation_max_deg <= 89.0 &&
        elevation_min_deg <= elevation_max_deg)) {
    throw OptionError("lidar: need -89 <= elevation_min_deg <= elevation_max_deg <= 89");
  }
  if (num_rings > 1 && !(elevation_min_deg < elevation_max_deg)) {
    throw OptionError("lidar: several rings need elevation_min_deg < elevation_max_deg");
  }
  if (!(azimuth_step_deg >= 0.01 && azimuth_step_deg <= 90.0)) {
    throw OptionError("lidar.azimuth_step_deg must be in [0.01, 90]");
  }
  if (!(range_min_m >= 0.0 && range_min_m < range_max_m)) {
    throw OptionError("lidar: need 0 <= range_min_m < range_max_m");
  }
  if (!(rate_hz > 0.0)) throw OptionError("lidar.rate_hz must be > 0");
  if (!(mount_height_m > 0.0)) throw OptionError("lidar.mount_height_m must be > 0");
}

std::vector<ParameterRef> LidarOptions::parameters() {
  return {
      {"num_rings", &num_rings, "beams per azimuth column (VLP-16: 16)"},
      {"elevation_min_deg", &elevation_min_deg, "lowest ring's elevation [deg]"},
      {"elevation_max_deg", &elevation_max_deg,
       "highest ring's elevation [deg]; the rings are evenly spaced"},
      {"azimuth_step_deg", &azimuth_step_deg,
       "azimuth between columns [deg] (VLP-16 at 10 Hz: 0.2, 1800 columns)"},
      {"range_min_m", &range_min_m, "minimum range: closer returns are dropped [m]"},
      {"range_max_m", &range_max_m, "maximum range: no return beyond it [m]"},
      {"rate_hz", &rate_hz, "revolutions per second"},
      {"mount_height_m", &mount_height_m,
       "sensor origin above the floor, on the robot's centre [m]"},
  };
}

LidarSimulator::LidarSimulator(const ColumnWorld& world, const LidarOptions& options,
                               std::uint64_t seed, const RangeNoise& noise)
    : world_(world), options_(options), noise_(noise), rng_(seed) {
  options_.validate();
  noise_.validate();
  const double deg = M_PI / 180.0;
  for (int k = 0; k < options_.num_rings; ++k) {
    const double e = options_.num_rings == 1
                         ? options_.elevation_min_deg
                         : options_.elevation_min_deg +
                               (options_.elevation_max_deg - options_.elevation_min_deg) * k /
                                   (options_.num_rings - 1);
    elevations_rad_.push_back(e * deg);
  }
  // Per raster cell: the kind of a non-empty column (kKinds - 1: read the column), or
  // kClearBase - 1 plus the chessboard distance to the nearest non-empty column, capped at 255
  // (two chamfer passes with unit weights are exact for this metric). The kinds are the most
  // common span lists (a wall, a table top over its legs, a lintel): a ray that meets one
  // reads its spans from kind_spans_, which stays in cache, instead of from the column.
  {
    const int w = world_.geometry().width(), h = world_.geometry().height();
    const std::size_t n_cells = world_.geometry().cellCount();
    // A column's span list, ordered by its values (for counting equal lists).
    using SpanList = std::span<const ZInterval>;
    const auto less = [](const SpanList& a, const SpanList& b) {
      return std::lexicographical_compare(
          a.begin(), a.end(), b.begin(), b.end(), [](const ZInterval& p, const ZInterval& q) {
            return p.z_min_m != q.z_min_m ? p.z_min_m < q.z_min_m : p.z_max_m < q.z_max_m;
          });
    };
    std::map<SpanList, std::size_t, decltype(less)> counts(less);
    for (std::size_t i = 0; i < n_cells; ++i) {
      if (!world_.columnEmpty(i)) ++counts[world_.intervals(i)];
    }
    std::vector<std::pair<std::size_t, SpanList>> by_count;
    for (const auto& [list, count] : counts) by_count.emplace_back(count, list);
    std::stable_sort(by_count.begin(), by_count.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::map<SpanList, std::uint8_t, decltype(less)> kind_of(less);
    kind_offsets_.assign(1, 0);
    for (std::size_t k = 0; k < by_count.size() && k + 1 < kKinds; ++k) {
      kind_of[by_count[k].second] = static_cast<std::uint8_t>(k);
      kind_spans_.insert(kind_spans_.end(), by_count[k].second.begin(), by_count[k].second.end());
      kind_offsets_.push_back(static_cast<std::uint32_t>(kind_spans_.size()));
    }
    clear_cells_.assign(n_cells, 255);
    std::uint8_t* d = clear_cells_.data();
    auto relax = [&](std::size_t i, std::size_t j) {
      d[i] =
          static_cast<std::uint8_t>(std::min<int>(d[i], std::max<int>(d[j], kClearBase - 1) + 1));
    };
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        if (!world_.columnEmpty(i)) {
          const auto kind = kind_of.find(world_.intervals(i));
          d[i] = kind != kind_of.end() ? kind->second : kReadColumn;
          continue;
        }
        if (x > 0) relax(i, i - 1);
        if (y > 0) {
          relax(i, i - w);
          if (x > 0) relax(i, i - w - 1);
          if (x + 1 < w) relax(i, i - w + 1);
        }
      }
    }
    for (int y = h - 1; y >= 0; --y) {
      for (int x = w - 1; x >= 0; --x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        if (d[i] < kClearBase) continue;
        if (x + 1 < w) relax(i, i + 1);
        if (y + 1 < h) {
          relax(i, i + w);
          if (x + 1 < w) relax(i, i + w + 1);
          if (x > 0) relax(i, i + w - 1);
        }
      }
    }
  }
  const int n_columns =
      std::max(1, static_cast<int>(std::lround(360.0 / options_.azimuth_step_deg)));
  for (int c = 0; c < n_columns; ++c) {
    const double a = 2.0 * M_PI * c / n_columns;
    cos_azimuth_.push_back(std::cos(a));
    sin_azimuth_.push_back(std::sin(a));
  }
}

Eigen::Isometry3d LidarSimulator::sensorPose(const Pose2& T_map_robot) const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(T_map_robot.yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() =
      Eigen::Vector3d(T_map_robot.x_m, T_map_robot.y_m, world_.floor_m() + options_.mount_height_m);
  return T;
}

std::vector<LidarSimulator::Ring> LidarSimulator::makeRings(
    const std::vector<double>& elevations_rad, double z_m, double max_range_m,
    std::vector<int>& order) const {
  std::vector<Ring> rings;
  const double inf = std::numeric_limits<double>::infinity();
  for (double e : elevations_rad) {
    Ring r;
    r.slope = std::tan(e);
    r.cos_elev = std::cos(e);
    double t_plane = inf;
    r.plane_surface = LidarSurface::kObject;
    if (r.slope > 0.0) {
      t_plane = (world_.ceiling_m() - z_m) / r.slope;
      r.plane_surface = LidarSurface::kCeiling;
    } else if (r.slope < 0.0) {
      t_plane = (world_.floor_m() - z_m) / r.slope;
      r.plane_surface = LidarSurface::kFloor;
    }
    const double t_range = max_range_m * r.cos_elev;
    r.plane_hit = t_plane <= t_range;
    r.limit_m = std::max(0.0, std::min(t_plane, t_range));
    rings.push_back(r);
  }
  order.resize(rings.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return rings[a].limit_m < rings[b].limit_m; });
  return rings;
}

void LidarSimulator::castColumn(const Eigen::Vector2d& origin_m, double z_m, double cos_az,
                                double sin_az, const std::vector<Ring>& rings,
                                const std::vector<int>& order, double* hit_t_m, double* hit_dz_m,
                                LidarSurface* hit_surface) const {
  const int n = static_cast<int>(rings.size());
  for (int k = 0; k < n; ++k) hit_t_m[k] = -1.0;
  std::uint64_t active = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
  const double inf = std::numeric_limits<double>::infinity();
  // Rings retire at their plane/range limit in `order`; next_limit_m is the next such limit.
  std::size_t next_limit = 0;
  double next_limit_m = order.empty() ? inf : rings[order[0]].limit_m;
  auto retireUpTo = [&](double t_m) {
    while (next_limit < order.size() && rings[order[next_limit]].limit_m <= t_m) {
      const int k = order[next_limit++];
      const std::uint64_t bit = std::uint64_t{1} << k;
      if (!(active & bit)) continue;
      active &= ~bit;
      if (rings[k].plane_hit) {
        hit_t_m[k] = rings[k].limit_m;
        hit_dz_m[k] = (rings[k].plane_surface == LidarSurface::kFloor ? world_.floor_m()
                                                                      : world_.ceiling_m()) -
                      z_m;
        hit_surface[k] = rings[k].plane_surface;
      }
    }
    next_limit_m = next_limit < order.size() ? rings[order[next_limit]].limit_m : inf;
  };
  // Rings in increasing slope (their index order for a scan): the lowest and highest active
  // ring bound the heights all active rings reach in a cell.
  bool slopes_sorted = true;
  for (int k = 1; k < n; ++k) slopes_sorted = slopes_sorted && rings[k - 1].slope <= rings[k].slope;

  const GridGeometry& g = world_.geometry();
  const double res = g.resolution_m();
  GridRay ray((origin_m - g.origin_m()) / res, cos_az, sin_az);
  const int x = ray.x(), y = ray.y();
  const int w = g.width(), h = g.height();
  const int step_x = ray.stepX();
  const int step_y = ray.stepY();
  double t_in = 0.0;
  if (x < 0 || y < 0 || x >= w || y >= h) return;
  // Steps left before the ray leaves the raster along x and along y.
  int steps_x = step_x > 0 ? w - 1 - x : x;
  int steps_y = step_y > 0 ? h - 1 - y : y;
  const std::ptrdiff_t cell_step_y = static_cast<std::ptrdiff_t>(step_y) * w;
  std::ptrdiff_t cell = static_cast<std::ptrdiff_t>(y) * w + x;
  const std::uint8_t* clear_cells = clear_cells_.data();
  // Margin of the tests that skip cells and rings that cannot give a hit: far above the
  // rounding of the heights compared (1e-15 m), far below any geometry, so every hit is
  // computed exactly as without the tests.
  constexpr double kSkipMargin_m = 1e-6;
  constexpr int kMinJumpClearance = 3;  // jump over squares of radius 2 and more
  for (;;) {
    const int code = clear_cells[cell];
    const int clear =
        code - (kClearBase - 1);  // chessboard distance to a solid column (<= 0: solid)
    if (clear >= kMinJumpClearance) {
      // Every cell within clear - 1 of this one (chessboard distance) is empty: jump to the
      // step that leaves that square, in the same cell with the same parameters as one step at
      // a time (GridRay::jump); only the branchy per-cell loop is replaced by two independent
      // chains of additions.
      const int radius = clear - 1;
      const GridRay::Jump jump =
          ray.jump(std::min(radius, steps_x) + 1, std::min(radius, steps_y) + 1);
      const double t_out = jump.t_out;
      cell += static_cast<std::ptrdiff_t>(jump.x_steps) * step_x + jump.y_steps * cell_step_y;
      steps_x -= jump.x_steps;
      steps_y -= jump.y_steps;
      const double t_out_m = t_out * res;
      if (t_out_m >= next_limit_m) retireUpTo(t_out_m);
      if (!active || steps_x < 0 || steps_y < 0) return;
      t_in = t_out;
      continue;
    }
    const bool along_x = ray.leavesAlongX();
    const double t_out = ray.exitT();
    const double t_out_m = t_out * res;
    if (clear <= 0) {
      const double t_in_m = t_in * res;
      // A column of a common kind is read from the kinds' table (in cache), not the column.
      const std::span<const ZInterval> spans =
          code == kReadColumn
              ? world_.intervals(static_cast<std::size_t>(cell))
              : std::span<const ZInterval>(kind_spans_.data() + kind_offsets_[code],
                                           kind_spans_.data() + kind_offsets_[code + 1]);
      // Heights the active rings span in this cell (conservative: over [t_in_m, t_out_m]):
      // a cell whose spans all lie outside them (by a margin far above the rounding of the
      // heights compared, 1e-15 m, and far below any geometry) cannot give a hit.
      double z_lo = inf, z_hi = -inf;
      if (slopes_sorted) {
        const double lo = rings[std::countr_zero(active)].slope,
                     hi = rings[63 - std::countl_zero(active)].slope;
        z_lo = z_m + std::min(lo * t_in_m, lo * t_out_m);
        z_hi = z_m + std::max(hi * t_in_m, hi * t_out_m);
      } else {
        for (std::uint64_t bits = active; bits; bits &= bits - 1) {
          const double sl = rings[std::countr_zero(bits)].slope;
          z_lo = std::min(z_lo, z_m + std::min(sl * t_in_m, sl * t_out_m));
          z_hi = std::max(z_hi, z_m + std::max(sl * t_in_m, sl * t_out_m));
        }
      }
      bool reachable = false;
      for (const ZInterval& s : spans) {
        reachable =
            reachable || (s.z_min_m <= z_hi + kSkipMargin_m && s.z_max_m >= z_lo - kSkipMargin_m);
      }
      for (std::uint64_t bits = reachable ? active : 0; bits;) {
        const int k = std::countr_zero(bits);
        bits &= bits - 1;
        const Ring& r = rings[k];
        const double t_end = std::min(t_out_m, r.limit_m);
        if (t_in_m > t_end) continue;
        const double z_in = z_m + r.slope * t_in_m;
        // Heights this ring spans in the cell: a span outside them (with the same margin as
        // above) gives no hit, so the exact test below runs only where one is possible.
        const double z_end = z_m + r.slope * t_end;
        const double ring_lo = std::min(z_in, z_end) - kSkipMargin_m,
                     ring_hi = std::max(z_in, z_end) + kSkipMargin_m;
        bool near = false;
        for (const ZInterval& s : spans)
          near = near || (s.z_min_m <= ring_hi && s.z_max_m >= ring_lo);
        if (!near) continue;
        double t_hit = inf, dz_hit = 0.0;
        for (const ZInterval& s : spans) {
          if (s.z_min_m <= z_in && z_in <= s.z_max_m) {
            t_hit = t_in_m;  // the column's side face
            dz_hit = z_in - z_m;
            break;
          }
          if (r.slope > 0.0 && z_in < s.z_min_m && (s.z_min_m - z_m) / r.slope < t_hit) {
            t_hit = (s.z_min_m - z_m) / r.slope;  // an underside, going up
            dz_hit = s.z_min_m - z_m;
          } else if (r.slope < 0.0 && z_in > s.z_max_m && (s.z_max_m - z_m) / r.slope < t_hit) {
            t_hit = (s.z_max_m - z_m) / r.slope;  // a top face, going down
            dz_hit = s.z_max_m - z_m;
          }
        }
        if (t_hit <= t_end) {
          hit_t_m[k] = t_hit;
          hit_dz_m[k] = dz_hit;
          hit_surface[k] = LidarSurface::kObject;
          active &= ~(std::uint64_t{1} << k);
        }
      }
    }
    if (t_out_m >= next_limit_m) retireUpTo(t_out_m);
    if (!active) return;
    // Next cell; the ray ends where it leaves the raster.
    if (along_x) {
      if (--steps_x < 0) return;
      cell += step_x;
    } else {
      if (--steps_y < 0) return;
      cell += cell_step_y;
    }
    ray.step();
    t_in = t_out;
  }
  // Beyond the raster there is neither floor nor ceiling: remaining rings have no return.
}

LidarScan LidarSimulator::scan(const Pose2& T_map_robot) {
  LidarScan scan;
  scan.T_map_sensor = sensorPose(T_map_robot);
  const double z_m = scan.T_map_sensor.translation().z();
  std::vector<int> order;
  const std::vector<Ring> rings = makeRings(elevations_rad_, z_m, options_.range_max_m, order);
  const int n = static_cast<int>(rings.size());
  std::vector<double> t(n), dz(n);
  std::vector<LidarSurface> surface(n);
  const double cy = std::cos(T_map_robot.yaw_rad), sy = std::sin(T_map_robot.yaw_rad);
  const Eigen::Vector2d origin(T_map_robot.x_m, T_map_robot.y_m);
  const bool noisy = !noise_.none();
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::bernoulli_distribution dropout(noise_.dropout_probability);
  scan.points_sensor.reserve(static_cast<std::size_t>(columns()) * n);
  scan.surfaces.reserve(scan.points_sensor.capacity());
  for (int c = 0; c < columns(); ++c) {
    const double ca = cos_azimuth_[c], sa = sin_azimuth_[c];
    castColumn(origin, z_m, cy * ca - sy * sa, sy * ca + cy * sa, rings, order, t.data(), dz.data(),
               surface.data());
    for (int k = 0; k < n; ++k) {
      if (t[k] < 0.0) continue;
      const double r_true = t[k] / rings[k].cos_elev;
      double r = r_true;
      if (noisy) {
        if (noise_.dropout_probability > 0.0 && dropout(rng_)) continue;  // a lost return: no point
        const double sd_m = noise_.sd_m(r_true);
        if (sd_m > 0.0) r += sd_m * gauss(rng_);
      }
      if (r < options_.range_min_m || r > options_.range_max_m) continue;
      const double scale = r_true > 0.0 ? r / r_true : 0.0;  // noise moves the point along its beam
      scan.points_sensor.emplace_back(static_cast<float>(scale * t[k] * ca),
                                      static_cast<float>(scale * t[k] * sa),
                                      static_cast<float>(scale * dz[k]));
      scan.surfaces.push_back(surface[k]);
    }
  }
  return scan;
}

std::optional<LidarHit> LidarSimulator::castRay(const Eigen::Vector3d& origin_map,
                                                double azimuth_rad, double elevation_rad,
                                                double max_range_m) const {
  std::vector<int> order;
  const std::vector<Ring> rings = makeRings({elevation_rad}, origin_map.z(), max_range_m, order);
  double t = -1.0, dz = 0.0;
  LidarSurface surface = LidarSurface::kObject;
  castColumn(origin_map.head<2>(), origin_map.z(), std::cos(azimuth_rad), std::sin(azimuth_rad),
             rings, order, &t, &dz, &surface);
  if (t < 0.0) return std::nullopt;
  return LidarHit{t / rings[0].cos_elev, surface};
}

}  // namespace roomscout::sim
