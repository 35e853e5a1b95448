// Decision time per call of every registered strategy on the built-in large_office: the
// first 900 simulated seconds of an episode (the map grows through the phase where frontier
// sets are largest), with the semantic map built as in `roomscout explore`. Reported as
// counters: decision median and p95 [ms] and the number of calls; the iteration time is the
// wall time of the whole partial episode.

#include <benchmark/benchmark.h>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"

namespace roomscout {
namespace {

void BM_StrategyDecisionLargeOffice(benchmark::State& state, const std::string& method) {
  static const sim::WorldModel model(sim::loadBuiltinWorld("large_office"));
  sim::EpisodeResult result;
  for (auto _ : state) {
    sim::EpisodeConfig config;
    config.episode.max_time_s = 900.0;
    config.resolve();
    auto strategy = createStrategy(method, 1);
    result = sim::runEpisode(model, config, *strategy, 1);
  }
  state.counters["decision_median_ms"] = result.decision.median_ms;
  state.counters["decision_p95_ms"] = result.decision.p95_ms;
  state.counters["decisions"] = static_cast<double>(result.decision.count);
}

const bool registered = [] {
  for (const std::string& name : strategyNames()) {
    benchmark::RegisterBenchmark(("BM_StrategyDecisionLargeOffice/" + name).c_str(),
                                 BM_StrategyDecisionLargeOffice, name)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace roomscout
