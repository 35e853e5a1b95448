#include "roomscout/experiment/run_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/format.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"

namespace roomscout::experiment {
namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json timing(const sim::TimingStats& s) {
  nlohmann::json t = {{"median", s.median_ms}, {"p95", s.p95_ms}, {"count", s.count}};
  if (!s.by_known_area.empty()) {
    nlohmann::json bins = nlohmann::json::array();
    for (const sim::TimingStats::AreaBin& b : s.by_known_area)
      bins.push_back({b.known_max_m2, b.count, b.median_ms, b.p95_ms});
    t["by_known_area_columns"] = {"known_max_m2", "count", "median", "p95"};
    t["by_known_area"] = std::move(bins);
  }
  return t;
}

std::string trajectoryCsv(const sim::EpisodeResult& result) {
  // With SLAM, the estimated pose follows the true one on each line.
  const bool slam = result.slam.has_value();
  std::string out =
      slam ? "time_s,x_m,y_m,yaw_rad,est_x_m,est_y_m,est_yaw_rad\n" : "time_s,x_m,y_m,yaw_rad\n";
  for (const sim::TrajectorySample& s : result.trajectory) {
    out += slam ? formatString("%.2f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", s.time_s, s.pose.x_m,
                               s.pose.y_m, s.pose.yaw_rad, s.estimate.x_m, s.estimate.y_m,
                               s.estimate.yaw_rad)
                : formatString("%.2f,%.4f,%.4f,%.4f\n", s.time_s, s.pose.x_m, s.pose.y_m,
                               s.pose.yaw_rad);
  }
  return out;
}

}  // namespace

nlohmann::json metricsJson(const RunInfo& info, const sim::EpisodeResult& r) {
  nlohmann::json update_ms = {{"occupancy", timing(r.occupancy_update)},
                              {"costmap", timing(r.costmap_update)},
                              {"decision", timing(r.decision)}};
  for (const auto& [name, stats] : r.map_updates) update_ms[name] = timing(stats);
  if (r.slam) update_ms["slam"] = timing(r.slam_update);
  nlohmann::json curve = nlohmann::json::array();
  for (const sim::CurveSample& c : r.curve) curve.push_back({c.time_s, c.length_m, c.rate});
  nlohmann::json metrics = {
      {"world", info.world},
      {"world_source", info.world_source},
      {"method", info.method},
      {"seed", info.seed},
      {"exploration_rate", r.exploration_rate},
      {"t98_s", optionalNumber(r.t98_s)},
      {"l98_m", optionalNumber(r.l98_m)},
      {"t_done_s", optionalNumber(r.t_done_s)},
      {"l_done_m", optionalNumber(r.l_done_m)},
      {"timed_out", r.timed_out},
      {"sim_time_s", r.sim_time_s},
      {"length_m", r.length_m},
      {"max_time_s", r.max_time_s},
      {"reachable_area_m2", r.reachable_area_m2},
      // null without ground-truth rooms, so that reports show no count instead of a zero.
      {"revisits", r.room_truth ? nlohmann::json(r.revisits) : nlohmann::json(nullptr)},
      {"revisits_98",
       r.room_truth && r.revisits98 ? nlohmann::json(*r.revisits98) : nlohmann::json(nullptr)},
      {"rooms_entered", r.room_truth ? nlohmann::json(r.rooms_entered) : nlohmann::json(nullptr)},
      {"goals", r.goals},
      {"goal_failures", r.goal_failures},
      {"recoveries", r.recoveries},
      {"stalls", r.stalls},
      {"wall_time_s", r.wall_time_s},
      {"map_accuracy",
       {{"false_occupied", r.map_accuracy.false_occupied},
        {"occupied_precision", r.map_accuracy.occupied_precision},
        {"occupied_recall", r.map_accuracy.occupied_recall},
        {"false_free", r.map_accuracy.false_free},
        {"free_coverage", r.map_accuracy.free_coverage}}},
      {"update_ms", update_ms},
      {"curve_columns", {"time_s", "length_m", "rate"}},
      {"curve", curve},
      {"options", info.options},
  };
  if (r.slam) {
    metrics["slam"] = {{"mode", r.slam->mode},
                       {"ate_rmse_m", r.slam->error.rmse_m},
                       {"ate_max_m", r.slam->error.max_m},
                       {"heading_rmse_rad", r.slam->error.heading_rmse_rad},
                       {"diverged", r.slam->diverged},
                       {"ate_final_rmse_m", r.slam->final_error.rmse_m},
                       {"ate_final_max_m", r.slam->final_error.max_m},
                       {"nodes", r.slam->nodes},
                       {"loop_closures", r.slam->loop_closures},
                       {"optimisations", r.slam->optimisations},
                       {"matches_rejected", r.slam->matches_rejected},
                       {"loop_search_ms", timing(r.slam->loop_search)},
                       {"optimise_ms", timing(r.slam->optimise)}};
  }
  if (!info.maps.is_null()) metrics["maps"] = info.maps;
  return metrics;
}

