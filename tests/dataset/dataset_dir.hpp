#pragma once
// Where the tests find the shared data set (real maps made elsewhere, not in the repository):
// ROOMSCOUT_DATA_DIR, or else ../shared/data beside the checkout.
// - ROOMSCOUT_DATA_DIR set (as CI sets it): the data set is part of the test environment, and a
//   missing folder is a failure.
// - Unset, and the default folder absent (a clone on its own): the dataset tests skip.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

namespace roomscout::testing {

inline constexpr const char* kDatasetHint =
    "shared data set not found: set ROOMSCOUT_DATA_DIR to its folder to run the dataset tests";

/// The data set's folder, or none when the tests should skip. Records a failure when
/// ROOMSCOUT_DATA_DIR names a folder that does not exist. Use through ROOMSCOUT_DATASET_DIR.
inline std::optional<std::filesystem::path> datasetDir() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("ROOMSCOUT_DATA_DIR"); dir && *dir) {
    EXPECT_TRUE(fs::is_directory(dir)) << "ROOMSCOUT_DATA_DIR is not a folder: " << dir;
    return fs::is_directory(dir) ? std::optional(fs::path(dir)) : std::nullopt;
  }
  const fs::path fallback = fs::path(ROOMSCOUT_SOURCE_DIR).parent_path() / "shared" / "data";
  if (fs::is_directory(fallback)) return fallback;
  return std::nullopt;
}

}  // namespace roomscout::testing

/// Declares `const std::filesystem::path var`, the data set's folder; skips the test when the
/// data set is absent and was not asked for, fails it when ROOMSCOUT_DATA_DIR names no folder.
#define ROOMSCOUT_DATASET_DIR(var)                                      \
  const auto var##_found = ::roomscout::testing::datasetDir();          \
  if (::testing::Test::HasFailure()) return;                            \
  if (!var##_found) GTEST_SKIP() << ::roomscout::testing::kDatasetHint; \
  const std::filesystem::path var = *var##_found
