#include "roomscout/sim/world_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <regex>
#include <utility>
#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/yaml_support.hpp"

namespace roomscout::sim {

using io::describeYamlNode;
using io::joinNames;
using io::parseYaml;
using io::readFile;
using io::yamlDouble;
namespace {

constexpr double kDoorTouchTolerance_m = 1e-6;
constexpr double kMinPieceLength_m = 1e-9;
constexpr double kDegToRad = M_PI / 180.0;

/// Place of a node inside the document, for error messages: "furniture[3].box.size".
std::string child(const std::string& where, std::string_view key) {
  return where.empty() ? std::string(key) : where + "." + std::string(key);
}
std::string item(const std::string& where, std::size_t index) {
  return where + "[" + std::to_string(index) + "]";
}

/// Strict conversions that throw InputError(source, "<where>: <problem>").
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(source_, where.empty() ? problem : where + ": " + problem);
  }

  double number(const YAML::Node& node, const std::string& where) const {
    if (auto value = yamlDouble(node, /*finite_only=*/false)) {
      if (!std::isfinite(*value))
        fail(where, "expected a finite number, got " + describeYamlNode(node));
      return *value;
    }
    fail(where, "expected a number, got " + describeYamlNode(node));
  }

  double positive(const YAML::Node& node, const std::string& where) const {
    const double value = number(node, where);
    if (!(value > 0.0)) fail(where, "must be > 0, got " + formatDouble(value));
    return value;
  }

  std::string text(const YAML::Node& node, const std::string& where) const {
    if (!node.IsDefined() || !node.IsScalar()) {
      fail(where, "expected a string, got " + describeYamlNode(node));
    }
    return node.Scalar();
  }

  /// A list of exactly `count` numbers, e.g. [x, y].
  std::vector<double> numbers(const YAML::Node& node, const std::string& where, std::size_t count,
                              const std::string& shape) const {
    if (!node.IsSequence() || node.size() != count) {
      fail(where, "expected " + shape + ", got " + describeSequence(node));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(number(node[i], item(where, i)));
    return out;
  }

  Vec2 point(const YAML::Node& node, const std::string& where) const {
    const std::vector<double> xy = numbers(node, where, 2, "a point [x, y]");
    return {xy[0], xy[1]};
  }

  std::vector<Vec2> points(const YAML::Node& node, const std::string& where, std::size_t min_points,
                           const std::string& what) const {
    if (!node.IsSequence()) {
      fail(where, "expected " + what + " (a list of [x, y] points), got " + describeYamlNode(node));
    }
    if (node.size() < min_points) {
      fail(where, what + " needs at least " + std::to_string(min_points) + " points, got " +
                      std::to_string(node.size()));
    }
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < node.size(); ++i) out.push_back(point(node[i], item(where, i)));
    return out;
  }

  /// A node that must be a list; null (an empty key) counts as an empty list.
  YAML::Node list(const YAML::Node& node, const std::string& where) const {
    if (node.IsNull()) return YAML::Node(YAML::NodeType::Sequence);
    if (!node.IsSequence()) fail(where, "expected a list, got " + describeYamlNode(node));
    return node;
  }

 private:
  static std::string describeSequence(const YAML::Node& node) {
    if (!node.IsSequence()) return describeYamlNode(node);
    return "a list of " + std::to_string(node.size());
  }

  std::string source_;
};