cv::Mat renderMapWithPath(const OccupancyGrid& grid, const std::vector<Pose2>& path) {
  const GridGeometry& g = grid.geometry();
  const int scale = std::max(1, std::min(4, 1200 / std::max(1, std::max(g.width(), g.height()))));
  cv::Mat image(g.height(), g.width(), CV_8UC3);
  for (int y = 0; y < g.height(); ++y) {
    cv::Vec3b* row = image.ptr<cv::Vec3b>(g.height() - 1 - y);
    for (int x = 0; x < g.width(); ++x) {
      switch (grid.state(Cell{x, y})) {
        case CellState::kFree:
          row[x] = {255, 255, 255};
          break;
        case CellState::kOccupied:
          row[x] = {0, 0, 0};
          break;
        case CellState::kUnknown:
          row[x] = {205, 205, 205};
          break;
      }
    }
  }
  cv::resize(image, image, {}, scale, scale, cv::INTER_NEAREST);
  auto toPixel = [&](const Pose2& p) {
    const double px = (p.x_m - g.origin_m().x()) / g.resolution_m() * scale;
    const double py = (g.height() - (p.y_m - g.origin_m().y()) / g.resolution_m()) * scale;
    return cv::Point(static_cast<int>(std::lround(px)), static_cast<int>(std::lround(py)));
  };
  for (std::size_t i = 1; i < path.size(); ++i) {
    cv::line(image, toPixel(path[i - 1]), toPixel(path[i]), cv::Scalar(200, 90, 20),
             std::max(1, scale / 2), cv::LINE_AA);
  }
  if (!path.empty()) {
    const int r = 3 * scale;
    cv::circle(image, toPixel(path.front()), r, cv::Scalar(40, 170, 40), cv::FILLED, cv::LINE_AA);
    cv::circle(image, toPixel(path.back()), r, cv::Scalar(30, 30, 220), cv::FILLED, cv::LINE_AA);
  }
  return image;
}

cv::Mat renderRun(const sim::EpisodeResult& result) {
  std::vector<Pose2> path;
  path.reserve(result.trajectory.size());
  for (const sim::TrajectorySample& s : result.trajectory) path.push_back(s.pose);
  return renderMapWithPath(result.map, path);
}

void writeRunOutputs(const std::filesystem::path& directory, const RunInfo& info,
                     const sim::EpisodeResult& result) {
  io::ensureWritableDirectory(directory);
  io::saveOccupancyMap(result.map, directory / "occupancy.yaml");
  io::writeFileAtomic(directory / "trajectory.csv", trajectoryCsv(result));
  io::writeImageAtomic(directory / "run.png", renderRun(result));
  // metrics.json last: its presence says the run's outputs are complete.
  io::writeFileAtomic(directory / "metrics.json", metricsJson(info, result).dump(2) + "\n");
}

}  // namespace roomscout::experiment
