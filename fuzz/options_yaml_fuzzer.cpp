// Fuzz target: an options file as `--config FILE` reads it: every group of options (the
// simulation's, the point cloud's and each method's) set from the file, then resolved and
// validated, as experiment::makeEpisodeSetup does for `explore` and `bench`. Accepted
// failures: InputError (syntax, top level) and OptionError (unknown or bad options).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/episode_setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path path = fuzz::scratchDir() / "config.yaml";
  fuzz::writeFile(path, fuzz::asText(data, size));
  experiment::RunSettings settings;
  settings.config_file = path;
  try {
    const experiment::EpisodeSetup setup =
        experiment::makeEpisodeSetup("nearest_frontier", 1, settings);
    (void)setup;
  } catch (const InputError&) {
  } catch (const OptionError&) {
  }
  return 0;
}
