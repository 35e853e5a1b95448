#pragma once
// Element ids of SVG documents, renamed so a document is reproducible and can share an HTML
// page with others: Cairo names some ids after process-wide counters ("surface17",
// "image21"), and ids of documents inlined in one page must differ.

#include <string>
#include <string_view>

namespace roomscout::plots {

/// `svg` with every element id renamed to `prefix`, the id's leading letters and its number
/// in document order ("image21" -> "<prefix>image9"), and every reference to an id
/// (href="#id", url(#id)) renamed along. References to ids the document lacks stay.
std::string numberSvgIds(std::string_view svg, std::string_view prefix = {});

}  // namespace roomscout::plots
