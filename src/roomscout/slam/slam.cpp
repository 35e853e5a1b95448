#include "roomscout/slam/slam.hpp"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/slam/CMetricMapBuilderRBPF.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>

#include "roomscout/core/errors.hpp"
#include "roomscout/slam/detail/graph_slam.hpp"

namespace roomscout::slam {

SlamMode SlamOptions::slamMode() const {
  if (mode == "none") return SlamMode::kNone;
  if (mode == "graph") return SlamMode::kGraph;
  if (mode == "icp") return SlamMode::kIcp;
  if (mode == "rbpf") return SlamMode::kRbpf;
  throw OptionError("slam.mode must be none, graph, icp or rbpf, not \"" + mode + "\"");
}

void SlamOptions::validate() const {
  slamMode();
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(match_distance_m)) throw OptionError("slam.match_distance_m must be > 0");
  if (!positive(match_angle_deg)) throw OptionError("slam.match_angle_deg must be > 0");
  if (!positive(insert_distance_m)) throw OptionError("slam.insert_distance_m must be > 0");
  if (!positive(insert_angle_deg)) throw OptionError("slam.insert_angle_deg must be > 0");
  if (particles < 1 || particles > 1000) throw OptionError("slam.particles must be in [1, 1000]");
  if (!positive(diverged_ate_m)) throw OptionError("slam.diverged_ate_m must be > 0");
  if (submap_scans < 4 || submap_scans > 10000) {
    throw OptionError("slam.submap_scans must be in [4, 10000]");
  }
  if (!(std::isfinite(max_range_m) && max_range_m >= 0.0)) {
    throw OptionError("slam.max_range_m must be >= 0 (0: the sensor's range)");
  }
  for (const auto& [name, value] :
       {std::pair{"odometry_sd_per_m", odometry_sd_per_m},
        std::pair{"odometry_rotation_sd_per_rad", odometry_rotation_sd_per_rad},
        std::pair{"odometry_rotation_sd_per_m", odometry_rotation_sd_per_m},
        std::pair{"range_sd_fraction", range_sd_fraction}}) {
    if (!std::isfinite(value) || (value < 0.0 && value != -1.0)) {
      throw OptionError(std::string("slam.") + name + " must be >= 0, or -1 for automatic");
    }
  }
  if (!positive(loop_search_distance_m))
    throw OptionError("slam.loop_search_distance_m must be > 0");
  if (!positive(loop_window_m) || loop_window_m > 10.0) {
    throw OptionError("slam.loop_window_m must be in (0, 10]");
  }
  if (!positive(loop_window_deg) || loop_window_deg > 180.0) {
    throw OptionError("slam.loop_window_deg must be in (0, 180]");
  }
  if (!(loop_min_score > 0.1 && loop_min_score < 0.9)) {
    throw OptionError("slam.loop_min_score must be in (0.1, 0.9)");
  }
  if (loop_every_n_nodes < 0) throw OptionError("slam.loop_every_n_nodes must be >= 0 (0: never)");
  if (optimise_every_n_nodes < 1) throw OptionError("slam.optimise_every_n_nodes must be >= 1");
  if (!positive(huber_scale)) throw OptionError("slam.huber_scale must be > 0");
}

