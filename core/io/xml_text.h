#pragma once
// What the XML readers of core/io (qif.cpp, mtconnect.cpp) share: the local name of an element (without
// its namespace prefix), the root element's name of a text before it is parsed (to recognise a format by
// content), line numbers of byte offsets, and parsing with a one-line error naming the file and the line
// (a cut-off file said as such). Private to core/io: it includes pugixml, which only io links.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/error.h"

namespace metrofit::xml {

inline std::string_view localName(std::string_view qualified) {
  const auto colon = qualified.find(':');
  return colon == std::string_view::npos ? qualified : qualified.substr(colon + 1);
}
inline std::string_view localName(const pugi::xml_node& n) {
  return localName(std::string_view(n.name()));
}

/// The local name of the first element of `text` (declarations, comments and processing instructions
/// skipped) within its first 4 KiB, or "" when there is none.
inline std::string rootName(std::string_view text) {
  const std::string_view head = text.substr(0, 4096);
  std::size_t pos = 0;
  while ((pos = head.find('<', pos)) != std::string_view::npos) {
    const std::string_view rest = head.substr(pos + 1);
    if (rest.empty()) return {};
    if (rest.front() == '?' || rest.front() == '!') {
      ++pos;
      continue;
    }
    std::size_t end = 0;
    while (end < rest.size() && !std::isspace(static_cast<unsigned char>(rest[end])) && rest[end] != '>' &&
           rest[end] != '/')
      ++end;
    return std::string(localName(rest.substr(0, end)));
  }
  return {};
}

/// 1-based line numbers of byte offsets of a text.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  long of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    return static_cast<long>(
        std::upper_bound(starts_.begin(), starts_.end(), static_cast<std::size_t>(offset)) - starts_.begin());
  }
  long of(const pugi::xml_node& n) const { return of(n.offset_debug()); }

 private:
  std::vector<std::size_t> starts_;
};

/// Parses `text` into `doc`; ParseError naming `source` and the line when it is not well-formed XML.
inline void parse(pugi::xml_document& doc, std::string_view text, const std::string& source,
                  const LineIndex& lines) {
  const pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_auto);
  if (parsed) return;
  // pugixml reports an unclosed element at the end of the text: the file was cut off.
  const bool cut = parsed.status == pugi::status_end_element_mismatch &&
                   static_cast<std::size_t>(parsed.offset) + 1 >= text.size();
  throw ParseError(
      ErrorContext{source, lines.of(parsed.offset), 0, {}},
      std::string("not well-formed XML: ") +
          (cut ? "the text ends before its elements are closed (a truncated file?)" : parsed.description()));
}

}  // namespace metrofit::xml
