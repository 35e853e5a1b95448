// Fuzz target: the command line's value parsers that are functions of the library:
// `--seeds N|A-B`, `--shard I/N` and `--pcd-format NAME`, each given the whole input. The
// only accepted failure is OptionError.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/bench_plan.hpp"
#include "roomscout/io/pcd_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::string_view text = fuzz::asText(data, size);
  try {
    const experiment::SeedRange seeds = experiment::parseSeeds(text);
    if (seeds.first < 1 || seeds.last < seeds.first) __builtin_trap();
  } catch (const OptionError&) {
  }
  try {
    const experiment::Shard shard = experiment::parseShard(text);
    if (shard.index < 1 || shard.index > shard.count) __builtin_trap();
  } catch (const OptionError&) {
  }
  try {
    (void)io::parsePcdFormat(text);
  } catch (const OptionError&) {
  }
  return 0;
}