std::vector<ParameterRef> SlamOptions::parameters() {
  return {
      {"mode", &mode,
       "none (the true pose), graph (roomscout's graph SLAM: submaps, loop closure, Ceres pose "
       "graph), icp (MRPT ICP-SLAM) or rbpf (MRPT particle-filter SLAM)"},
      {"match_distance_m", &match_distance_m,
       "distance driven (or match_angle_deg turned) before SLAM corrects the pose with the next "
       "scan (graph: before a scan becomes a node of the graph and joins the map); in between "
       "the pose follows the odometry [m]"},
      {"match_angle_deg", &match_angle_deg,
       "angle turned before SLAM corrects the pose with a scan [deg]"},
      {"insert_distance_m", &insert_distance_m,
       "icp, rbpf: distance driven (or insert_angle_deg turned) before a scan's points join "
       "SLAM's map [m]"},
      {"insert_angle_deg", &insert_angle_deg,
       "icp, rbpf: angle turned before a scan is added to the map [deg]"},
      {"particles", &particles, "rbpf: number of particles"},
      {"submap_scans", &submap_scans,
       "graph: nodes per submap; a new submap starts every half of it, so each scan is matched "
       "against a submap of between half and all of this many scans"},
      {"max_range_m", &max_range_m,
       "graph: beams are cut at this range for matching and mapping (0: the sensor's range); far "
       "returns are the least precise, and make large submaps"},
      {"odometry_sd_per_m", &odometry_sd_per_m,
       "graph: the odometry's along-track error after 1 m (sd) [m], for the prior on each "
       "match and the check that a match agrees with it; -1: in the simulator the simulated "
       "robot's odometry (noise.profile), elsewhere 0.1"},
      {"odometry_rotation_sd_per_rad", &odometry_rotation_sd_per_rad,
       "graph: the odometry's heading error after turning 1 rad (sd) [rad]; -1: automatic as "
       "above, elsewhere 0.2"},
      {"odometry_rotation_sd_per_m", &odometry_rotation_sd_per_m,
       "graph: the odometry's heading error after driving 1 m (sd) [rad]; -1: automatic as "
       "above, elsewhere 0.1"},
      {"range_sd_fraction", &range_sd_fraction,
       "graph: the laser's range noise (sd) as a fraction of the range, for fitting walls to "
       "noisy returns; -1: in the simulator the simulated laser's (noise.profile), elsewhere "
       "0.01"},
      {"loop_search_distance_m", &loop_search_distance_m,
       "graph: finished submaps with a node this close to a new node are searched for a loop "
       "closure [m]"},
      {"loop_window_m", &loop_window_m,
       "graph: a loop-closure search covers this far from the estimate on each axis [m]"},
      {"loop_window_deg", &loop_window_deg,
       "graph: ... and this many degrees either side of its heading [deg]"},
      {"loop_min_score", &loop_min_score,
       "graph: a loop closure needs this mean occupancy probability of the scan's points on the "
       "submap, before and after refinement (0.5 is a scan on unknown ground)"},
      {"loop_every_n_nodes", &loop_every_n_nodes,
       "graph: every n-th node is searched for loop closures (0: never)"},
      {"optimise_every_n_nodes", &optimise_every_n_nodes,
       "graph: after new loop closures, the pose graph is solved once this many nodes have "
       "been added since the last solve (and at the end)"},
      {"huber_scale", &huber_scale,
       "graph: a loop closure off by more than this many standard deviations pulls with a "
       "constant force (Huber loss), so a wrong one cannot bend the map"},
      {"diverged_ate_m", &diverged_ate_m,
       "position RMSE against the truth above which a run is marked diverged and does not count as "
       "a success [m]"},
  };
}

namespace {

using Clock = std::chrono::steady_clock;

/// MRPT's particle filter draws from one process-wide generator: rbpf instances take turns and
/// reseed it from their own seed, so that each run is repeatable whatever else runs.
std::mutex& mrptRandomMutex() {
  static std::mutex m;
  return m;
}

mrpt::poses::CPose2D toMrpt(const Pose2& p) { return {p.x_m, p.y_m, p.yaw_rad}; }

}  // namespace

struct Slam::Impl {
  SlamOptions options;
  SlamMode mode = SlamMode::kNone;
  std::uint64_t seed = 0;
  std::uint64_t updates = 0;
  std::unique_ptr<mrpt::slam::CMetricMapBuilder> builder;
  std::unique_ptr<detail::GraphSlam> graph;
  std::optional<Pose2> last_odometry;
  Pose2 map_from_odom;  ///< the last estimate composed with its odometry's inverse
  std::vector<double> update_ms;
  std::vector<Pose2> trajectory;  ///< icp, rbpf: the estimate after each update
  bool finished = false;
  /// Time stamps: MRPT's ICP-SLAM stamps the start pose with the wall clock and trusts odometry
  /// only when it is newer, so updates are stamped after it at a fixed interval (their values
  /// matter only in that order: no velocities are given, so nothing is extrapolated).
  mrpt::Clock::time_point stamp_base;

