#pragma once
// Headless Chromium for the browser tests (label "browser"): finding the binary, and loading a
// page to dump its DOM or take a screenshot. scripts/test.sh installs Chromium
// (scripts/setup.sh with ROOMSCOUT_BROWSER_TESTS=1); elsewhere the tests skip when no Chromium
// is found, unless ROOMSCOUT_BROWSER_TESTS=1 says it must be there. ROOMSCOUT_CHROMIUM
// overrides the binary.

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace roomscout::test {

inline std::optional<std::filesystem::path> findChromium() {
  if (const char* env = std::getenv("ROOMSCOUT_CHROMIUM"); env && *env) {
    if (std::filesystem::exists(env)) return std::filesystem::path(env);
    return std::nullopt;
  }
  for (const char* candidate : {"/usr/bin/chromium", "/usr/bin/chromium-browser",
                                "/usr/bin/google-chrome", "/usr/bin/google-chrome-stable"}) {
    if (std::filesystem::exists(candidate)) return std::filesystem::path(candidate);
  }
  return std::nullopt;
}

/// True when ROOMSCOUT_BROWSER_TESTS=1: a missing Chromium is then a failure, not a skip.
inline bool browserRequired() {
  const char* env = std::getenv("ROOMSCOUT_BROWSER_TESTS");
  return env && std::string(env) == "1";
}

inline std::string shellQuoted(const std::filesystem::path& p) {
  std::string out = "'";
  for (char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs headless Chromium on `page` with `mode_flags` (e.g. "--dump-dom"), its profile and
/// HOME in `work_dir`, stdout to `out` and stderr to work_dir/chromium.log; its exit status.
inline int runChromium(const std::filesystem::path& chromium, const std::filesystem::path& work_dir,
                       const std::string& mode_flags, const std::filesystem::path& page,
                       const std::filesystem::path& out) {
  const std::filesystem::path profile = work_dir / "profile";
  const std::string command =
      "HOME=" + shellQuoted(work_dir) + " timeout 120 " + shellQuoted(chromium) +
      " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run"
      " --disable-extensions --hide-scrollbars --user-data-dir=" +
      shellQuoted(profile) + " " + mode_flags + " " + shellQuoted("file://" + page.string()) +
      " > " + shellQuoted(out) + " 2> " + shellQuoted(work_dir / "chromium.log");
  return std::system(command.c_str());
}

}  // namespace roomscout::test
