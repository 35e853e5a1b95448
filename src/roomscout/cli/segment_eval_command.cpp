// `roomscout segment-eval`: the room segmentation benchmark of Bormann et al. (ICRA 2016) on a
// folder laid out like ../shared/data/room_segmentation/, scored with its protocol.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "roomscout/cli/map_commands.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/options_yaml.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/io/semantic_io.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace roomscout::cli {
namespace {

struct SegmentEvalArgs {
  std::string dataset;
  std::string out;
  std::string config;
  bool images = false;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int runSegmentEval(const SegmentEvalArgs& args) {
  RoomSegmenterOptions seg_options;
  TopologyBuilderOptions topo_options;
  std::vector<ParameterGroup> groups{{"segmentation", seg_options.parameters()},
                                     {"topology", topo_options.parameters()}};
  if (!args.config.empty()) io::applyConfigFile(args.config, groups);
  const RoomSegmenter segmenter(seg_options);
  const TopologyBuilder builder(topo_options);
  const std::vector<io::SegmentationDatasetMap> maps = io::listSegmentationDataset(args.dataset);
  io::OutputDirectory out(args.out);  // removed again if the command fails and it is empty
  const double resolution_m = 0.05;   // the benchmark's maps, all of them

  nlohmann::json rows = nlohmann::json::array();
  nlohmann::json summary = nlohmann::json::object();
  std::printf("%-22s %-9s %5s %5s %8s %8s %8s %8s %7s %8s %8s\n", "map", "variant", "rooms", "segs",
              "recall", "precis", "p.recall", "p.precis", "IoU", "seg ms", "topo ms");
  for (const char* variant : {"plain", "furnished"}) {
    const bool furnished = std::string(variant) == "furnished";
    std::vector<double> seg_ms, topo_ms;
    double sum_r = 0, sum_p = 0, sum_iou = 0, sum_pr = 0, sum_pp = 0;
    int count = 0;
    for (const io::SegmentationDatasetMap& m : maps) {
      if (furnished && !m.furnished_png) continue;
      const cv::Mat grey = io::readGreyImage(furnished ? *m.furnished_png : m.plain_png);
      const cv::Mat gt_grey = io::readGreyImage(m.ground_truth_png);
      if (gt_grey.size() != grey.size())
        throw InputError(m.ground_truth_png.string(), "size differs from the map");
      const cv::Mat states = io::benchmarkStates(grey);
      auto t0 = std::chrono::steady_clock::now();
      const RoomSegmentation seg = segmenter.segment(states, resolution_m);
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      t0 = std::chrono::steady_clock::now();
      const TopologicalMap topo = builder.build(
          states, GridGeometry(Vec2::Zero(), resolution_m, states.cols, states.rows), nullptr);
      const double tms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const SegmentationScore s = scoreSegmentation(seg.labels, groundTruthRooms(gt_grey));
      seg_ms.push_back(ms);
      topo_ms.push_back(tms);
      sum_r += s.recall;
      sum_p += s.precision;
      sum_pr += s.pooled_recall;
      sum_pp += s.pooled_precision;
      sum_iou += s.iou;
      ++count;
      std::printf("%-22s %-9s %5d %5d %7.1f%% %7.1f%% %7.1f%% %7.1f%% %6.1f%% %8.1f %8.1f\n",
                  m.name.c_str(), variant, s.ground_truth_rooms, s.segments, 100 * s.recall,
                  100 * s.precision, 100 * s.pooled_recall, 100 * s.pooled_precision, 100 * s.iou,
                  ms, tms);
      rows.push_back({{"map", m.name},
                      {"variant", variant},
                      {"ground_truth_rooms", s.ground_truth_rooms},
                      {"segments", s.segments},
                      {"recall", s.recall},
                      {"precision", s.precision},
                      {"pooled_recall", s.pooled_recall},
                      {"pooled_precision", s.pooled_precision},
                      {"iou", s.iou},
                      {"segmentation_ms", ms},
                      {"topology_ms", tms},
                      {"topology_nodes", topo.nodes().size()},
                      {"topology_edges", topo.edges().size()}});
      if (args.images) {
        io::writeImageAtomic(
            std::filesystem::path(args.out) / (m.name + "_" + variant + "_segmentation.png"),
            io::colourLabels(seg.labels, grey));
      }
    }
    if (count == 0) continue;
    const double n = count;
    summary[variant] = {{"maps", count},
                        {"recall", sum_r / n},
                        {"precision", sum_p / n},
                        {"pooled_recall", sum_pr / n},
                        {"pooled_precision", sum_pp / n},
                        {"iou", sum_iou / n},
                        {"median_segmentation_ms", median(seg_ms)},
                        {"median_topology_ms", median(topo_ms)}};
    std::printf("%-22s %-9s %5s %5s %7.1f%% %7.1f%% %7.1f%% %7.1f%% %6.1f%% %8.1f %8.1f\n",
                "MEAN (median ms)", variant, "", "", 100 * sum_r / n, 100 * sum_p / n,
                100 * sum_pr / n, 100 * sum_pp / n, 100 * sum_iou / n, median(seg_ms),
                median(topo_ms));
  }
  nlohmann::json options = nlohmann::json::object();
  for (const ParameterGroup& g : groups) options[g.name] = io::parametersToJson(g.parameters);
  const nlohmann::json results = {
      {"dataset", args.dataset},
      {"protocol", "Bormann et al. ICRA 2016: free >= 250, regions <= 100 cells dropped"},
      {"summary", summary},
      {"maps", rows},
      {"options", options}};
  io::writeFileAtomic(std::filesystem::path(args.out) / "results.json", results.dump(2) + "\n");
  out.keep();
  return 0;
}

}  // namespace

Subcommand addSegmentEvalCommand(CLI::App& app) {
  auto args = std::make_shared<SegmentEvalArgs>();
  CLI::App* cmd =
      app.add_subcommand("segment-eval", "Score the room segmentation on a benchmark folder");
  cmd->add_option("--dataset", args->dataset,
                  "folder of NAME.png, NAME_furnitures.png, NAME_gt_segmentation.png")
      ->required();
  cmd->add_option("--out", args->out, "output directory (results.json)")->required();
  cmd->add_option("--config", args->config, "YAML file with groups 'segmentation' and 'topology'");
  cmd->add_flag("--images", args->images, "also write each segmentation as a colour PNG");
  return {cmd, [args] { return runSegmentEval(*args); }};
}

}  // namespace roomscout::cli
