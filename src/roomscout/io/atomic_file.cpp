#include "roomscout/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <limits>
#include <random>
#include <system_error>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::io {
namespace {

std::string errnoText(int error) { return std::strerror(error); }

/// The directory holding `path` ("." for a bare file name).
std::filesystem::path directoryOf(const std::filesystem::path& path) {
  const std::filesystem::path parent = path.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

/// A file name that no other writer in this or another process will pick at the same time.
std::string uniqueSuffix() {
  static std::atomic<unsigned> counter{0};
  thread_local std::mt19937 rng{std::random_device{}()};
  return std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1)) + "." +
         std::to_string(rng() % 1000000u);
}

/// Creates a new, empty file next to `path` and returns its descriptor and name; the kernel
/// applies the umask to mode 0666 as for any new file. Returns -1 and sets errno on failure.
int createTempFile(const std::filesystem::path& path, std::filesystem::path& temp_path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name(1, '.');  // hidden; built by appending (GCC 12 misreports "." + str)
    name += path.filename().string();
    name += ".tmp.";
    name += uniqueSuffix();
    temp_path = directoryOf(path) / name;
    const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

/// The PID in a temporary file name made by createTempFile or the directory probe, or -1 when
/// `name` is not one: ".NAME.tmp.PID.N.R" or ".roomscout_probe.PID.N.R".
long tempFileOwner(const std::string& name) {
  if (name.empty() || name[0] != '.') return -1;
  std::size_t suffix = 0;
  if (name.rfind(".roomscout_probe.", 0) == 0) {
    suffix = std::string(".roomscout_probe.").size();
  } else {
    const std::size_t tmp = name.rfind(".tmp.");
    if (tmp == std::string::npos || tmp == 0) return -1;
    suffix = tmp + 5;
  }
  // Exactly three dot-separated runs of digits: PID, counter, random number.
  long pid = -1;
  int parts = 0;
  std::size_t begin = suffix;
  while (begin <= name.size()) {
    const std::size_t end = std::min(name.find('.', begin), name.size());
    if (end == begin || end - begin > 18) return -1;
    for (std::size_t i = begin; i < end; ++i) {
      if (name[i] < '0' || name[i] > '9') return -1;
    }
    if (parts == 0) pid = std::stol(name.substr(begin, end - begin));
    ++parts;
    begin = end + 1;
  }
  return parts == 3 ? pid : -1;
}

bool processRuns(long pid) {
  if (pid <= 0 || pid > std::numeric_limits<pid_t>::max()) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

bool writeAll(int fd, std::string_view bytes) {
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes) {
  const auto fail = [&](int error) -> void {
    throw InputError(path.string(), "cannot write: " + errnoText(error));
  };
  if (path.filename().empty()) fail(EISDIR);

  std::filesystem::path temp_path;
  const int fd = createTempFile(path, temp_path);
  if (fd < 0) fail(errno);

  // Removes the temporary file on every failure path below.
  const auto abandon = [&](int error) {
    ::close(fd);
    ::unlink(temp_path.c_str());
    fail(error);
  };
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
    if (::fchmod(fd, existing.st_mode & 07777) != 0) abandon(errno);
  }
  if (!writeAll(fd, bytes)) abandon(errno);
  if (::fsync(fd) != 0) abandon(errno);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temp_path.c_str());
    fail(error);
  }
  if (::rename(temp_path.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp_path.c_str());
    fail(error);
  }
  // Make the rename itself durable; a failure here does not undo the write, so ignore it.
  const int dir_fd = ::open(directoryOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

void writeImageAtomic(const std::filesystem::path& path, const cv::Mat& image) {
  const std::string extension = path.extension().string();
  if (image.empty()) throw InputError(path.string(), "cannot write: the image is empty");
  if (extension.empty()) {
    throw InputError(path.string(), "cannot write: no file extension to choose an image format");
  }
  std::vector<uchar> encoded;
  bool ok = false;
  std::string reason = "unsupported image format or pixel type";
  try {
    ok = cv::imencode(extension, image, encoded);
  } catch (const cv::Exception& e) {
    reason = e.what();
  }
  if (!ok) throw InputError(path.string(), "cannot encode image: " + reason);
  writeFileAtomic(path,
                  std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

bool ensureWritableDirectory(const std::filesystem::path& directory) {
  std::error_code ec;
  const auto status = std::filesystem::status(directory, ec);
  bool created = false;
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status)) {
      throw InputError(directory.string(), "not a directory");
    }
  } else {
    created = std::filesystem::create_directories(directory, ec);
    if (!created && ec)
      throw InputError(directory.string(), "cannot create directory: " + ec.message());
  }
  const std::filesystem::path probe = directory / (".roomscout_probe." + uniqueSuffix());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw InputError(directory.string(), "directory is not writable: " + errnoText(errno));
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return created;
}

OutputDirectory::OutputDirectory(std::filesystem::path directory)
    : directory_(std::move(directory)) {
  created_ = ensureWritableDirectory(directory_);
}

OutputDirectory::~OutputDirectory() {
  if (!created_) return;
  std::error_code ec;
  if (std::filesystem::is_empty(directory_, ec) && !ec) std::filesystem::remove(directory_, ec);
}

std::size_t removeStaleTempFiles(const std::filesystem::path& directory) {
  std::size_t removed = 0;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(directory, ec);
       !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    std::error_code type_ec;
    if (!it->is_regular_file(type_ec)) continue;
    const long pid = tempFileOwner(it->path().filename().string());
    if (pid < 0 || processRuns(pid)) continue;
    std::error_code remove_ec;
    if (std::filesystem::remove(it->path(), remove_ec)) ++removed;
  }
  return removed;
}

std::string readFile(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) throw InputError(path.string(), "file not found");
    throw InputError(path.string(), "cannot read: " + errnoText(error));
  }
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      throw InputError(path.string(), "cannot read: " + errnoText(error));
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return bytes;
}

}  // namespace roomscout::io
