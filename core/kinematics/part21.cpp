#include "core/kinematics/part21.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/file_io.h"

namespace metrofit {
namespace {

constexpr int kMaxDepth = 64;

bool isKeywordStart(char c) {
  return std::isupper(static_cast<unsigned char>(c)) || c == '_' || c == '!';
}
bool isKeywordChar(char c) {
  return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
         c == '_' || c == '-';
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& source) : t_(text), src_(source) {}

  P21File parse() {
    P21File f;
    f.source = src_;
    if (t_.size() >= 3 && t_.substr(0, 3) == "\xEF\xBB\xBF") advance(3);
    skip();
    expectKeyword("ISO-10303-21");
    expect(';');
    skip();
    expectKeyword("HEADER");
    expect(';');
    for (;;) {
      skip();
      const long line = line_;
      const std::string kw = keyword("a header entity or ENDSEC");
      if (kw == "ENDSEC") {
        expect(';');
        break;
      }
      P21Entity e;
      e.type = kw;
      e.line = line;
      skip();
      expect('(');
      e.params = params(0);
      expect(';');
      f.header.push_back(std::move(e));
    }
    bool sawData = false;
    for (;;) {
      skip();
      if (atEnd()) fail("the file ends before END-ISO-10303-21;");
      const std::string kw = keyword("DATA or END-ISO-10303-21");
      if (kw == "END-ISO-10303-21") {
        expect(';');
        break;
      }
      if (kw != "DATA") fail("expected DATA or END-ISO-10303-21, found '" + kw + "'");
      sawData = true;
      skip();
      if (peek('(')) {
        advance(1);
        (void)params(0);
      }
      expect(';');
      dataSection(f);
    }
    skip();
    if (!atEnd()) fail("text after END-ISO-10303-21;");
    if (!sawData) fail("the file has no DATA section");
    checkReferences(f);
    for (const char* required : {"FILE_DESCRIPTION", "FILE_NAME", "FILE_SCHEMA"}) {
      if (!f.headerEntity(required)) {
        throw ValidationError(ErrorContext{src_, 0, 0, required}, "missing in the HEADER section");
      }
    }
    return f;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ParseError(ErrorContext{src_, line_, static_cast<long>(i_ - lineStart_) + 1, {}}, what);
  }
  [[noreturn]] void failAtLine(long line, const std::string& what) const {
    throw ParseError(ErrorContext{src_, line, 0, {}}, what);
  }

  bool atEnd() const { return i_ >= t_.size(); }
  bool peek(char c) const { return i_ < t_.size() && t_[i_] == c; }
  void advance(std::size_t n) {
    for (std::size_t k = 0; k < n && i_ < t_.size(); ++k) {
      if (t_[i_] == '\n') {
        ++line_;
        lineStart_ = i_ + 1;
      }
      ++i_;
    }
  }

