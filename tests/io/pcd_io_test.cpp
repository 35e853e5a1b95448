#include "roomscout/io/pcd_io.hpp"

#include <gtest/gtest.h>

#include <random>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/point_cloud_observer.hpp"

namespace roomscout::io {
namespace {

std::vector<Eigen::Vector3f> randomCloud(int n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), u(rng) * 0.1f);
  return points;
}

std::pair<Eigen::Vector3f, Eigen::Vector3f> boundsOf(const std::vector<Eigen::Vector3f>& points) {
  Eigen::Vector3f lo = points.front(), hi = points.front();
  for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo, hi};
}

TEST(PcdIo, RoundTripInEveryFormat) {
  test::TempDir dir;
  const std::vector<Eigen::Vector3f> points = randomCloud(5000);
  const auto [lo, hi] = boundsOf(points);
  for (PcdFormat format : {PcdFormat::kAscii, PcdFormat::kBinary, PcdFormat::kBinaryCompressed}) {
    const auto path = dir / ("cloud_" + std::string(pcdFormatName(format)) + ".pcd");
    writePcdAtomic(path, points, format, "keyframes: every 1 m or 0.2 rad\nsecond line");
    const std::vector<Eigen::Vector3f> back = readPcd(path);
    ASSERT_EQ(back.size(), points.size());
    const auto [lo2, hi2] = boundsOf(back);
    EXPECT_TRUE(lo2.isApprox(lo, 1e-5f)) << pcdFormatName(format);
    EXPECT_TRUE(hi2.isApprox(hi, 1e-5f)) << pcdFormatName(format);
    for (std::size_t i = 0; i < points.size(); i += 97)
      EXPECT_TRUE(back[i].isApprox(points[i], 1e-6f));
    const std::string bytes = readFile(path);
    EXPECT_NE(bytes.find("# keyframes: every 1 m or 0.2 rad second line\n"), std::string::npos);
    EXPECT_NE(bytes.find("DATA " + std::string(pcdFormatName(format))), std::string::npos);
    EXPECT_NE(bytes.find("VIEWPOINT 0 0 0 1 0 0 0"), std::string::npos);
  }
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 3);
}

TEST(PcdIo, PrecisionRoundsAndSortsWithinHalfAStep) {
  test::TempDir dir;
  const std::vector<Eigen::Vector3f> points = randomCloud(20000);
  writePcdAtomic(dir / "exact.pcd", points, PcdFormat::kBinaryCompressed);
  writePcdAtomic(dir / "rounded.pcd", points, PcdFormat::kBinaryCompressed, {}, 0.005);
  const std::vector<Eigen::Vector3f> back = readPcd(dir / "rounded.pcd");
  ASSERT_EQ(back.size(), points.size());
  const auto [lo, hi] = boundsOf(points);
  const auto [lo2, hi2] = boundsOf(back);
  EXPECT_LE((lo2 - lo).cwiseAbs().maxCoeff(), 0.0025f + 1e-5f);
  EXPECT_LE((hi2 - hi).cwiseAbs().maxCoeff(), 0.0025f + 1e-5f);
  for (std::size_t i = 1; i < back.size(); ++i) ASSERT_LE(back[i - 1].x(), back[i].x());
  EXPECT_LT(std::filesystem::file_size(dir / "rounded.pcd"),
            std::filesystem::file_size(dir / "exact.pcd"));
  EXPECT_THROW(writePcdAtomic(dir / "bad.pcd", points, PcdFormat::kBinary, {}, -1.0),
               InvalidArgument);
}

TEST(PcdIo, EmptyCloudAndErrors) {
  test::TempDir dir;
  writePcdAtomic(dir / "empty.pcd", {}, PcdFormat::kBinaryCompressed);
  EXPECT_TRUE(readPcd(dir / "empty.pcd").empty());
  EXPECT_THROW(readPcd(dir / "missing.pcd"), InputError);
  dir.write("garbage.pcd", "not a point cloud\n");
  EXPECT_THROW(readPcd(dir / "garbage.pcd"), InputError);
  EXPECT_THROW(writePcdAtomic(dir / "no_such_dir" / "x.pcd", randomCloud(3), PcdFormat::kBinary),
               InputError);
  EXPECT_EQ(parsePcdFormat("ascii"), PcdFormat::kAscii);
  EXPECT_EQ(parsePcdFormat("binary_compressed"), PcdFormat::kBinaryCompressed);
  EXPECT_THROW(parsePcdFormat("ply"), OptionError);
}

std::string pcdErrorOf(const std::filesystem::path& path) {
  return test::messageOf<InputError>([&] { readPcd(path); });
}

const std::string kXyzHead =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