/// The keys of one YAML map, checked against the keys its place allows.
class Fields {
 public:
  Fields(const Reader& reader, const YAML::Node& node, std::string where,
         std::vector<std::string_view> known)
      : reader_(reader), where_(std::move(where)) {
    if (!node.IsMap()) {
      reader_.fail(where_, "expected a map with keys " + joinNames(known) + ", got " +
                               describeYamlNode(node));
    }
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) reader_.fail(where_, "map keys must be plain names");
      const std::string key = entry.first.Scalar();
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        reader_.fail(where_, "unknown key '" + key + "' (known: " + joinNames(known) + ")");
      }
      if (!values_.emplace(key, entry.second).second) {
        reader_.fail(where_, "key '" + key + "' appears twice");
      }
    }
  }

  /// The value of an optional key; nullopt when absent or empty.
  std::optional<YAML::Node> optional(std::string_view key) const {
    const auto it = values_.find(std::string(key));
    if (it == values_.end() || it->second.IsNull()) return std::nullopt;
    return it->second;
  }
  bool has(std::string_view key) const { return optional(key).has_value(); }

  YAML::Node required(std::string_view key) const {
    const auto it = values_.find(std::string(key));
    if (it == values_.end())
      reader_.fail(where_, "missing required key '" + std::string(key) + "'");
    return it->second;
  }

  /// Place of a key's value, for errors.
  std::string at(std::string_view key) const { return child(where_, key); }
  const std::string& where() const { return where_; }

 private:
  const Reader& reader_;
  std::string where_;
  std::map<std::string, YAML::Node> values_;
};

/// A wall as written in the file, before doors cut it.
struct WallSpec {
  sim::Wall wall;
  std::string where;
};

/// A door as written in the file.
struct DoorSpec {
  sim::Door door;
  double lintel_m = 2.0;
  std::string where;
};

/// Rectangle of size (size_x, size_y) centred at `center`, turned by `yaw_rad`; corners
/// counter-clockwise.
Polygon rotatedRectangle(const Vec2& center, double size_x, double size_y, double yaw_rad) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  const double hx = 0.5 * size_x;
  const double hy = 0.5 * size_y;
  Polygon out;
  for (const Vec2& local : {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)}) {
    out.emplace_back(center.x() + c * local.x() - s * local.y(),
                     center.y() + s * local.x() + c * local.y());
  }
  return out;
}

struct Box {
  Vec2 center_m;
  double size_x_m = 0.0;
  double size_y_m = 0.0;
  double yaw_rad = 0.0;
};

Box parseBox(const Reader& r, const YAML::Node& node, const std::string& where) {
  const Fields f(r, node, where, {"center", "size", "yaw_deg"});
  Box box;
  box.center_m = r.point(f.required("center"), f.at("center"));
  const std::vector<double> size =
      r.numbers(f.required("size"), f.at("size"), 2, "a size [size_x, size_y]");
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(size[i] > 0.0)) {
      r.fail(item(f.at("size"), i), "must be > 0, got " + formatDouble(size[i]));
    }
  }
  box.size_x_m = size[0];
  box.size_y_m = size[1];
  if (auto yaw = f.optional("yaw_deg")) box.yaw_rad = r.number(*yaw, f.at("yaw_deg")) * kDegToRad;
  return box;
}

void parseWalls(const Reader& r, const YAML::Node& node, double thickness_m, double height_m,
                std::vector<WallSpec>& out) {
  const YAML::Node walls = r.list(node, "walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const std::string where = item("walls", i);
    std::vector<Vec2> points;
    double thickness = thickness_m;
    double height = height_m;
    std::string points_where = where;
    if (walls[i].IsMap()) {
      const Fields f(r, walls[i], where, {"points", "thickness_m", "height_m"});
      points_where = f.at("points");
      points = r.points(f.required("points"), points_where, 2, "a wall polyline");
      if (auto t = f.optional("thickness_m")) thickness = r.positive(*t, f.at("thickness_m"));
      if (auto h = f.optional("height_m")) height = r.positive(*h, f.at("height_m"));
    } else if (walls[i].IsSequence()) {
      points = r.points(walls[i], where, 2, "a wall polyline");
    } else {
      r.fail(where, "expected a polyline [[x, y], ...] or a map with 'points', got " +
                        describeYamlNode(walls[i]));
    }
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      if ((points[k + 1] - points[k]).norm() <= kMinPieceLength_m) {
        r.fail(points_where, "points " + std::to_string(k) + " and " + std::to_string(k + 1) +
                                 " coincide at " + formatPoint(points[k]) +
                                 " (a wall needs a positive length)");
      }
      sim::Wall wall;
      wall.a_m = points[k];
      wall.b_m = points[k + 1];
      wall.thickness_m = thickness;
      wall.z_min_m = 0.0;
      wall.z_max_m = height;
      out.push_back({wall, where});
    }
  }
}