  /// Skips white space and /* comments */.
  void skip() {
    for (;;) {
      while (i_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[i_]))) advance(1);
      if (i_ + 1 < t_.size() && t_[i_] == '/' && t_[i_ + 1] == '*') {
        const long line = line_;
        const std::size_t end = t_.find("*/", i_ + 2);
        if (end == std::string_view::npos) failAtLine(line, "unterminated comment /* ...");
        advance(end + 2 - i_);
        continue;
      }
      return;
    }
  }

  void expect(char c) {
    skip();
    if (!peek(c)) {
      if (atEnd()) fail(std::string("expected '") + c + "', found the end of the file");
      fail(std::string("expected '") + c + "', found '" + t_[i_] + "'");
    }
    advance(1);
  }

  std::string keyword(const char* what) {
    skip();
    if (atEnd() || !isKeywordStart(t_[i_])) {
      if (atEnd()) fail(std::string("expected ") + what + ", found the end of the file");
      fail(std::string("expected ") + what + ", found '" + t_[i_] + "'");
    }
    const std::size_t start = i_;
    advance(1);
    while (i_ < t_.size() && isKeywordChar(t_[i_])) advance(1);
    return std::string(t_.substr(start, i_ - start));
  }

  void expectKeyword(std::string_view kw) {
    const std::string got = keyword(std::string(kw).c_str());
    if (got != kw) fail("expected " + std::string(kw) + ", found '" + got + "'");
  }

  long instanceId() {
    // at '#'
    advance(1);
    const std::size_t start = i_;
    while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) advance(1);
    if (i_ == start || i_ - start > 15) fail("'#' must be followed by an instance number (1 to 15 digits)");
    return std::stol(std::string(t_.substr(start, i_ - start)));
  }

  void dataSection(P21File& f) {
    for (;;) {
      skip();
      if (atEnd()) fail("the DATA section is not closed by ENDSEC;");
      if (!peek('#')) {
        const std::string kw = keyword("an instance '#n=' or ENDSEC");
        if (kw != "ENDSEC") fail("expected an instance '#n=' or ENDSEC, found '" + kw + "'");
        expect(';');
        return;
      }
      const long line = line_;
      P21Entity e;
      e.id = instanceId();
      e.line = line;
      expect('=');
      skip();
      if (peek('(')) fail("complex entity instances #" + std::to_string(e.id) + "=(...) are not supported");
      e.type = keyword("an entity name");
      expect('(');
      e.params = params(0);
      expect(';');
      if (f.data.count(e.id)) {
        failAtLine(line, "#" + std::to_string(e.id) + " is defined twice (first on line " +
                             std::to_string(f.data.at(e.id).line) + ")");
      }
      f.data.emplace(e.id, std::move(e));
    }
  }

  /// Parameters after '(' up to and including the closing ')'.
  std::vector<P21Value> params(int depth) {
    if (depth > kMaxDepth) fail("lists nested deeper than " + std::to_string(kMaxDepth) + " levels");
    std::vector<P21Value> out;
    skip();
    if (peek(')')) {
      advance(1);
      return out;
    }
    for (;;) {
      out.push_back(value(depth));
      skip();
      if (peek(',')) {
        advance(1);
        continue;
      }
      if (peek(')')) {
        advance(1);
        return out;
      }
      if (atEnd()) fail("expected ',' or ')', found the end of the file");
      fail(std::string("expected ',' or ')', found '") + t_[i_] + "'");
    }
  }

  P21Value value(int depth) {
    skip();
    if (atEnd()) fail("expected a parameter, found the end of the file");
    P21Value v;
    const char c = t_[i_];
    if (c == '$') {
      advance(1);
      v.kind = P21Value::Kind::Unset;
    } else if (c == '*') {
      advance(1);
      v.kind = P21Value::Kind::Derived;
    } else if (c == '\'') {
      v.kind = P21Value::Kind::String;
      v.text = string();
    } else if (c == '.') {
      advance(1);
      const std::size_t start = i_;
      while (i_ < t_.size() && (isKeywordChar(t_[i_]) && t_[i_] != '-')) advance(1);
      if (i_ == start || !peek('.')) fail("malformed enumeration value (expected .NAME.)");
      v.kind = P21Value::Kind::Enum;
      v.text = std::string(t_.substr(start, i_ - start));
      advance(1);
    } else if (c == '#') {
      v.kind = P21Value::Kind::Reference;
      v.reference = instanceId();
    } else if (c == '(') {
      advance(1);
      v.kind = P21Value::Kind::List;
      v.items = params(depth + 1);
    } else if (c == '"') {
      fail("binary values \"...\" are not supported");
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-') {
      number(v);
    } else if (isKeywordStart(c)) {
      v.kind = P21Value::Kind::Typed;
      v.text = keyword("a type name");
      expect('(');
      v.items = params(depth + 1);
      if (v.items.size() != 1) fail("typed parameter " + v.text + "(...) must have exactly one value");
    } else {
      fail(std::string("unexpected character '") + c + "' in a parameter list");
    }
    return v;
  }

  std::string string() {
    const long line = line_;
    advance(1);  // opening quote
    std::string out;
    for (;;) {
      if (atEnd()) failAtLine(line, "unterminated string '...");
      const char c = t_[i_];
      if (c == '\'') {
        if (i_ + 1 < t_.size() && t_[i_ + 1] == '\'') {
          out += '\'';
          advance(2);
          continue;
        }
        advance(1);
        return out;
      }
      if (c == '\\' && i_ + 1 < t_.size() && t_[i_ + 1] == '\\') {
        out += '\\';
        advance(2);
        continue;
      }
      if (c != '\n' && c != '\r') out += c;  // line breaks inside strings are not part of the value
      advance(1);
    }
  }

  void number(P21Value& v) {
    const std::size_t start = i_;
    const long startLine = line_;
    const long startCol = static_cast<long>(i_ - lineStart_) + 1;
    auto malformed = [&](const std::string& what) {
      throw ParseError(ErrorContext{src_, startLine, startCol, {}}, what);
    };
    if (peek('+') || peek('-')) advance(1);
    const std::size_t digits = i_;
    while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) advance(1);
    if (i_ == digits) malformed("malformed number (expected a digit)");
    bool real = false;
    if (peek('.')) {
      real = true;
      advance(1);
      while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) advance(1);
      if (peek('E') || peek('e')) {
        advance(1);
        if (peek('+') || peek('-')) advance(1);
        const std::size_t exp = i_;
        while (i_ < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i_]))) advance(1);
        if (i_ == exp) malformed("malformed real (expected exponent digits)");
      }
    }
    if (i_ < t_.size() && (std::isalpha(static_cast<unsigned char>(t_[i_])) || t_[i_] == '.')) {
      malformed("malformed number '" + std::string(t_.substr(start, i_ - start + 1)) + "'");
    }
    const std::string s(t_.substr(start, i_ - start));
    char* end = nullptr;
    const double d = metrofit::num::strtodC(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(d)) malformed("malformed number '" + s + "'");
    v.kind = real ? P21Value::Kind::Real : P21Value::Kind::Integer;
    v.number = d;
  }

  void checkReferences(const P21File& f) const {
    std::function<void(const P21Value&, const P21Entity&)> check = [&](const P21Value& v,
                                                                       const P21Entity& e) {
      if (v.kind == P21Value::Kind::Reference && !f.data.count(v.reference)) {
        failAtLine(e.line, "#" + std::to_string(e.id) + " " + e.type + " refers to #" +
                               std::to_string(v.reference) + ", which is not defined");
      }
      for (const auto& item : v.items) check(item, e);
    };
    for (const auto& [id, e] : f.data) {
      for (const auto& p : e.params) check(p, e);
    }
  }

  std::string_view t_;
  const std::string& src_;
  std::size_t i_ = 0;
  long line_ = 1;
  std::size_t lineStart_ = 0;
};

