#include "roomscout/plots/svg_ids.hpp"

#include <array>
#include <cctype>
#include <unordered_map>

namespace roomscout::plots {
namespace {

/// Where an id or a reference to one starts, and what ends it.
struct Marker {
  std::string_view text;
  char end;
};
constexpr std::array<Marker, 3> kMarkers = {{{" id=\"", '"'}, {"href=\"#", '"'}, {"url(#", ')'}}};

}  // namespace

std::string numberSvgIds(std::string_view svg, std::string_view prefix) {
  std::unordered_map<std::string_view, std::string> renamed;
  const std::string_view id_marker = kMarkers[0].text;
  for (std::size_t at = svg.find(id_marker); at != std::string_view::npos;
       at = svg.find(id_marker, at + 1)) {
    const std::size_t start = at + id_marker.size();
    const std::size_t end = svg.find('"', start);
    if (end == std::string_view::npos) break;
    const std::string_view id = svg.substr(start, end - start);
    if (renamed.count(id)) continue;
    std::size_t letters = 0;
    while (letters < id.size() && std::isalpha(static_cast<unsigned char>(id[letters]))) ++letters;
    renamed.emplace(id, std::string(prefix) + std::string(id.substr(0, letters)) +
                            std::to_string(renamed.size() + 1));
  }

  std::string out;
  out.reserve(svg.size() + svg.size() / 8);
  std::array<std::size_t, kMarkers.size()> next{};
  for (std::size_t k = 0; k < kMarkers.size(); ++k) next[k] = svg.find(kMarkers[k].text);
  std::size_t copied = 0;
  while (true) {
    std::size_t k = 0;
    for (std::size_t j = 1; j < kMarkers.size(); ++j) {
      if (next[j] < next[k]) k = j;
    }
    if (next[k] == std::string_view::npos) break;
    if (next[k] < copied) {  // inside the id just copied
      next[k] = svg.find(kMarkers[k].text, copied);
      continue;
    }
    const std::size_t start = next[k] + kMarkers[k].text.size();
    const std::size_t end = svg.find(kMarkers[k].end, start);
    if (end == std::string_view::npos) break;
    out.append(svg.substr(copied, start - copied));
    const std::string_view id = svg.substr(start, end - start);
    const auto it = renamed.find(id);
    out.append(it == renamed.end() ? id : std::string_view(it->second));
    copied = end;
    next[k] = svg.find(kMarkers[k].text, end);
  }
  out.append(svg.substr(copied));
  return out;
}

}  // namespace roomscout::plots
