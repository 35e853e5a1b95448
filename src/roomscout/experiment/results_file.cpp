#include "roomscout/experiment/results_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "roomscout/core/errors.hpp"

namespace roomscout::experiment {

EpisodeKey recordKey(const nlohmann::json& record, const std::string& where) {
  if (!record.is_object()) throw InputError(where, "a results line must be a JSON object");
  for (const char* key : {"world", "method"}) {
    if (!record.contains(key) || !record[key].is_string() ||
        record[key].get<std::string>().empty()) {
      throw InputError(where, std::string("record has no '") + key + "' (a non-empty string)");
    }
  }
  if (!record.contains("seed") || !record["seed"].is_number_unsigned()) {
    throw InputError(where, "record has no 'seed' (a non-negative integer)");
  }
  return {record["world"].get<std::string>(), record["method"].get<std::string>(),
          record["seed"].get<std::uint64_t>()};
}

ResultsScan forEachRecord(
    const std::filesystem::path& path,
    const std::function<void(const nlohmann::json&, const std::string&)>& visit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "file not found");
    throw InputError(path.string(), "cannot read: " + std::string(std::strerror(errno)));
  }
  ResultsScan scan;
  std::string line;
  std::size_t line_no = 0;
  std::uintmax_t offset = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const bool has_newline = !in.eof();
    const std::uintmax_t line_end = offset + line.size() + (has_newline ? 1 : 0);
    const std::string where = path.string() + ":" + std::to_string(line_no);
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      offset = line_end;
      if (has_newline) scan.complete_bytes = line_end;
      continue;
    }
    nlohmann::json record;
    try {
      record = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception& e) {  // bad syntax, or a number out of range
      if (!has_newline) {  // an interrupted write: the bench that resumes drops it
        scan.truncated_tail = true;
        break;
      }
      throw InputError(where, std::string("not a JSON line: ") + e.what());
    }
    const EpisodeKey key = recordKey(record, where);
    (void)key;
    visit(record, where);
    ++scan.records;
    offset = line_end;
    scan.complete_bytes = line_end;
    scan.missing_final_newline = !has_newline;
  }
  if (in.bad())
    throw InputError(path.string(), "cannot read: " + std::string(std::strerror(errno)));
  return scan;
}

ResultsFile::ResultsFile(const std::filesystem::path& path) : path_(path) {
  std::error_code ec;
  ResultsScan scan;
  if (std::filesystem::exists(path, ec)) {
    scan = forEachRecord(path, [&](const nlohmann::json& record, const std::string& where) {
      recorded_.insert(recordKey(record, where));
      const auto mode = record.find("start_mode");
      start_modes_.emplace(mode == record.end() ? "world"
                           : mode->is_string()  ? mode->get<std::string>()
                                                : mode->dump(),
                           where);
    });
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
  if (fd_ < 0)
    throw InputError(path.string(),
                     "cannot open for appending: " + std::string(std::strerror(errno)));
  if (scan.truncated_tail) {
    if (::ftruncate(fd_, static_cast<off_t>(scan.complete_bytes)) != 0) {
      const int error = errno;
      ::close(fd_);
      throw InputError(path.string(), "cannot cut off its truncated last line: " +
                                          std::string(std::strerror(error)));
    }
    dropped_truncated_ = true;
  }
  if (scan.missing_final_newline) {
    if (::write(fd_, "\n", 1) != 1) {
      const int error = errno;
      ::close(fd_);
      throw InputError(path.string(), "cannot write: " + std::string(std::strerror(error)));
    }
  }
}

ResultsFile::~ResultsFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ResultsFile::append(const nlohmann::json& record) {
  const std::string line = record.dump() + "\n";
  const std::lock_guard<std::mutex> lock(mutex_);
  // One write() of the whole line: with O_APPEND it lands at the end in one piece; a short
  // write (disk full) continues, and a reader treats an unfinished last line as truncated.
  const char* data = line.data();
  std::size_t left = line.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path_.string(),
                       "cannot append a record: " + std::string(std::strerror(errno)));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace roomscout::experiment
