#include "roomscout/plots/html_report.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/svg_ids.hpp"
#include "roomscout/plots/text_encoding.hpp"

namespace roomscout::plots {
namespace {

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; color: #222; margin: 2em auto;
       max-width: 1280px; padding: 0 1em; line-height: 1.45; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.3em; margin-top: 2em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; }
nav ol { margin: 0.5em 0 1.5em 0; }
table.report-table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
table.report-table caption { caption-side: top; text-align: left; font-weight: bold;
                             padding-bottom: 0.3em; }
table.report-table th, table.report-table td { border: 1px solid #ccc; padding: 0.25em 0.6em; }
table.report-table th { background: #f3f3f3; text-align: left; }
table.report-table td.num { text-align: right; font-variant-numeric: tabular-nums; }
table.report-table tbody tr:nth-child(even) { background: #fafafa; }
figure.report-figure { margin: 1.2em 0; }
figure.report-figure svg, figure.report-figure img { max-width: 100%; height: auto;
                                                     display: block; }
figure.report-figure figcaption { font-size: 0.9em; color: #555; margin-top: 0.3em; }
)css";

/// Looks like a number, possibly with a unit-like suffix such as "%" or " m".
bool numeric(const std::string& cell) {
  std::size_t i = 0;
  while (i < cell.size() && std::isspace(static_cast<unsigned char>(cell[i]))) ++i;
  if (i < cell.size() && (cell[i] == '-' || cell[i] == '+')) ++i;
  bool digits = false;
  while (i < cell.size() && (std::isdigit(static_cast<unsigned char>(cell[i])) || cell[i] == '.')) {
    digits |= std::isdigit(static_cast<unsigned char>(cell[i])) != 0;
    ++i;
  }
  if (!digits) return false;
  if (i < cell.size() && (cell[i] == 'e' || cell[i] == 'E')) {
    ++i;
    if (i < cell.size() && (cell[i] == '-' || cell[i] == '+')) ++i;
    while (i < cell.size() && std::isdigit(static_cast<unsigned char>(cell[i]))) ++i;
  }
  // Allow "%", "x", "×" (a ratio) or a short suffix after a space: a unit (" m") or a
  // spread (" ± 1.2").
  const std::string rest = cell.substr(i);
  return rest.empty() || rest == "%" || rest == "x" || rest == "\u00d7" ||
         (rest[0] == ' ' && rest.size() <= 8);
}

std::string stripXmlDeclaration(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? svg : svg.substr(start);
}

void appendTable(std::string& out, const HtmlTable& table) {
  const std::size_t columns = std::max(
      table.header.size(),
      table.rows.empty()
          ? std::size_t{0}
          : std::max_element(table.rows.begin(), table.rows.end(),
                             [](const auto& a, const auto& b) { return a.size() < b.size(); })
                ->size());
  out += "<table class=\"report-table\">\n";
  if (!table.caption.empty()) out += "<caption>" + escapeXml(table.caption) + "</caption>\n";
  if (!table.header.empty()) {
    out += "<thead><tr>";
    for (std::size_t c = 0; c < columns; ++c) {
      out +=
          "<th>" + (c < table.header.size() ? escapeXml(table.header[c]) : std::string()) + "</th>";
    }
    out += "</tr></thead>\n";
  }
  out += "<tbody>\n";
  for (const auto& row : table.rows) {
    out += "<tr>";
    for (std::size_t c = 0; c < columns; ++c) {
      const std::string cell = c < row.size() ? row[c] : std::string();
      out += numeric(cell) ? "<td class=\"num\">" : "<td>";
      out += escapeXml(cell) + "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody>\n</table>\n";
}

/// Appends the page's `number`-th figure (from 1); the ids of its SVG get the prefix
/// "figN-", so they differ from those of the page's other figures.
void appendFigure(std::string& out, const HtmlFigure& figure, int number) {
  out += "<figure class=\"report-figure\">\n";
  if (!figure.svg.empty()) {
    out += numberSvgIds(stripXmlDeclaration(figure.svg), "fig" + std::to_string(number) + "-");
    if (out.back() != '\n') out += '\n';
  } else if (!figure.png_bytes.empty()) {
    out += "<img alt=\"" + escapeXml(figure.caption) + "\" src=\"data:image/png;base64," +
           encodeBase64(figure.png_bytes) + "\">\n";
  } else {
    throw InvalidArgument("report figure '" + figure.caption + "' has neither SVG nor PNG data");
  }
  if (!figure.caption.empty())
    out += "<figcaption>" + escapeXml(figure.caption) + "</figcaption>\n";
  out += "</figure>\n";
}

struct BlockWriter {
  std::string& out;
  int& figures;  ///< figures written so far
  void operator()(const HtmlParagraph& p) const { out += "<p>" + escapeXml(p.text) + "</p>\n"; }
  void operator()(const HtmlTable& t) const { appendTable(out, t); }
  void operator()(const HtmlFigure& f) const { appendFigure(out, f, ++figures); }
};

std::string markdownCell(const std::string& cell) {
  std::string out;
  for (char c : cell) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

}  // namespace

HtmlFigure htmlFigure(const Figure& figure, std::string caption, FigureEmbedding embedding) {
  HtmlFigure out;
  out.caption = std::move(caption);
  if (embedding == FigureEmbedding::kSvg) {
    out.svg = renderSvg(figure);
  } else {
    out.png_bytes = renderPng(figure);
  }
  return out;
}

std::string renderHtml(const HtmlPage& page) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + escapeXml(page.title) + "</title>\n<style>" + kStyle + "</style>\n";
  out += "</head>\n<body>\n<h1>" + escapeXml(page.title) + "</h1>\n";
  int figures = 0;
  for (const HtmlParagraph& p : page.intro) BlockWriter{out, figures}(p);
  if (page.sections.size() > 1) {
    out += "<nav><ol>\n";
    for (std::size_t s = 0; s < page.sections.size(); ++s) {
      out += "<li><a href=\"#section-" + std::to_string(s + 1) + "\">" +
             escapeXml(page.sections[s].title) + "</a></li>\n";
    }
    out += "</ol></nav>\n";
  }
  for (std::size_t s = 0; s < page.sections.size(); ++s) {
    const HtmlSection& section = page.sections[s];
    out += "<section id=\"section-" + std::to_string(s + 1) + "\">\n<h2>" +
           escapeXml(section.title) + "</h2>\n";
    for (const HtmlBlock& block : section.blocks) std::visit(BlockWriter{out, figures}, block);
    out += "</section>\n";
  }
  out += "</body>\n</html>\n";
  return out;
}

void writeHtml(const HtmlPage& page, const std::filesystem::path& path) {
  io::writeFileAtomic(path, renderHtml(page));
}

std::string markdownTable(const HtmlTable& table) {
  std::size_t columns = table.header.size();
  for (const auto& row : table.rows) columns = std::max(columns, row.size());
  if (columns == 0) return {};
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string s = "|";
    for (std::size_t c = 0; c < columns; ++c) {
      s += ' ';
      if (c < cells.size()) s += markdownCell(cells[c]);
      s += " |";
    }
    return s + "\n";
  };
  std::string out;
  if (!table.caption.empty()) out += "**" + markdownCell(table.caption) + "**\n\n";
  out += line(table.header);
  std::string rule = "|";
  for (std::size_t c = 0; c < columns; ++c) {
    bool all_numeric = !table.rows.empty();
    for (const auto& row : table.rows) {
      if (c < row.size() && !row[c].empty() && !numeric(row[c])) all_numeric = false;
    }
    rule += all_numeric ? " ---: |" : " --- |";
  }
  out += rule + "\n";
  for (const auto& row : table.rows) out += line(row);
  return out;
}

}  // namespace roomscout::plots
