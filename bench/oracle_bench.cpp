// Oracle reference tour (sim/oracle_tour.hpp) on the built-in worlds, with the episode's
// default options. The counters are the reference lengths the benchmark report quotes.

#include <benchmark/benchmark.h>

#include "roomscout/experiment/oracle_tour.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"

namespace {

void BM_OracleTour(benchmark::State& state, const char* world_name) {
  const roomscout::sim::WorldModel world(roomscout::sim::loadBuiltinWorld(world_name));
  const roomscout::experiment::OracleTourOptions options =
      roomscout::experiment::oracleTourOptionsFor(roomscout::sim::EpisodeConfig{});
  roomscout::experiment::OracleTour tour;
  for (auto _ : state) {
    tour = roomscout::experiment::planOracleTour(world, options);
    benchmark::DoNotOptimize(tour.length_m);
  }
  state.counters["length_m"] = tour.length_m;
  state.counters["viewpoints"] = static_cast<double>(tour.viewpointCount());
  state.counters["coverage"] = tour.coverage;
  state.counters["candidates"] = tour.candidates;
}

BENCHMARK_CAPTURE(BM_OracleTour, small_house, "small_house")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OracleTour, medium_house, "medium_house")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OracleTour, large_office, "large_office")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
