#pragma once
// A self-contained HTML report page: sections of paragraphs, tables and figures, with every
// figure inlined (SVG markup or a PNG data URI) so the single file reads offline with no
// external resources.

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "roomscout/plots/figure.hpp"

namespace roomscout::plots {

/// Plain text; HTML special characters are escaped.
struct HtmlParagraph {
  std::string text;
};

/// A table given as a markdown table is: a header row and rows of cell strings. Cells that
/// read as numbers ("12.5", "-3", "98 %", "1.2e3", "1.45×") are right-aligned.
struct HtmlTable {
  std::string caption;  ///< none when empty
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< short rows are padded with empty cells
};

/// A figure: inline SVG when `svg` is set, else the PNG bytes as a data URI.
struct HtmlFigure {
  std::string caption;
  std::string svg;        ///< an <svg> document (an XML declaration, if any, is dropped; its
                          ///< element ids get a prefix of their figure, see numberSvgIds)
  std::string png_bytes;  ///< an encoded PNG file
};

enum class FigureEmbedding { kSvg, kPng };

/// An HtmlFigure of a Figure: renderSvg(), or renderPng().
HtmlFigure htmlFigure(const Figure& figure, std::string caption,
                      FigureEmbedding embedding = FigureEmbedding::kSvg);

using HtmlBlock = std::variant<HtmlParagraph, HtmlTable, HtmlFigure>;

struct HtmlSection {
  std::string title;
  std::vector<HtmlBlock> blocks;  ///< shown in order
};

struct HtmlPage {
  std::string title;
  std::vector<HtmlParagraph> intro;  ///< under the title, before the contents list
  std::vector<HtmlSection> sections;
};

/// The page as one HTML5 document: <table class="report-table"> per table and
/// <figure class="report-figure"> per figure, a contents list linking the sections, and an
/// embedded style sheet. Throws InvalidArgument when a figure has neither SVG nor PNG bytes.
std::string renderHtml(const HtmlPage& page);

/// Writes renderHtml(page) to `path` atomically. Throws InputError when it cannot.
void writeHtml(const HtmlPage& page, const std::filesystem::path& path);

/// The table as GitHub-flavoured markdown (pipes in cells escaped), for text reports.
std::string markdownTable(const HtmlTable& table);

}  // namespace roomscout::plots
