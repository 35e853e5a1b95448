#include "roomscout/experiment/bench_plan.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <set>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/builtin_worlds.hpp"

namespace roomscout::experiment {
namespace fs = std::filesystem;

std::vector<BenchWorld> expandWorlds(const std::vector<std::string>& items) {
  std::vector<BenchWorld> worlds;
  for (const std::string& item : items) {
    if (sim::isBuiltinWorld(item)) {
      worlds.push_back({item, item, "builtin"});
      continue;
    }
    const fs::path path(item);
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<fs::path> files;
      for (const fs::directory_entry& e : fs::directory_iterator(path, ec)) {
        if (e.path().extension() == ".yaml" && e.is_regular_file()) files.push_back(e.path());
      }
      if (ec) throw InputError(item, "cannot list folder: " + ec.message());
      if (files.empty()) throw InputError(item, "folder holds no .yaml world file");
      std::sort(files.begin(), files.end(),
                [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
      const fs::path folder = fs::absolute(path).lexically_normal();
      std::string group =
          (folder.filename().empty() ? folder.parent_path() : folder).filename().string();
      for (const fs::path& f : files) worlds.push_back({f.stem().string(), f.string(), group});
    } else if (fs::is_regular_file(path, ec)) {
      const fs::path parent = fs::absolute(path).lexically_normal().parent_path();
      worlds.push_back({path.stem().string(), item, parent.filename().string()});
    } else {
      std::string known;
      for (const std::string& n : sim::builtinWorldNames())
        known += (known.empty() ? "" : ", ") + n;
      throw InputError(
          item, "no such file or folder, and not a built-in world (built-in: " + known + ")");
    }
  }
  std::map<std::string, std::string> seen;  // name -> spec
  std::vector<BenchWorld> unique;
  for (BenchWorld& w : worlds) {
    const auto [it, inserted] = seen.emplace(w.name, w.spec);
    if (inserted) {
      unique.push_back(std::move(w));
    } else if (it->second != w.spec) {
      throw OptionError("--worlds: two worlds are named '" + w.name + "': " + it->second + " and " +
                        w.spec);
    }
  }
  return unique;
}

Shard parseShard(std::string_view text) {
  const auto fail = [&]() -> Shard {
    throw OptionError("--shard: expected I/N with 1 <= I <= N (e.g. 2/8), got '" +
                      std::string(text) + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return fail();
  Shard s;
  const std::string_view a = text.substr(0, slash), b = text.substr(slash + 1);
  const auto ra = std::from_chars(a.data(), a.data() + a.size(), s.index);
  const auto rb = std::from_chars(b.data(), b.data() + b.size(), s.count);
  if (a.empty() || b.empty() || ra.ec != std::errc() || ra.ptr != a.data() + a.size() ||
      rb.ec != std::errc() || rb.ptr != b.data() + b.size() || s.count < 1 || s.index < 1 ||
      s.index > s.count) {
    return fail();
  }
  return s;
}

SeedRange parseSeeds(std::string_view text) {
  const auto number = [](std::string_view t, int& value) {
    const auto r = std::from_chars(t.data(), t.data() + t.size(), value);
    return !t.empty() && r.ec == std::errc() && r.ptr == t.data() + t.size();
  };
  SeedRange range;
  const std::size_t dash = text.find('-');
  const bool ok = dash == std::string_view::npos ? number(text, range.last)
                                                 : number(text.substr(0, dash), range.first) &&
                                                       number(text.substr(dash + 1), range.last);
  if (!ok || range.first < 1 || range.last < range.first) {
    throw OptionError(
        "--seeds: expected N (seeds 1..N) or A-B (seeds A..B) with 1 <= A <= B, got '" +
        std::string(text) + "'");
  }
  return range;
}

std::vector<EpisodeKey> planEpisodes(const std::vector<std::string>& worlds,
                                     const std::vector<std::string>& methods,
                                     const SeedRange& seeds, const Shard& shard) {
  if (worlds.empty()) throw OptionError("--worlds: no world given");
  if (methods.empty()) throw OptionError("--methods: no method given");
  if (seeds.first < 1 || seeds.last < seeds.first) {
    throw OptionError("--seeds: empty range " + std::to_string(seeds.first) + "-" +
                      std::to_string(seeds.last));
  }
  const std::set<std::string> world_set(worlds.begin(), worlds.end());
  const std::set<std::string> method_set(methods.begin(), methods.end());
  std::vector<EpisodeKey> all;
  for (const std::string& w : world_set) {
    for (const std::string& m : method_set) {
      for (int s = seeds.first; s <= seeds.last; ++s) {
        all.push_back({w, m, static_cast<std::uint64_t>(s)});
      }
    }
  }
  std::vector<EpisodeKey> mine;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (shard.holds(i)) mine.push_back(std::move(all[i]));
  }
  return mine;
}

std::vector<std::string> splitList(std::string_view text) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find(',', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(begin, end - begin);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    if (!item.empty()) items.emplace_back(item);
    begin = end + 1;
  }
  return items;
}

}  // namespace roomscout::experiment
