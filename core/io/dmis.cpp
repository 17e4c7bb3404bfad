#include "core/io/dmis.h"

#include <cctype>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(b, e - b + 1));
}

std::size_t afterByteOrderMark(std::string_view text) {
  return text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
}

}  // namespace

std::string DmisStatement::field() const {
  return kind.empty() ? major : kind + "(" + label + ")";
}

std::vector<DmisStatement> dmisStatements(std::string_view text, const std::string& source) {
  std::vector<DmisStatement> out;
  std::string pending;
  long pendingLine = 0;
  long lineNo = 0;
  std::size_t pos = afterByteOrderMark(text);
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view raw = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++lineNo;
    // DMIS is text: a control byte (NUL, ESC, ...) means a binary file, and echoing it would break the
    // one-line message.
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const auto u = static_cast<unsigned char>(raw[i]);
      if ((u < 0x20 && u != '\t' && u != '\r') || u == 0x7f) {
        throw ParseError(ErrorContext{source, lineNo, static_cast<long>(i + 1), {}},
                         "binary data (control byte 0x" + std::string(1, "0123456789ABCDEF"[u >> 4]) +
                             "0123456789ABCDEF"[u & 15] + "); this is not a DMIS text file");
      }
    }
    // Remove a "$$" comment (outside quotes).
    bool inQuote = false;
    std::size_t cut = raw.size();
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '\'') inQuote = !inQuote;
      if (!inQuote && raw[i] == '$' && i + 1 < raw.size() && raw[i + 1] == '$') {
        cut = i;
        break;
      }
    }
    std::string line = trim(raw.substr(0, cut));
    if (pending.empty()) pendingLine = lineNo;
    if (!line.empty() && line.back() == '@') {
      line.pop_back();
      pending += line;
      continue;
    }
    pending += line;
    const std::string stmt = trim(pending);
    pending.clear();
    if (stmt.empty()) continue;
    DmisStatement s;
    s.line = pendingLine;
    std::string rhs = stmt;
    const auto eq = stmt.find('=');
    const auto slash0 = stmt.find('/');
    if (eq != std::string::npos && (slash0 == std::string::npos || eq < slash0)) {
      const std::string lhs = trim(std::string_view(stmt).substr(0, eq));
      const auto open = lhs.find('('), close = lhs.rfind(')');
      if (open == std::string::npos || close == std::string::npos || close < open) {
        throw ParseError(ErrorContext{source, s.line, 0, {}},
                         "expected 'KIND(label)=...', found '" + lhs + "'");
      }
      s.kind = upper(trim(std::string_view(lhs).substr(0, open)));
      s.label = trim(std::string_view(lhs).substr(open + 1, close - open - 1));
      rhs = trim(std::string_view(stmt).substr(eq + 1));
    }
    const auto slash = rhs.find('/');
    s.major = upper(trim(std::string_view(rhs).substr(0, slash)));
    if (slash != std::string::npos) {
      std::string_view rest = std::string_view(rhs).substr(slash + 1);
      while (true) {
        const auto comma = rest.find(',');
        s.minor.push_back(trim(rest.substr(0, comma)));
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
      }
      if (!s.minor.empty() && s.minor.back().empty()) s.minor.pop_back();
    }
    out.push_back(std::move(s));
  }
  if (!trim(pending).empty())
    throw ParseError(ErrorContext{source, pendingLine, 0, {}},
                     "the last statement ends in '@' (continuation) but the file ends");
  return out;
}

double dmisNumber(const DmisStatement& s, std::size_t i, const std::string& source, const std::string& what) {
  if (i >= s.minor.size()) throw ParseError(ErrorContext{source, s.line, 0, s.field()}, "missing " + what);
  double v = 0.0;
  if (!parseNumber(s.minor[i], &v))
    throw ParseError(ErrorContext{source, s.line, 0, s.field()},
                     what + ": '" + s.minor[i] + "' is not a number");
  return v;
}

double dmisUnitMm(const DmisStatement& units, const std::string& source) {
  const std::string u = units.minor.empty() ? std::string() : upper(units.minor.front());
  if (u == "MM") return 1.0;
  if (u == "CM") return 10.0;
  if (u == "INCH") return 25.4;
  if (u == "FEET") return 304.8;
  throw ParseError(ErrorContext{source, units.line, 0, "UNITS"}, "unknown length unit '" + u + "'");
}

std::optional<std::size_t> dmisDiameterIndex(const std::string& upperCaseType) {
  if (upperCaseType == "CIRCLE" || upperCaseType == "CYLNDR") return 6;  // x,y,z,i,j,k,diam
  if (upperCaseType == "SPHERE") return 3;                               // x,y,z,diam
  return std::nullopt;
}

bool looksLikeDmisText(std::string_view text) {
  std::size_t pos = afterByteOrderMark(text);
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string line =
        trim(text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos));
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    if (line.empty() || line.rfind("$$", 0) == 0) continue;
    const std::string u = upper(line);
    // Program files start with DMISMN (DMISMD for a module); CMM output files often with FILNAM.
    return u.rfind("DMISMN", 0) == 0 || u.rfind("DMISMD", 0) == 0 || u.rfind("FILNAM", 0) == 0;
  }
  return false;
}

}  // namespace metrofit
