#include "core/io/json_util.h"

#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/file_io.h"

namespace metrofit {
namespace {

void lineColumn(std::string_view text, std::size_t offset, long* line, long* col) {
  *line = 1;
  *col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++*line;
      *col = 1;
    } else {
      ++*col;
    }
  }
}

/// The message with control characters and bytes of invalid UTF-8 ("last read: '\x89'" of a binary
/// file) written as \xNN, so that the one-line message stays one line of valid text.
std::string printable(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    if (u >= 0x20 && u < 0x7f) {
      n = 1;
    } else if (u >= 0xC2 && u <= 0xF4) {
      n = u < 0xE0 ? 2 : u < 0xF0 ? 3 : 4;
      for (std::size_t k = 1; k < n; ++k) {
        if (i + k >= s.size() || (static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) n = 0;
      }
    }
    if (n > 0) {
      out.append(s, i, n);
      i += n - 1;
    } else {
      char buf[8];
      metrofit::c_snprintf(buf, sizeof buf, "\\x%02X", u);
      out += buf;
    }
  }
  return out;
}

const char* typeName(const nlohmann::json& j) {
  return j.type_name();
}

}  // namespace

nlohmann::json parseJson(std::string_view text, const std::string& source) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.size() >= 2 &&
      (static_cast<unsigned char>(text[0]) == 0xFF || static_cast<unsigned char>(text[0]) == 0xFE)) {
    throw ParseError(ErrorContext{source, 1, 1, {}}, "the file is UTF-16 encoded; save it as UTF-8");
  }
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw ParseError(ErrorContext{source, 1, 1, {}}, "invalid JSON: the file is empty (expected JSON)");
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    long line, col;
    lineColumn(text, nul, &line, &col);
    throw ParseError(ErrorContext{source, line, col, {}},
                     "binary data (a NUL byte); this is not a JSON text file");
  }
  // Nesting check before parsing (outside strings).
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
      continue;
    }
    if (c == '"')
      inString = true;
    else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth) {
        long line, col;
        lineColumn(text, i, &line, &col);
        throw ParseError(ErrorContext{source, line, col, {}},
                         "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      }
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    long line, col;
    lineColumn(text, e.byte > 0 ? e.byte - 1 : 0, &line, &col);
    std::string what = e.what();
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error
    // while parsing value - invalid literal; last read: 'x'"
    const auto pos = what.find("syntax error");
    if (pos != std::string::npos) what = what.substr(pos);
    throw ParseError(ErrorContext{source, line, col, {}}, "invalid JSON: " + printable(what));
  } catch (const nlohmann::json::exception& e) {
    // Not a syntax error but a value the parser cannot hold, e.g. out_of_range.406 for a number
    // beyond a double ("1e999"; found by fuzz/fuzz_project). nlohmann quotes the offending text:
    // locate it for the line and column.
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    long line = 0, col = 0;
    const auto open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open + 1) {
      const auto at = text.find(std::string_view(what).substr(open + 1, close - open - 1));
      if (at != std::string_view::npos) lineColumn(text, at, &line, &col);
    }
    throw ParseError(ErrorContext{source, line, col, {}}, "invalid JSON: " + printable(what));
  }
}

nlohmann::json readJsonFile(const std::string& path) {
  return parseJson(readFile(path, 256u << 20), path);
}

std::string dumpJson(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void JsonReader::fail(const std::string& what, const std::string& key) const {
  throw ValidationError(
      ErrorContext{source_, 0, 0, key.empty() ? (path_.empty() ? "(top level)" : path_) : sub(key)}, what);
}

void JsonReader::requireObject() const {
  if (!j_.is_object()) fail(std::string("expected a JSON object, found ") + typeName(j_));
}

const nlohmann::json& JsonReader::member(const std::string& key) const {
  requireObject();
  const auto it = j_.find(key);
  if (it == j_.end()) fail("missing", key);
  return *it;
}

std::string JsonReader::string(const std::string& key) const {
  const auto& v = member(key);
  if (!v.is_string()) fail(std::string("expected a string, found ") + typeName(v), key);
  return v.get<std::string>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

double JsonReader::number(const std::string& key) const {
  const auto& v = member(key);
  if (!v.is_number()) fail(std::string("expected a number, found ") + typeName(v), key);
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail("not a finite number", key);
  return d;
}

double JsonReader::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

long JsonReader::integer(const std::string& key) const {
  const auto& v = member(key);
  if (!v.is_number_integer()) fail(std::string("expected an integer, found ") + typeName(v), key);
  return v.get<long>();
}

bool JsonReader::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const auto& v = member(key);
  if (!v.is_boolean()) fail(std::string("expected true or false, found ") + typeName(v), key);
  return v.get<bool>();
}

JsonReader JsonReader::object(const std::string& key) const {
  const auto& v = member(key);
  if (!v.is_object()) fail(std::string("expected an object, found ") + typeName(v), key);
  return JsonReader(v, source_, sub(key));
}

JsonReader JsonReader::array(const std::string& key) const {
  const auto& v = member(key);
  if (!v.is_array()) fail(std::string("expected an array, found ") + typeName(v), key);
  return JsonReader(v, source_, sub(key));
}

JsonReader JsonReader::at(std::size_t i) const {
  return JsonReader(j_.at(i), source_, path_ + "[" + std::to_string(i) + "]");
}

}  // namespace metrofit