// Crashed the pcd fuzz target (heap-buffer-overflow in PCL's readBodyBinary): a
// binary_compressed body whose uncompressed size (36 bytes) is less than the header's points
// need (COUNT 2 for x: 3 points of 16 bytes). PCL read past its buffer.
TEST(PcdFuzzRegression, CompressedBodySmallerThanTheHeaderSays) {
  test::TempDir dir;
  static constexpr char kCrash[] =
      "# .PCD ION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 2 1 1\nWIDTH 3\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA binarWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n"
      "DATA binary_compressed\n"
      "\x26\x00\x00\x00\x24\x00\x00\x00\x1f\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\xc0\xbf\x00"
      "\x00\x00\x00\x00\x00\x00\x40\x00\x00\x80\x3e\x00\x00\x00\x00\x00\x00\x00\x3f\x03\x00\x00"
      "\x00\x40";
  const std::string crash(kCrash, sizeof(kCrash) - 1);  // with its NUL bytes
  const auto path = dir.write("crash.pcd", crash);
  EXPECT_TRUE(test::Contains(pcdErrorOf(path), path.string() + ": cannot read PCD: "));
  // The same sizes under a well-formed header (a fourth float field instead of COUNT 2).
  const auto tidy = dir.write("tidy.pcd",
                              "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z i\nSIZE 4 4 4 4\n"
                              "TYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 1\nPOINTS 3\n"
                              "DATA binary_compressed\n" +
                                  crash.substr(crash.size() - 46));
  EXPECT_TRUE(test::Contains(pcdErrorOf(tidy),
                             tidy.string() +
                                 ": cannot read PCD: the header announces 3 points of 16 bytes "
                                 "but the uncompressed size is 36 bytes"));
}

// Crashed the pcd fuzz target (out of memory): PCL allocates POINTS x point size from the
// header before reading the body, 1.2 GB for these 12-byte files.
TEST(PcdFuzzRegression, HeaderAnnouncingMorePointsThanTheBodyHolds) {
  test::TempDir dir;
  const std::string head = kXyzHead + "WIDTH 100000000\nHEIGHT 1\nPOINTS 100000000\n";
  const auto ascii = dir.write("ascii.pcd", head + "DATA ascii\n1 2 3\n");
  EXPECT_TRUE(test::Contains(pcdErrorOf(ascii),
                             ascii.string() +
                                 ": cannot read PCD: the header announces 100000000 points of "
                                 "12 bytes but the ASCII body has only 6 bytes"));
  const auto binary = dir.write("binary.pcd", head + "DATA binary\n123456789012");
  EXPECT_TRUE(test::Contains(pcdErrorOf(binary), "but the binary body has only 12 bytes"));
  const auto header_only = dir.write("header_only.pcd", head + "DATA ascii");
  EXPECT_TRUE(test::Contains(pcdErrorOf(header_only), "but the ASCII body has only 0 bytes"));
  const auto compressed = dir.write(
      "compressed.pcd", head + "DATA binary_compressed\n" + std::string("\x04\x00\x00\x00", 4) +
                            std::string("\x00\x8c\x86\x47", 4) + "abcd");
  EXPECT_TRUE(test::Contains(pcdErrorOf(compressed), "is impossible for a compressed size of 4"));
}

// Crashed the pcd fuzz target (heap-buffer-overflow in pcl::fromPCLPointCloud2): x y z of one
// byte each (and no TYPE line); PCL copies 4 bytes per coordinate out of 3-byte points.
TEST(PcdFuzzRegression, CoordinatesThatAreNotFloats) {
  test::TempDir dir;
  const std::string body(
      "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x40\x00\x00"
      "\x00\x3f\x00\x00\xc0\xbf\x00\x00\x80\x3e\x00\x00\x00\x40",
      36);
  const auto crash = dir.write("crash.pcd",
                               "# .PCD v0.7 - Point Clo!file format\nVERSION 0.7\nFIELDS y x z\n"
                               "SIZE  1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINTEWPOINT 0 0 0 1 0 0 0\n"
                               "POINTS 3\nDATA binary\n" +
                                   body);
  EXPECT_TRUE(test::Contains(pcdErrorOf(crash),
                             crash.string() + ": cannot read PCD: FIELDS, SIZE, TYPE and COUNT do "
                                              "not have the same number of entries"));
  const auto bytes = dir.write("bytes.pcd",
                               "# .PCD v0.7\nVERSION 0.7\nFIELDS y x z\nSIZE 1 1 1\n"
                               "TYPE F F F\nWIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA binary\n" +
                                   body);
  EXPECT_TRUE(test::Contains(pcdErrorOf(bytes),
                             bytes.string() +
                                 ": cannot read PCD: field y is not a float (SIZE 4, TYPE F, "
                                 "COUNT 1)"));
}

