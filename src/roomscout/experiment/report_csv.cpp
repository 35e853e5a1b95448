#include "roomscout/experiment/report_csv.hpp"

#include <optional>
#include <sstream>

#include "roomscout/core/format.hpp"
#include "roomscout/experiment/paper_reference.hpp"

namespace roomscout::experiment {
namespace {

std::string csvNumber(double v) { return formatString("%.6g", v); }
std::string csvNumber(const std::optional<double>& v) { return v ? csvNumber(*v) : ""; }

}  // namespace

std::string table1Csv(const Report& report) {
  std::ostringstream csv;
  csv << "world,is_group,worlds,method,method_label,episodes,successes,success_rate,t98_n,t98_"
         "mean_s,t98_sd_s,l98_n,l98_mean_m,l98_sd_m,revisits_n,revisits_mean,revisits_sd,paper_"
         "t_s,paper_l_m,oracle_worlds,oracle_l_mean_m,oracle_l_sd_m,l98_oracle_ratio_n,l98_"
         "oracle_ratio_mean,l98_oracle_ratio_sd,revisits_98_n,revisits_98_mean,revisits_98_sd,"
         "pairs,"
         "all_pairs,own_t98_n,own_t98_mean_s,own_t98_sd_s,own_l98_n,own_l98_mean_m,own_l98_sd_m,"
         "reference,l98_reference_ratio_n,l98_reference_ratio_mean,l98_reference_ratio_sd,t98_"
         "reference_ratio_mean,t98_reference_ratio_sd,semantic_pairs,beats_semantic\n";
  for (const ReportRow& row : report.rows) {
    const auto oracle = report.oracle.find(row.name);
    for (const std::string& method : report.methods) {
      const auto it = report.table1.find({row.name, method});
      if (it == report.table1.end()) continue;
      const MethodStats& s = it->second;
      const std::optional<PaperTimeLength> paper = paperTable1(row.name, method);
      std::string label = methodLabel(method);
      if (label.find_first_of(",\"") != std::string::npos) label = "\"" + label + "\"";
      const auto mean = [](const Stat& st) { return st.n ? csvNumber(st.mean) : std::string(); };
      csv << row.name << "," << (row.is_group ? 1 : 0) << "," << row.worlds << "," << method << ","
          << label << "," << s.episodes << "," << s.successes << ","
          << csvNumber(static_cast<double>(s.successes) / static_cast<double>(s.episodes)) << ","
          << s.t98_s.n << "," << mean(s.t98_s) << "," << csvNumber(s.t98_s.sd) << "," << s.l98_m.n
          << "," << mean(s.l98_m) << "," << csvNumber(s.l98_m.sd) << "," << s.revisits.n << ","
          << mean(s.revisits) << "," << csvNumber(s.revisits.sd) << ","
          << (paper ? csvNumber(paper->t_s) : "") << "," << (paper ? csvNumber(paper->l_m) : "")
          << ",";
      if (oracle != report.oracle.end()) {
        csv << oracle->second.worlds << "," << mean(oracle->second.length_m) << ","
            << csvNumber(oracle->second.length_m.sd);
      } else {
        csv << "0,,";
      }
      csv << "," << s.l98_oracle_ratio.n << "," << mean(s.l98_oracle_ratio) << ","
          << csvNumber(s.l98_oracle_ratio.sd) << "," << s.revisits_98.n << ","
          << mean(s.revisits_98) << "," << csvNumber(s.revisits_98.sd) << ",";
      const auto paired = report.paired.find(row.name);
      if (paired != report.paired.end()) {
        csv << paired->second.pairs << "," << paired->second.all_pairs;
      } else {
        csv << "0,0";
      }
      csv << "," << s.own_t98_s.n << "," << mean(s.own_t98_s) << "," << csvNumber(s.own_t98_s.sd)
          << "," << s.own_l98_m.n << "," << mean(s.own_l98_m) << "," << csvNumber(s.own_l98_m.sd)
          << "," << report.reference << "," << s.l98_reference_ratio.n << ","
          << mean(s.l98_reference_ratio) << "," << csvNumber(s.l98_reference_ratio.sd) << ","
          << mean(s.t98_reference_ratio) << "," << csvNumber(s.t98_reference_ratio.sd) << ","
          << s.semantic_pairs << "," << s.beats_semantic << "\n";
    }
  }
  return csv.str();
}

}  // namespace roomscout::experiment
