#pragma once
// DIR/results.jsonl of a bench: one self-describing JSON object per line, one line per
// episode (schema in README "Benchmarks"). Lines are appended whole and flushed, so an
// interrupted bench leaves whole lines, except perhaps a truncated last line, which readers
// ignore and the next writer removes.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "roomscout/experiment/episode_key.hpp"

namespace roomscout::experiment {

/// The key of a record. Throws InputError(where, ...) when `world`, `method` or `seed` is
/// missing or of the wrong type.
EpisodeKey recordKey(const nlohmann::json& record, const std::string& where);

/// How a results file ended.
struct ResultsScan {
  std::size_t records = 0;             ///< complete records read
  bool truncated_tail = false;         ///< the last line had no newline and was not valid JSON
  std::uintmax_t complete_bytes = 0;   ///< bytes up to the end of the last complete record
                                       ///< (its newline included, if any)
  bool missing_final_newline = false;  ///< the last record is whole but has no newline
};

/// Calls `visit(record, where)` for each record of `path` in file order (`where` is
/// "path:line"). Blank lines are skipped. A last line without a newline that does not parse is
/// an interrupted write: skipped and reported in the result. Throws InputError("path:line",
/// problem) for any other line that is not a JSON object with a valid key, and
/// InputError(path, ...) when the file cannot be read. Records are parsed one at a time, so
/// large files never sit in memory whole.
ResultsScan forEachRecord(
    const std::filesystem::path& path,
    const std::function<void(const nlohmann::json& record, const std::string& where)>& visit);

/// A results file open for appending by the threads of one bench.
class ResultsFile {
 public:
  /// Creates `path` if missing, reads the keys recorded so far and cuts off a truncated last
  /// line so that appends start on a line of their own. Throws InputError as forEachRecord,
  /// or when the file cannot be opened for writing.
  explicit ResultsFile(const std::filesystem::path& path);
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Keys recorded before this bench started.
  const std::set<EpisodeKey>& recorded() const { return recorded_; }
  /// The records' start modes ("world" for records without one), each with the "path:line"
  /// of its first record.
  const std::map<std::string, std::string>& startModes() const { return start_modes_; }
  /// True when the file ended in a truncated line that was removed.
  bool droppedTruncatedLine() const { return dropped_truncated_; }

  /// Appends `record` as one line with a single write() and flushes it to the kernel.
  /// Thread-safe. Throws InputError naming the file when the write fails.
  void append(const nlohmann::json& record);

 private:
  std::filesystem::path path_;
  std::set<EpisodeKey> recorded_;
  std::map<std::string, std::string> start_modes_;
  bool dropped_truncated_ = false;
  int fd_ = -1;
  std::mutex mutex_;
};

}  // namespace roomscout::experiment