  /// The laser points new scans are aligned with: 5 cm apart at least, a new point fused with
  /// an old one it falls on, so that the map and the cost of matching grow with the area seen
  /// rather than with the distance driven.
  static mrpt::maps::CSimplePointsMap::TMapDefinition pointsDefinition() {
    mrpt::maps::CSimplePointsMap::TMapDefinition def;
    def.insertionOpts.minDistBetweenLaserPoints = 0.05f;
    def.insertionOpts.isPlanarMap = true;
    def.insertionOpts.fuseWithExisting = true;
    return def;
  }

  void configureIcp(mrpt::slam::CICP::TConfigParams& icp) const {
    // MRPT's demo values for laser ICP-SLAM (icp-slam_demo_classic.ini), but pairs at most
    // 15 cm apart: the scans are matched every few centimetres of odometry, and a wider
    // window pairs the two faces of a thin wall more often (see docs/slam.md, Limits).
    icp.maxIterations = 60;
    icp.thresholdDist = 0.15;
    icp.thresholdAng = 1.0 * M_PI / 180.0;
    icp.ALFA = 0.5;
    icp.smallestThresholdDist = 0.03;
    icp.corresponding_points_decimation = 3;
  }
};

namespace {

detail::GraphSlamOptions graphOptions(const SlamOptions& o) {
  detail::GraphSlamOptions g;
  g.node_distance_m = o.match_distance_m;
  g.node_angle_rad = o.match_angle_deg * M_PI / 180.0;
  g.submap_scans = o.submap_scans;
  g.max_range_m = o.max_range_m;
  if (o.odometry_sd_per_m >= 0.0) g.odometry_sd_per_m = o.odometry_sd_per_m;
  if (o.odometry_rotation_sd_per_rad >= 0.0) {
    g.odometry_rotation_sd_per_rad = o.odometry_rotation_sd_per_rad;
  }
  if (o.odometry_rotation_sd_per_m >= 0.0)
    g.odometry_rotation_sd_per_m = o.odometry_rotation_sd_per_m;
  if (o.range_sd_fraction >= 0.0) g.match.range_sd_fraction = o.range_sd_fraction;
  g.loop_search_distance_m = o.loop_search_distance_m;
  g.loop_window_m = o.loop_window_m;
  g.loop_window_rad = o.loop_window_deg * M_PI / 180.0;
  g.loop_min_score = o.loop_min_score;
  g.loop_every_n_nodes = o.loop_every_n_nodes;
  g.optimise_every_n_nodes = o.optimise_every_n_nodes;
  g.graph.huber_scale = o.huber_scale;
  return g;
}

}  // namespace