// Crashed the pcd fuzz target (heap-buffer-overflow in pcl::fromPCLPointCloud2): a header PCL
// reads differently from a strict reader (it takes "COLUMNSDT" for COLUMNS and "COUNT\xff..."
// for COUNT), ending with fields of 3 bytes or of no values.
TEST(PcdFuzzRegression, KeywordsReadByTheirPrefixAsPclDoes) {
  test::TempDir dir;
  static constexpr char kCrash[] =
      "\x23\x20\x2e\x50\x00\x52\x2e\x37\x0a\x46\x49\x45\x4c\x44\x53\x20\x78\x20\xf9\x0a\x56\x45\x52"
      "\x53"
      "\x49\x4f\x4e\x20\x30\x2e\x37\x0a\x46\x49\x45\x4c\x44\x53\x20\x78\x20\x79\x20\x7a\x0a\x53\x49"
      "\x5a"
      "\x45\x20\x33\x20\x34\x20\x34\x0a\x54\x59\x50\x45\x20\x46\x20\x46\x20\x46\x0a\x43\x4f\x55\x4e"
      "\x54"
      "\xff\xff\xff\xff\xff\xff\xff\xff\xff\x4c\x44\x53\x20\x78\x20\x79\x20\x7a\x0a\x53\x49\x5a\x45"
      "\x20"
      "\x34\x20\x34\x20\x34\x0a\x54\x59\x50\x45\x20\x46\x20\x46\x20\x46\x0a\x43\x4f\x55\x4e\x54\xff"
      "\xff"
      "\xff\xff\xff\xff\xff\xff\xff\x20\x31\x20\x31\x20\x30\x0a\x48\x45\x49\x47\x48\x54\x20\x31\x0a"
      "\x43"
      "\x4f\x4c\x55\x4d\x4e\x53\x44\x54\x20\x30\x20\x43\x4f\x4c\x55\x4d\x4e\x53\x20\x31\x20\x31\x20"
      "\x30"
      "\x0a\x48\x45\x49\x47\x48\x54\x20\x31\x0a\x43\x4f\x4c\x55\x4d\x4e\x53\x44\x54\x20\x30\x20\x43"
      "\x4f"
      "\x4c\x55\x4d\x4e\x53\x44\x54\x20\x30\x20\x30\x20\x30\x20\x60\x20\x20\x20\x01\x00\x00\x00\x00"
      "\x48"
      "\x45\x49\x47\x48\x54\x20\x31\x0a\x43\x4f\x4c\x55\x4d\x4e\x53\x44\x54\x20\x30\x20\x43\x4f\x4c"
      "\x55"
      "\x4d\x4e\x43\x4f\x4c\x55\x4d\x4e\x53\x44\x54\x20\x30\x20\x43\x4f\x4c\x55\x4d\x4e\x53\x44\x54"
      "\x20"
      "\x30\x20\x30\x20\x30\x20\x60\x20\x20\x20\x01\x00\x00\x00\x00\x00\x00\x0f\x48\x45\x49\x47\x48"
      "\x54"
      "\x20\x31\x4f\x49\x4e\x30\x23\x20\x2e\x50\x43\x44\x20\x76\x30\x30\x26\x37\x0a\x46\x49\x45\x4c"
      "\x44"
      "\x53\x20\x78\x20\x79\x20\x7a\x20\x69\x69\x74\x79\x0a\x53\x49\x5a\x45\x20\x34\x20\x34\x20\x34"
      "\x20"
      "\x34\x0a\x54\x59\x50\x45\x20\x46\x20\x46\x20\x46\x20\x46\x0a\x43\x4f\x55\x4e\x54\x20\x30\x20"
      "\x31"
      "\x20\x31\x20\x31\x0a\x57\x49\x44\x54\x48\x20\x32\x0a\x48\x45\x49\x47\x48\x54\x20\x31\x0a\x56"
      "\x49"
      "\x45\x57\x50\x4f\x49\x4e\x54\x20\x30\x20\x30\x20\x30\x20\x31\x20\x30\x20\x30\x20\x30\x0a\x50"
      "\x4f"
      "\x49\x4e\x54\x53\x20\x32\x0a\x44\x41\x54\x41\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
      "\x00"
      "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x46\x20\x46\x0a"
      "\x43"
      "\x4f\x55\x4e\x54\x20\x31\x20\x31\x20\x31\x20\x31\x0a\x57\x49\x44\x54\x48\x20\x32\x0a\x48\x45"
      "\x49"
      "\x47\x48\x54\x20\x31\x0a\x56\x49\x45\x57\x50\x4f\x49\x4e\x54\x20\x30\x20\x30\x20\x30\x20\x31"
      "\x20"
      "\x30\x20\x30\x20\x30\x0a\x50\x49\x47\x48\x54\x20\x31\x0a\x56\x49\x45\x57\x50\x4f\x49\x4e\x54"
      "\x20"
      "\x30\x20\x30\x20\x30\x20\x31\x20\x30\x20\x30\x20\x30\x0a\x50\x4f\x49\x4e\x54\x53\x20\x32\x0a"
      "\x44"
      "\x41\x54\x41\x20\x61\x73\x63\x69\x69\x0a\x31\x20\x54\x54\x54\x54\x54\x54\x48\x4d\x54\x54\x54"
      "\x54"
      "\x45\x49";
  const auto path = dir.write("crash.pcd", std::string(kCrash, sizeof(kCrash) - 1));
  EXPECT_TRUE(test::Contains(pcdErrorOf(path), path.string() + ": cannot read PCD: "));
}

