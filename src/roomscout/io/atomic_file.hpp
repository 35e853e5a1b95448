#pragma once
// Whole-file reads and crash-safe whole-file writes: a reader never sees a half-written file.

#include <filesystem>
#include <string>
#include <string_view>

#include <opencv2/core/mat.hpp>

namespace roomscout::io {

/// Replaces `path` with `bytes` atomically: writes a temporary file in the same directory,
/// fsyncs it and renames it over `path`. An existing file keeps its permission bits.
/// On any failure throws InputError(path, "cannot write: <reason>"), leaves no temporary file
/// behind and leaves the old content of `path` (if any) untouched.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

/// Encodes `image` in the format of `path`'s extension (.png, .pgm, .jpg, ...) with
/// cv::imencode and writes it with writeFileAtomic. Throws InputError when the image cannot
/// be encoded (empty image, unknown extension) or written.
void writeImageAtomic(const std::filesystem::path& path, const cv::Mat& image);

/// Creates `directory` (and its parents) if needed and checks that files can be created in
/// it by creating and removing a probe file. Returns true when it created the directory.
/// Throws InputError(directory, problem) when it exists but is not a directory, cannot be
/// created, or is not writable.
bool ensureWritableDirectory(const std::filesystem::path& directory);

/// A command's output directory: created (ensureWritableDirectory) when the object is made,
/// and removed again when the object goes before keep() was called (the command failed) if
/// this object created it and it is still empty, so a failed command leaves nothing behind.
class OutputDirectory {
 public:
  explicit OutputDirectory(std::filesystem::path directory);
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;
  /// The command succeeded: leave the directory.
  void keep() { created_ = false; }

 private:
  std::filesystem::path directory_;
  bool created_ = false;
};

/// Removes, from `directory` (not below it), the temporary files that writeFileAtomic and
/// ensureWritableDirectory leave when their process is killed before they finish (hidden
/// ".NAME.tmp.PID.N.R" and ".roomscout_probe.PID.N.R" files whose process PID no longer
/// runs). Files of running processes and every other file stay. Returns how many it removed;
/// a directory that does not exist has none.
std::size_t removeStaleTempFiles(const std::filesystem::path& directory);

/// Reads a whole file. Throws InputError(path, "file not found") when it does not exist and
/// InputError(path, "cannot read: <reason>") when it cannot be read (e.g. it is a directory).
std::string readFile(const std::filesystem::path& path);

}  // namespace roomscout::io