std::vector<DoorSpec> parseDoors(const Reader& r, const YAML::Node& node) {
  std::vector<DoorSpec> out;
  const YAML::Node doors = r.list(node, "doors");
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const std::string where = item("doors", i);
    const Fields f(r, doors[i], where, {"center", "width_m", "lintel_m"});
    DoorSpec spec;
    spec.where = where;
    spec.door.center_m = r.point(f.required("center"), f.at("center"));
    spec.door.width_m = r.positive(f.required("width_m"), f.at("width_m"));
    if (auto lintel = f.optional("lintel_m")) spec.lintel_m = r.positive(*lintel, f.at("lintel_m"));
    out.push_back(spec);
  }
  return out;
}

/// Cuts every door's opening out of the walls it touches. A door touches a wall when the
/// wall's centre segment passes within thickness/2 + tolerance of the door's centre; the
/// opening is the interval of width_m centred on the door's projection onto the wall. Above
/// lintel_m the wall stays (a lintel piece over the gap, when lintel_m < the wall's top).
std::vector<sim::Wall> cutDoors(const Reader& r, const std::vector<WallSpec>& walls,
                                const std::vector<DoorSpec>& doors) {
  std::vector<bool> door_touches(doors.size(), false);
  std::vector<sim::Wall> out;
  for (const WallSpec& spec : walls) {
    const sim::Wall& wall = spec.wall;
    const Vec2 ab = wall.b_m - wall.a_m;
    const double length_m = ab.norm();
    const Vec2 dir = ab / length_m;
    // Openings along the wall as [from, to] distances from a, with their lintel heights.
    std::vector<std::pair<double, double>> gaps;
    std::vector<double> gap_lintels;
    for (std::size_t d = 0; d < doors.size(); ++d) {
      const Vec2& c = doors[d].door.center_m;
      const double along_m = (c - wall.a_m).dot(dir);
      const Vec2 closest = wall.a_m + std::clamp(along_m, 0.0, length_m) * dir;
      if ((c - closest).norm() > 0.5 * wall.thickness_m + kDoorTouchTolerance_m) continue;
      door_touches[d] = true;
      const double from = std::max(0.0, along_m - 0.5 * doors[d].door.width_m);
      const double to = std::min(length_m, along_m + 0.5 * doors[d].door.width_m);
      if (to - from <= kMinPieceLength_m) continue;
      gaps.emplace_back(from, to);
      gap_lintels.push_back(doors[d].lintel_m);
    }
    const auto piece = [&](double from, double to, double z_min, double z_max) {
      sim::Wall p = wall;
      p.a_m = wall.a_m + from * dir;
      p.b_m = wall.a_m + to * dir;
      p.z_min_m = z_min;
      p.z_max_m = z_max;
      return p;
    };
    if (gaps.empty()) {
      out.push_back(wall);
      continue;
    }
    std::vector<std::pair<double, double>> sorted = gaps;
    std::sort(sorted.begin(), sorted.end());
    double solid_from = 0.0;
    for (const auto& [from, to] : sorted) {
      if (from - solid_from > kMinPieceLength_m) {
        out.push_back(piece(solid_from, from, wall.z_min_m, wall.z_max_m));
      }
      solid_from = std::max(solid_from, to);
    }
    if (length_m - solid_from > kMinPieceLength_m) {
      out.push_back(piece(solid_from, length_m, wall.z_min_m, wall.z_max_m));
    }
    for (std::size_t g = 0; g < gaps.size(); ++g) {
      const double lintel_m = std::max(gap_lintels[g], wall.z_min_m);
      if (lintel_m < wall.z_max_m) {
        out.push_back(piece(gaps[g].first, gaps[g].second, lintel_m, wall.z_max_m));
      }
    }
  }
  for (std::size_t d = 0; d < doors.size(); ++d) {
    if (!door_touches[d]) {
      r.fail(doors[d].where, "the door at " + formatPoint(doors[d].door.center_m) +
                                 " touches no wall (its centre must lie within half a wall "
                                 "thickness of a wall's centre line)");
    }
  }
  return out;
}