Slam::Slam(const SlamOptions& options, const Pose2& start, std::uint64_t seed,
           const OccupancyGridOptions& cells, std::optional<GridGeometry> map_geometry)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  Impl& s = *impl_;
  s.options = options;
  s.mode = options.slamMode();
  if (s.mode == SlamMode::kNone) throw OptionError("slam.mode is none: there is no SLAM to run");
  if (!isFinite(start)) {
    throw InvalidArgument("SLAM: the start pose is not finite");
  }
  s.seed = seed;
  if (s.mode == SlamMode::kGraph) {
    cells.validate();
    s.graph = std::make_unique<detail::GraphSlam>(graphOptions(options), cells, map_geometry);
    return;
  }

  const mrpt::poses::CPosePDFGaussian x0(toMrpt(start));
  const double deg = M_PI / 180.0;
  try {
    if (s.mode == SlamMode::kIcp) {
      auto icp = std::make_unique<mrpt::slam::CMetricMapBuilderICP>();
      icp->setVerbosityLevel(mrpt::system::LVL_ERROR);
      auto& o = icp->ICP_options;
      o.matchAgainstTheGrid = false;
      o.insertionLinDistance = options.insert_distance_m;
      o.insertionAngDistance = options.insert_angle_deg * deg;
      o.localizationLinDistance = options.match_distance_m;
      o.localizationAngDistance = options.match_angle_deg * deg;
      o.minICPgoodnessToAccept = 0.2;  // noisy scans pair fewer points within 15 cm
      o.mapInitializers.clear();
      o.mapInitializers.push_back(Impl::pointsDefinition());
      s.configureIcp(icp->ICP_params);
      icp->initialize(mrpt::maps::CSimpleMap(), &x0);
      s.builder = std::move(icp);
    } else {
      mrpt::slam::CMetricMapBuilderRBPF::TConstructionOptions c;
      c.insertionLinDistance = static_cast<float>(options.insert_distance_m);
      c.insertionAngDistance = static_cast<float>(options.insert_angle_deg * deg);
      c.localizeLinDistance = static_cast<float>(options.match_distance_m);
      c.localizeAngDistance = static_cast<float>(options.match_angle_deg * deg);
      c.PF_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfOptimalProposal;
      c.PF_options.resamplingMethod = mrpt::bayes::CParticleFilter::prMultinomial;
      c.PF_options.adaptiveSampleSize = false;
      c.PF_options.sampleSize = static_cast<unsigned>(options.particles);
      c.PF_options.BETA = 0.5;
      c.mapsInitializers.clear();
      auto points = Impl::pointsDefinition();
      points.likelihoodOpts.sigma_dist = 0.1;  // a point's likelihood falls off over 10 cm
      c.mapsInitializers.push_back(points);
      c.predictionOptions.pfOptimalProposal_mapSelection = 3;  // ICP against each particle's points
      s.configureIcp(c.predictionOptions.icp_params);
      c.verbosity_level = mrpt::system::LVL_ERROR;
      std::lock_guard lock(mrptRandomMutex());
      mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(seed ^ (seed >> 32)));
      auto rbpf = std::make_unique<mrpt::slam::CMetricMapBuilderRBPF>(c);
      rbpf->setVerbosityLevel(mrpt::system::LVL_ERROR);
      rbpf->mapPDF.setVerbosityLevel(mrpt::system::LVL_ERROR);
      rbpf->initialize(mrpt::maps::CSimpleMap(), &x0);
      s.builder = std::move(rbpf);
    }
    s.stamp_base = mrpt::Clock::now() + std::chrono::seconds(1);
  } catch (const std::exception& e) {
    throw InvalidArgument(std::string("SLAM (") + options.mode +
                          "): MRPT failed to initialise: " + e.what());
  }
}

Slam::~Slam() = default;