[[noreturn]] void chainFail(const P21File& f, const P21Entity& e, const std::string& what) {
  throw ValidationError(ErrorContext{f.source, e.line, 0, {}},
                        "#" + std::to_string(e.id) + " " + e.type + ": " + what);
}

/// The first instance of `type` that `e` refers to directly (in its parameters or their lists).
const P21Entity* firstRefOfType(const P21File& f, const P21Entity& e, std::string_view type) {
  std::function<const P21Entity*(const P21Value&)> find = [&](const P21Value& v) -> const P21Entity* {
    if (v.kind == P21Value::Kind::Reference) {
      const P21Entity& t = f.entity(v.reference);
      return t.type == type ? &t : nullptr;
    }
    if (v.kind == P21Value::Kind::List) {
      for (const auto& item : v.items) {
        if (const P21Entity* r = find(item)) return r;
      }
    }
    return nullptr;
  };
  for (const auto& p : e.params) {
    if (const P21Entity* r = find(p)) return r;
  }
  return nullptr;
}

std::string nameOf(const P21Entity& e) {
  return !e.params.empty() && e.params[0].kind == P21Value::Kind::String ? e.params[0].text : std::string();
}

}  // namespace

const P21Entity* P21File::headerEntity(std::string_view type) const {
  for (const auto& e : header) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

std::vector<std::string> P21File::schemas() const {
  std::vector<std::string> out;
  const P21Entity* s = headerEntity("FILE_SCHEMA");
  if (!s || s->params.empty() || s->params[0].kind != P21Value::Kind::List) return out;
  for (const auto& v : s->params[0].items) {
    if (v.kind == P21Value::Kind::String) out.push_back(v.text);
  }
  return out;
}

const P21Entity& P21File::entity(long id) const {
  const auto it = data.find(id);
  if (it == data.end())
    throw ParseError(ErrorContext{source, 0, 0, {}}, "#" + std::to_string(id) + " is not defined");
  return it->second;
}

std::vector<const P21Entity*> P21File::ofType(std::string_view type) const {
  std::vector<const P21Entity*> out;
  for (const auto& [id, e] : data) {
    if (e.type == type) out.push_back(&e);
  }
  return out;
}

P21File parsePart21(std::string_view text, const std::string& source) {
  return Parser(text, source).parse();
}

P21File readPart21(const std::string& path) {
  return parsePart21(readFile(path, 512u << 20), path);
}

StepNcToolpath stepNcToolpath(const P21File& f) {
  const auto plans = f.ofType("WORKPLAN");
  if (plans.empty())
    throw ValidationError(ErrorContext{f.source, 0, 0, "WORKPLAN"}, "the file has no WORKPLAN");
  const P21Entity& plan = *plans.front();
  StepNcToolpath out;
  out.workplan = nameOf(plan);
  if (plan.params.size() < 2 || plan.params[1].kind != P21Value::Kind::List) {
    chainFail(f, plan, "attribute 2 (its_elements) must be a list of workingsteps");
  }
  for (const auto& el : plan.params[1].items) {
    if (el.kind != P21Value::Kind::Reference) chainFail(f, plan, "its_elements must hold references");
    const P21Entity& ws = f.entity(el.reference);
    if (ws.type != "MACHINING_WORKINGSTEP") continue;
    out.workingsteps.push_back(nameOf(ws));
    // The operation: the entity the workingstep refers to that has a TOOLPATH_LIST.
    const P21Entity* list = nullptr;
    for (const auto& p : ws.params) {
      if (p.kind != P21Value::Kind::Reference) continue;
      if ((list = firstRefOfType(f, f.entity(p.reference), "TOOLPATH_LIST"))) break;
    }
    if (!list) chainFail(f, ws, "no operation with a TOOLPATH_LIST");
    if (list->params.empty() || list->params[0].kind != P21Value::Kind::List) {
      chainFail(f, *list, "attribute 1 (its_list) must be a list of toolpaths");
    }
    for (const auto& tp : list->params[0].items) {
      if (tp.kind != P21Value::Kind::Reference) chainFail(f, *list, "its_list must hold references");
      const P21Entity& traj = f.entity(tp.reference);
      if (traj.type != "CUTTER_LOCATION_TRAJECTORY") {
        chainFail(f, traj, "expected CUTTER_LOCATION_TRAJECTORY in the toolpath list");
      }
      const P21Entity* poly = firstRefOfType(f, traj, "POLYLINE");
      if (!poly) chainFail(f, traj, "its basiccurve is not a POLYLINE");
      if (poly->params.size() < 2 || poly->params[1].kind != P21Value::Kind::List) {
        chainFail(f, *poly, "attribute 2 (points) must be a list of CARTESIAN_POINTs");
      }
      for (const auto& pr : poly->params[1].items) {
        if (pr.kind != P21Value::Kind::Reference) chainFail(f, *poly, "points must be references");
        const P21Entity& cp = f.entity(pr.reference);
        if (cp.type != "CARTESIAN_POINT" || cp.params.size() < 2 ||
            cp.params[1].kind != P21Value::Kind::List) {
          chainFail(f, cp, "expected CARTESIAN_POINT('name', (x, y[, z]))");
        }
        const auto& c = cp.params[1].items;
        if (c.size() < 2 || c.size() > 3) chainFail(f, cp, "coordinates must have 2 or 3 values");
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < c.size(); ++k) {
          if (!c[k].isNumber()) chainFail(f, cp, "coordinate " + std::to_string(k + 1) + " is not a number");
          p(static_cast<Eigen::Index>(k)) = c[k].number;
        }
        out.points.push_back(p);
      }
    }
  }
  if (out.workingsteps.empty()) chainFail(f, plan, "the workplan has no MACHINING_WORKINGSTEP");
  return out;
}

}  // namespace metrofit