std::vector<sim::Room> parseRooms(const Reader& r, const YAML::Node& node) {
  std::vector<sim::Room> out;
  const YAML::Node rooms = r.list(node, "rooms");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const Fields f(r, rooms[i], item("rooms", i), {"name", "polygon"});
    sim::Room room;
    room.id = static_cast<int>(i) + 1;
    room.name = r.text(f.required("name"), f.at("name"));
    if (room.name.empty()) r.fail(f.at("name"), "must not be empty");
    room.polygon_m = r.points(f.required("polygon"), f.at("polygon"), 3, "a polygon");
    out.push_back(std::move(room));
  }
  return out;
}

/// A table: a top over the whole box and four square legs, each kTableLegInset_m in from
/// the box's edges at a corner, up to the underside of the top.
void expandTable(const std::string& name, const Box& box, double height_m,
                 std::vector<sim::FurniturePiece>& out) {
  const double top_bottom_m = height_m - kTableTopThickness_m;
  out.push_back({name + "/top",
                 rotatedRectangle(box.center_m, box.size_x_m, box.size_y_m, box.yaw_rad),
                 top_bottom_m, height_m});
  const double offset_x = 0.5 * box.size_x_m - kTableLegInset_m - 0.5 * kTableLegSide_m;
  const double offset_y = 0.5 * box.size_y_m - kTableLegInset_m - 0.5 * kTableLegSide_m;
  const double c = std::cos(box.yaw_rad);
  const double s = std::sin(box.yaw_rad);
  int leg = 1;
  for (const Vec2& local : {Vec2(-offset_x, -offset_y), Vec2(offset_x, -offset_y),
                            Vec2(offset_x, offset_y), Vec2(-offset_x, offset_y)}) {
    const Vec2 center(box.center_m.x() + c * local.x() - s * local.y(),
                      box.center_m.y() + s * local.x() + c * local.y());
    out.push_back({name + "/leg_" + std::to_string(leg++),
                   rotatedRectangle(center, kTableLegSide_m, kTableLegSide_m, box.yaw_rad), 0.0,
                   top_bottom_m});
  }
}