CellRect Slam::update(const LaserScan& scan, const Pose2& odometry) {
  Impl& s = *impl_;
  if (s.finished) throw InvalidArgument("SLAM: update() after finish()");
  const auto t0 = Clock::now();
  const std::size_t n = scan.ranges_m.size();
  if (n < 2 || !(scan.angle_increment_rad > 0.0)) {
    throw InvalidArgument("SLAM: a scan needs at least two beams and a positive angle increment");
  }
  if (!isFinite(odometry)) {
    throw InvalidArgument("SLAM: the odometry pose is not finite");
  }
  if (s.graph) {
    // A NaN or negative range is no measurement at all: a beam to drop, not free space.
    LaserScan clean = scan;
    for (float& r : clean.ranges_m) {
      if (std::isnan(r) || r < 0.0f || r == -std::numeric_limits<float>::infinity()) r = -1.0f;
    }
    if (!(clean.range_min_m > 0.0)) clean.range_min_m = 1e-3;
    const CellRect changed = s.graph->update(clean, odometry);
    ++s.updates;
    s.update_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    return changed;
  }

  // The odometry increment since the previous scan, with MRPT's default Gaussian motion model.
  const Pose2 increment = s.last_odometry ? compose(inverse(*s.last_odometry), odometry) : Pose2{};
  s.last_odometry = odometry;
  const auto stamp = s.stamp_base + std::chrono::milliseconds(200 * s.updates);
  mrpt::obs::CActionRobotMovement2D movement;
  movement.computeFromOdometry(toMrpt(increment),
                               mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
  movement.timestamp = stamp;
  mrpt::obs::CActionCollection actions;
  actions.insert(movement);

  // The scan: MRPT spreads N beams evenly over its aperture, centred on the sensor's heading.
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  obs->resizeScan(n);
  obs->aperture = static_cast<float>(scan.angle_increment_rad * static_cast<double>(n - 1));
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(scan.range_max_m);
  obs->sensorPose = mrpt::poses::CPose3D(0, 0, 0, scan.angle_min_rad + 0.5 * obs->aperture, 0, 0);
  obs->sensorLabel = "LASER";
  obs->timestamp = stamp;
  for (std::size_t i = 0; i < n; ++i) {
    const float r = scan.ranges_m[i];
    const bool valid = std::isfinite(r) && r >= scan.range_min_m && r <= scan.range_max_m;
    // No return, too close or dropped: not a point to match.
    obs->setScanRange(i, valid ? r : 0.0f);
    obs->setScanRangeValidity(i, valid);
  }
  mrpt::obs::CSensoryFrame frame;
  frame.insert(obs);

  try {
    if (s.mode == SlamMode::kRbpf) {
      std::lock_guard lock(mrptRandomMutex());
      const std::uint64_t draw = s.seed * 0x9E3779B97F4A7C15ull + s.updates;
      mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(draw ^ (draw >> 32)));
      s.builder->processActionObservation(actions, frame);
    } else {
      s.builder->processActionObservation(actions, frame);
    }
    ++s.updates;
    const mrpt::math::TPose3D estimate =
        s.builder->getCurrentPoseEstimation()->getMeanVal().asTPose();
    s.map_from_odom = compose(Pose2{estimate.x, estimate.y, estimate.yaw}, inverse(odometry));
    s.trajectory.push_back(Pose2{estimate.x, estimate.y, wrapAngle(estimate.yaw)});
  } catch (const InvalidArgument&) {
    throw;
  } catch (const std::exception& e) {
    throw InvalidArgument(std::string("SLAM (") + s.options.mode + "): MRPT failed: " + e.what());
  }
  s.update_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  return {};
}

Pose2 Slam::pose(const Pose2& odometry) const {
  if (impl_->graph) return impl_->graph->pose(odometry);
  return compose(impl_->map_from_odom, odometry);
}

CellRect Slam::finish() {
  Impl& s = *impl_;
  if (s.finished) return {};
  s.finished = true;
  return s.graph ? s.graph->finish() : CellRect{};
}

std::vector<Pose2> Slam::trajectory() const {
  return impl_->graph ? impl_->graph->trajectory() : impl_->trajectory;
}

const OccupancyGrid* Slam::map() const { return impl_->graph ? impl_->graph->map() : nullptr; }

SlamStats Slam::stats() const {
  SlamStats out;
  if (!impl_->graph) return out;
  const detail::GraphSlamStats& g = impl_->graph->stats();
  out.nodes = g.nodes;
  out.submaps = g.submaps;
  out.matches_rejected = g.matches_rejected;
  out.matches_degenerate = g.matches_degenerate;
  out.loop_closures = g.loop_closures;
  out.optimisations = g.optimisations;
  out.loop_search_ms = g.loop_search_ms;
  out.optimise_ms = g.optimise_ms;
  return out;
}

SlamMode Slam::mode() const { return impl_->mode; }

const std::vector<double>& Slam::updateTimes_ms() const { return impl_->update_ms; }

}  // namespace roomscout::slam
