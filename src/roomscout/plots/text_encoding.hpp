#pragma once
// Text encodings for self-contained report files: XML/HTML escaping and base64 (RFC 4648)
// for data URIs.

#include <string>
#include <string_view>

namespace roomscout::plots {

/// Escapes &, <, >, " and ' so `text` is safe in XML/HTML text and attribute values.
std::string escapeXml(std::string_view text);

/// Standard base64 with padding, no line breaks.
std::string encodeBase64(std::string_view bytes);

}  // namespace roomscout::plots
