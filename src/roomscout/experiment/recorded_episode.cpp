#include "roomscout/experiment/recorded_episode.hpp"

#include <vector>

#include <Eigen/Core>

#include "roomscout/experiment/analysis_maps_output.hpp"
#include "roomscout/experiment/run_outputs.hpp"
#include "roomscout/explorer/explorer.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/options_yaml.hpp"
#include "roomscout/io/pcd_io.hpp"
#include "roomscout/io/point_cloud_render.hpp"
#include "roomscout/sim/point_cloud_observer.hpp"

namespace roomscout::experiment {
namespace {

/// The files an episode writes (the directory may hold others from earlier runs).
constexpr const char* kOutputFiles[] = {"occupancy.pgm",  "occupancy.yaml", "pointcloud.pcd",
                                        "pointcloud.png", "topology.json",  "topology.png",
                                        "semantic.json",  "semantic.png",   "semantic_labels.png",
                                        "trajectory.csv", "run.png",        "metrics.json"};

}  // namespace

RecordedEpisode runRecordedEpisode(const sim::WorldModel& model, EpisodeSetup& setup,
                                   const RunSettings& settings,
                                   const std::filesystem::path& directory,
                                   const sim::EpisodeProgress& progress) {
  io::ensureWritableDirectory(directory);
  // The point cloud on one worker, the rooms and skeleton on the Explorer's, both below the
  // episode's thread: on two cores the episode keeps a core and the workers share the other
  // and what it leaves. Declared before the observer, which waits for its jobs when it goes.
  MapWorker cloud_worker(settings.background_maps);
  sim::PointCloudObserver cloud(model, setup.cloud, setup.seed ^ 0x5851F42D4C957F2Dull,
                                &cloud_worker);
  ExplorerOptions options = sim::explorerOptionsFor(model, setup.config);
  options.all_maps = true;
  options.background_maps = settings.background_maps;
  Explorer explorer(*setup.strategy, options);
  RecordedEpisode recorded;
  recorded.result = sim::runEpisode(model, setup.config, explorer, setup.seed, progress, {&cloud});
  const sim::EpisodeResult& result = recorded.result;

  const sim::World& world = model.world();
  experiment::RunInfo info{world.name, world.source,        setup.method,
                           setup.seed, setup.optionsJson(), {}};
  {
    // The point cloud map, in the frame of occupancy.yaml; written before metrics.json.
    const std::vector<Eigen::Vector3f> points = cloud.map().points();
    const std::filesystem::path pcd = directory / "pointcloud.pcd";
    io::writePcdAtomic(
        pcd, points, settings.pcd_format,
        "roomscout point cloud map, map frame of occupancy.yaml; " + cloud.description(),
        settings.pcd_precision_m);
    io::writeImageAtomic(directory / "pointcloud.png",
                         io::renderPointCloud(points, cloud.columns().ceiling_m() - 0.1));
    nlohmann::json& record = info.maps["pointcloud"];
    record["file"] = "pointcloud.pcd";
    record["format"] = std::string(io::pcdFormatName(settings.pcd_format));
    record["precision_m"] = settings.pcd_precision_m;
    record["points"] = points.size();
    record["file_bytes"] = std::filesystem::file_size(pcd);
    record["memory_bytes"] = cloud.map().memoryBytes();
    record["scans"] = cloud.scans();
    record["keyframes"] = cloud.keyframes();
    record["built"] = cloud.description();
  }
  const nlohmann::json analysis_maps = experiment::writeAnalysisMaps(
      directory, *explorer.roomMap(), *explorer.skeletonMap(), result.map, &model);
  for (const auto& [name, summary] : analysis_maps.items()) info.maps[name] = summary;
  experiment::writeRunOutputs(directory, info, result);
  recorded.metrics = experiment::metricsJson(info, result);

  for (const char* name : kOutputFiles) {
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(directory / name, ec);
    if (!ec) recorded.file_bytes[name] = bytes;
  }
  return recorded;
}

}  // namespace roomscout::experiment
