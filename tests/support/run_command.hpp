#pragma once
// Test helper: runs the roomscout binary (ROOMSCOUT_BINARY, defined for every test target) and
// captures its exit code and output.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace roomscout::test {

struct CommandResult {
  int exit_code = -1;  ///< -1 when the command did not exit normally (a signal)
  std::string output;  ///< stdout and stderr, interleaved
};

/// Runs `command` through the shell with stdout and stderr sent to `log_dir`/log.txt.
inline CommandResult runCommand(const std::string& command, const std::filesystem::path& log_dir) {
  const std::filesystem::path log = log_dir / "log.txt";
  const int status = std::system((command + " > " + log.string() + " 2>&1").c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  r.output = s.str();
  return r;
}

/// Runs `roomscout ARGS`, its log in `log_dir`.
inline CommandResult runRoomscout(const std::string& args, const std::filesystem::path& log_dir) {
  return runCommand(std::string(ROOMSCOUT_BINARY) + " " + args, log_dir);
}

/// The result as (exit code, output), for tests that std::tie it.
inline std::pair<int, std::string> asPair(CommandResult r) {
  return {r.exit_code, std::move(r.output)};
}

}  // namespace roomscout::test
