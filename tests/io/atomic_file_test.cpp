#include "roomscout/io/atomic_file.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::io {
namespace {

using test::Contains;
using test::Names;
using test::TempDir;

template <typename Fn>
std::string inputErrorOf(Fn&& fn) {
  return test::messageOf<InputError>(fn);
}

TEST(WriteFileAtomic, CreatesAndReplacesFileLeavingNoTemporaryFile) {
  const TempDir dir;
  const auto file = dir / "out.txt";
  writeFileAtomic(file, "first");
  EXPECT_EQ(readFile(file), "first");
  writeFileAtomic(file, std::string("sec\0ond", 7));
  EXPECT_EQ(readFile(file), std::string("sec\0ond", 7));
  EXPECT_EQ(dir.entries(), (Names{"out.txt"}));
}

TEST(WriteFileAtomic, WritesEmptyFile) {
  const TempDir dir;
  writeFileAtomic(dir / "empty", "");
  EXPECT_EQ(std::filesystem::file_size(dir / "empty"), 0u);
}

TEST(WriteFileAtomic, KeepsPermissionsOfReplacedFile) {
  const TempDir dir;
  const auto file = dir.write("secret", "old");
  std::filesystem::permissions(
      file, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  writeFileAtomic(file, "new");
  EXPECT_EQ(readFile(file), "new");
  EXPECT_EQ(std::filesystem::status(file).permissions(),
            std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
}

TEST(WriteFileAtomic, ParentIsARegularFileThrowsAndCreatesNothing) {
  const TempDir dir;
  const auto blocker = dir.write("blocker", "i am a file");
  const auto target = blocker / "out.txt";
  const std::string message = inputErrorOf([&] { writeFileAtomic(target, "data"); });
  EXPECT_TRUE(Contains(message, target.string() + ": cannot write: "));
  EXPECT_TRUE(Contains(message, "Not a directory"));
  EXPECT_EQ(dir.entries(), (Names{"blocker"}));
  EXPECT_EQ(readFile(blocker), "i am a file");
}

TEST(WriteFileAtomic, TargetIsADirectoryThrowsAndLeavesItIntact) {
  const TempDir dir;
  std::filesystem::create_directory(dir / "sub");
  dir.write("sub/keep", "kept");
  const std::string message = inputErrorOf([&] { writeFileAtomic(dir / "sub", "data"); });
  EXPECT_TRUE(Contains(message, "cannot write"));
  EXPECT_EQ(dir.entries(), (Names{"sub"}));
  EXPECT_EQ(readFile(dir / "sub" / "keep"), "kept");
}

TEST(WriteFileAtomic, FailedWriteLeavesOldFileIntactAndNoTemporaryFile) {
  const TempDir dir;
  const auto file = dir.write("data.bin", "old content");
  // Make write() fail with EFBIG: a file size limit applies to root too.
  struct rlimit old_limit {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  auto* old_handler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = old_limit;
  small.rlim_cur = 16;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeFileAtomic(file, std::string(4096, 'x'));
  } catch (const InputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);

  EXPECT_TRUE(Contains(message, file.string() + ": cannot write: "));
  EXPECT_EQ(readFile(file), "old content");
  EXPECT_EQ(dir.entries(), (Names{"data.bin"}));
}

TEST(WriteFileAtomic, UnwritableDirectoryLeavesOldFileIntact) {
  // /proc refuses new files even for root; /proc/version is an existing "old file".
  const std::filesystem::path file = "/proc/version";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no /proc";
  const std::string before = readFile(file);
  const std::string message = inputErrorOf([&] { writeFileAtomic(file, "overwritten"); });
  EXPECT_TRUE(Contains(message, "/proc/version: cannot write: "));
  EXPECT_EQ(readFile(file), before);
}

TEST(WriteImageAtomic, EncodesByExtension) {
  const TempDir dir;
  cv::Mat image(3, 4, CV_8UC1);
  for (int i = 0; i < 12; ++i) image.data[i] = static_cast<uchar>(i * 20);
  writeImageAtomic(dir / "img.png", image);
  writeImageAtomic(dir / "img.pgm", image);
  for (const char* name : {"img.png", "img.pgm"}) {
    const cv::Mat back = cv::imread((dir / name).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(back.size(), image.size()) << name;
    EXPECT_EQ(cv::countNonZero(back != image), 0) << name;
  }
  EXPECT_EQ(readFile(dir / "img.pgm").substr(0, 2), "P5");
  EXPECT_EQ(dir.entries(), (Names{"img.pgm", "img.png"}));
}

TEST(WriteImageAtomic, RejectsUnknownExtensionAndEmptyImage) {
  const TempDir dir;
  const cv::Mat image(2, 2, CV_8UC1, cv::Scalar(7));
  EXPECT_TRUE(Contains(inputErrorOf([&] { writeImageAtomic(dir / "img.nosuchformat", image); }),
                       "img.nosuchformat: cannot encode image"));
  EXPECT_TRUE(
      Contains(inputErrorOf([&] { writeImageAtomic(dir / "noext", image); }), "no file extension"));
  EXPECT_TRUE(Contains(inputErrorOf([&] { writeImageAtomic(dir / "empty.png", cv::Mat()); }),
                       "empty.png: cannot write: the image is empty"));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(EnsureWritableDirectory, CreatesNestedDirectoriesAndLeavesNoProbe) {
  const TempDir dir;
  const auto nested = dir / "a" / "b" / "c";
  ensureWritableDirectory(nested);
  EXPECT_TRUE(std::filesystem::is_directory(nested));
  EXPECT_TRUE(std::filesystem::is_empty(nested));
  ensureWritableDirectory(nested);  // existing directory: fine
  EXPECT_TRUE(std::filesystem::is_empty(nested));
}

TEST(EnsureWritableDirectory, RejectsRegularFileAndPathBelowOne) {
  const TempDir dir;
  const auto file = dir.write("file", "x");
  EXPECT_TRUE(Contains(inputErrorOf([&] { ensureWritableDirectory(file); }),
                       file.string() + ": not a directory"));
  EXPECT_TRUE(Contains(inputErrorOf([&] { ensureWritableDirectory(file / "sub"); }),
                       (file / "sub").string() + ": cannot create directory"));
}

TEST(EnsureWritableDirectory, RejectsUnwritableDirectory) {
  if (!std::filesystem::is_directory("/proc")) GTEST_SKIP() << "no /proc";
  EXPECT_TRUE(Contains(inputErrorOf([] { ensureWritableDirectory("/proc"); }),
                       "/proc: directory is not writable"));
}

/// The PID of a process that has ended: a child that exits at once, reaped.
long deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

TEST(RemoveStaleTempFiles, RemovesOnlyTemporaryFilesOfEndedProcesses) {
  const TempDir dir;
  const std::string dead = std::to_string(deadPid());
  const std::string alive = std::to_string(::getpid());
  dir.write(".metrics.json.tmp." + dead + ".3.123456", "half");  // a killed writer's
  dir.write(".roomscout_probe." + dead + ".0.42", "");           // a killed probe's
  dir.write(".table1.md.tmp." + alive + ".1.7", "in progress");  // a running writer's
  dir.write("metrics.json.tmp." + dead + ".3.1", "x");           // not hidden: not ours
  dir.write(".notes.tmp." + dead + ".x.1", "x");                 // not three numbers
  dir.write(".notes.tmp." + dead + ".1", "x");
  dir.write("metrics.json", "{}");
  std::filesystem::create_directories(dir / ("sub") / "deeper");
  dir.write("sub/.a.tmp." + dead + ".1.2", "below: left alone");
  EXPECT_EQ(removeStaleTempFiles(dir.path()), 2u);
  EXPECT_EQ(dir.entries(), (Names{".notes.tmp." + dead + ".1", ".notes.tmp." + dead + ".x.1",
                                  ".table1.md.tmp." + alive + ".1.7", "metrics.json",
                                  "metrics.json.tmp." + dead + ".3.1", "sub"}));
  EXPECT_TRUE(std::filesystem::exists(dir / ("sub/.a.tmp." + dead + ".1.2")));
  EXPECT_EQ(removeStaleTempFiles(dir / "missing"), 0u);
}

TEST(ReadFile, ReportsMissingFileAndDirectory) {
  const TempDir dir;
  EXPECT_TRUE(Contains(inputErrorOf([&] { readFile(dir / "missing.yaml"); }),
                       (dir / "missing.yaml").string() + ": file not found"));
  EXPECT_TRUE(
      Contains(inputErrorOf([&] { readFile(dir.path()); }), dir.path().string() + ": cannot read"));
}

TEST(ReadFile, ReadsLargeBinaryFile) {
  const TempDir dir;
  std::string bytes(200000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 31);
  dir.write("big.bin", bytes);
  EXPECT_EQ(readFile(dir / "big.bin"), bytes);
}

}  // namespace
}  // namespace roomscout::io