/// A small furnished world: two rooms joined by a door with a lintel, a table and a cupboard.
sim::World smallWorld() {
  sim::World w;
  w.name = "pcd_frame";
  w.source = "test:pcd_frame";
  const double t = 0.15;
  w.walls = {{{0, 0}, {8, 0}, t, 0, 2.5},      {{8, 0}, {8, 5}, t, 0, 2.5},
             {{8, 5}, {0, 5}, t, 0, 2.5},      {{0, 5}, {0, 0}, t, 0, 2.5},
             {{4, 0}, {4, 2.0}, t, 0, 2.5},    {{4, 3.0}, {4, 5}, t, 0, 2.5},
             {{4, 2.0}, {4, 3.0}, t, 2.0, 2.5}};
  w.doors = {{{4, 2.5}, 1.0}};
  w.furniture = {{"cupboard", {{6.5, 4.0}, {7.8, 4.0}, {7.8, 4.8}, {6.5, 4.8}}, 0.0, 2.0},
                 {"table_top", {{1.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {1.0, 2.0}}, 0.71, 0.75}};
  w.rooms = {{1, "west", {{0, 0}, {4, 0}, {4, 5}, {0, 5}}},
             {2, "east", {{4, 0}, {8, 0}, {8, 5}, {4, 5}}}};
  w.start = {2.0, 3.5, 0.0};
  w.start_given = true;
  return w;
}

TEST(PcdIo, PointCloudAndOccupancyYamlShareTheirFrame) {
  test::TempDir dir;
  const sim::WorldModel model(smallWorld());
  sim::EpisodeConfig config;
  config.episode.max_time_s = 240.0;
  auto strategy = createStrategy("nearest_frontier", 1);
  sim::PointCloudObserver cloud(model, {}, 3);
  const sim::EpisodeResult result = sim::runEpisode(model, config, *strategy, 1, {}, {&cloud});
  ASSERT_GT(cloud.map().size(), 1000u);
  ASSERT_GT(cloud.keyframes(), 3);
  saveOccupancyMap(result.map, dir / "occupancy.yaml");
  writePcdAtomic(dir / "pointcloud.pcd", cloud.map().points(), PcdFormat::kBinaryCompressed, "test",
                 0.005);

  const OccupancyGrid grid = loadOccupancyMap(dir / "occupancy.yaml");
  const std::vector<Eigen::Vector3f> points = readPcd(dir / "pointcloud.pcd");
  ASSERT_EQ(points.size(), cloud.map().size());
  const GridGeometry& g = grid.geometry();
  // Points between 0.3 m and 0.6 m high are walls and the cupboard, which the 2D laser (at
  // 0.18 m) sees too: where the grid knows their cell, it is occupied (or next to one).
  int known = 0, on_occupied = 0;
  for (const Eigen::Vector3f& p : points) {
    if (p.z() < 0.3f || p.z() > 0.6f) continue;
    const Cell c = g.cellOf(Vec2(p.x(), p.y()));
    ASSERT_TRUE(g.contains(c)) << p.transpose();
    bool any_known = false, near_occupied = false;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell n{c.x + dx, c.y + dy};
        if (!g.contains(n)) continue;
        any_known |= grid.state(n) != CellState::kUnknown;
        near_occupied |= grid.state(n) == CellState::kOccupied;
      }
    }
    if (!any_known) continue;
    ++known;
    on_occupied += near_occupied;
  }
  ASSERT_GT(known, 500);
  EXPECT_GE(on_occupied, 0.97 * known) << on_occupied << " of " << known;
  // And every point lies on a ground-truth surface (centroids of 0.05 m voxels, rounded).
  for (const Eigen::Vector3f& p : points) {
    ASSERT_TRUE(cloud.columns().nearSurface(p.cast<double>(), 0.05)) << p.transpose();
  }
}

}  // namespace
}  // namespace roomscout::io