std::vector<sim::FurniturePiece> parseFurniture(const Reader& r, const YAML::Node& node) {
  std::vector<sim::FurniturePiece> out;
  const YAML::Node furniture = r.list(node, "furniture");
  for (std::size_t i = 0; i < furniture.size(); ++i) {
    const std::string where = item("furniture", i);
    const Fields f(r, furniture[i], where, {"name", "kind", "box", "polygon", "z_m", "height_m"});
    const std::string name = r.text(f.required("name"), f.at("name"));
    if (name.empty()) r.fail(f.at("name"), "must not be empty");
    std::string kind = "block";
    if (auto k = f.optional("kind")) kind = r.text(*k, f.at("kind"));
    if (kind != "block" && kind != "table") {
      r.fail(f.at("kind"), "unknown kind '" + kind + "' (known: block, table)");
    }
    if (f.has("box") == f.has("polygon")) {
      r.fail(where, f.has("box") ? "give either 'box' or 'polygon', not both"
                                 : "missing 'box' or 'polygon' (the footprint)");
    }
    if (kind == "table") {
      if (!f.has("box")) r.fail(where, "kind: table needs a 'box', not a 'polygon'");
      if (f.has("z_m")) r.fail(where, "kind: table takes 'height_m', not 'z_m'");
      const Box box = parseBox(r, f.required("box"), f.at("box"));
      const double min_side_m = 2.0 * (kTableLegInset_m + kTableLegSide_m);
      if (box.size_x_m < min_side_m || box.size_y_m < min_side_m) {
        r.fail(f.at("box") + ".size", "a table needs at least " + formatDouble(min_side_m) +
                                          " m on each side for its legs");
      }
      const double height_m = r.positive(f.required("height_m"), f.at("height_m"));
      if (!(height_m > kTableTopThickness_m)) {
        r.fail(f.at("height_m"), "must be above the top's thickness (" +
                                     formatDouble(kTableTopThickness_m) + " m), got " +
                                     formatDouble(height_m));
      }
      expandTable(name, box, height_m, out);
      continue;
    }
    if (f.has("height_m")) r.fail(where, "'height_m' is only for kind: table; use z_m: [min, max]");
    sim::FurniturePiece piece;
    piece.name = name;
    if (f.has("box")) {
      const Box box = parseBox(r, f.required("box"), f.at("box"));
      piece.footprint_m = rotatedRectangle(box.center_m, box.size_x_m, box.size_y_m, box.yaw_rad);
    } else {
      piece.footprint_m = r.points(f.required("polygon"), f.at("polygon"), 3, "a polygon");
    }
    const std::vector<double> z = r.numbers(f.required("z_m"), f.at("z_m"), 2, "[z_min, z_max]");
    if (!(z[0] < z[1])) {
      r.fail(f.at("z_m"),
             "z_min (" + formatDouble(z[0]) + ") must be below z_max (" + formatDouble(z[1]) + ")");
    }
    piece.z_min_m = z[0];
    piece.z_max_m = z[1];
    out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace

sim::World parseWorldYaml(std::string_view yaml_text, const std::string& source) {
  const Reader r(source);
  const YAML::Node root = parseYaml(yaml_text, source);
  if (!root.IsDefined() || root.IsNull()) r.fail("", "the world file is empty");
  const Fields f(r, root, "",
                 {"name", "description", "wall_thickness_m", "wall_height_m", "start", "walls",
                  "doors", "rooms", "furniture"});

  sim::World world;
  world.source = source;
  world.name = r.text(f.required("name"), "name");
  static const std::regex kNamePattern("[a-z0-9_]+");
  if (!std::regex_match(world.name, kNamePattern)) {
    r.fail("name", "'" + world.name + "' must match [a-z0-9_]+");
  }
  if (auto d = f.optional("description")) world.description = r.text(*d, "description");

  double thickness_m = 0.15;
  if (auto t = f.optional("wall_thickness_m")) thickness_m = r.positive(*t, "wall_thickness_m");
  if (auto h = f.optional("wall_height_m")) world.wall_height_m = r.positive(*h, "wall_height_m");

  const std::vector<double> start =
      r.numbers(f.required("start"), "start", 3, "a start pose [x, y, yaw_deg]");
  world.start = Pose2{start[0], start[1], wrapAngle(start[2] * kDegToRad)};
  world.start_given = true;

  std::vector<WallSpec> walls;
  if (auto w = f.optional("walls")) parseWalls(r, *w, thickness_m, world.wall_height_m, walls);
  std::vector<DoorSpec> doors;
  if (auto d = f.optional("doors")) doors = parseDoors(r, *d);
  world.walls = cutDoors(r, walls, doors);
  for (const DoorSpec& d : doors) world.doors.push_back(d.door);
  if (auto rooms = f.optional("rooms")) world.rooms = parseRooms(r, *rooms);
  if (auto furniture = f.optional("furniture")) world.furniture = parseFurniture(r, *furniture);
  return world;
}

sim::World loadWorldFile(const std::filesystem::path& path) {
  return parseWorldYaml(readFile(path), path.string());
}

}  // namespace roomscout::sim
