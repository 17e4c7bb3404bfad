#pragma once
// 8-bit text as Windows measuring software writes it (Q-DAS DFQ, Zeiss Calypso tables): Windows-1252,
// which agrees with ISO-8859-1 on its letters (ä, ö, ü, ß, µ, °) and adds €, ‰ and typographic quotes in
// 0x80-0x9F. Files that are valid UTF-8 are UTF-8; everything else is read as Windows-1252.
#include <string>
#include <string_view>

namespace metrofit {

/// True when `text` is valid UTF-8 (ASCII included).
bool isValidUtf8(std::string_view text);
/// `text` (Windows-1252) converted to UTF-8; the five bytes Windows-1252 leaves undefined become
/// U+FFFD.
std::string windows1252ToUtf8(std::string_view text);
/// `text` as UTF-8: a UTF-8 BOM is removed; valid UTF-8 is kept, anything else is converted from
/// Windows-1252 (`*eightBit` set to true then).
std::string textAsUtf8(std::string_view text, bool* eightBit = nullptr);

}  // namespace metrofit
