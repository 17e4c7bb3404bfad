#pragma once
// An interpreter for the subset of IEC 61131-3 Structured Text that core/thermal/control_export.cpp
// writes, so that the tests run the exported function block as a PLC would:
//   FUNCTION_BLOCK name, VAR_INPUT / VAR_OUTPUT / VAR ... END_VAR with `name : REAL|LREAL|BOOL
//   [:= literal];`, assignments, IF / ELSIF / ELSE / END_IF, OR, AND, NOT, comparisons, + - * /,
//   unary minus, parentheses, EXP(), REAL / BOOL literals, (* comments *). Identifiers and keywords
//   are case-insensitive, as in IEC 61131-3.
// REAL is IEEE single precision: every operation with a REAL operand is rounded to float, and so is
// every value stored in a REAL variable, so the tests see what a PLC's 32-bit arithmetic gives.
// Anything outside the subset (an unknown word, a missing ';', an undeclared variable, an input
// assigned inside the block) throws std::runtime_error naming the line: the exporter must not emit it.
// The same expression grammar evaluates the vendor forms' formulas (evaluateFormula).
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace metrofit::test::st {

enum class Type { Real, LReal, Bool, Literal };

struct Value {
  Type type = Type::Literal;
  double v = 0.0;
};

inline std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

struct Token {
  enum Kind { Ident, Number, Op, End } kind = End;
  std::string text;  ///< identifiers upper-cased
  int line = 0;
};

inline std::vector<Token> tokenise(const std::string& src) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("ST line " + std::to_string(line) + ": " + what);
  };
  while (i < src.size()) {
    const char c = src[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (src.compare(i, 2, "(*") == 0) {
      const std::size_t e = src.find("*)", i + 2);
      if (e == std::string::npos) fail("unterminated comment");
      for (std::size_t k = i; k < e; ++k) line += src[k] == '\n';
      i = e + 2;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t e = i;
      while (e < src.size() && (std::isalnum(static_cast<unsigned char>(src[e])) || src[e] == '_')) ++e;
      out.push_back({Token::Ident, upper(src.substr(i, e - i)), line});
      i = e;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t e = i;
      while (e < src.size() && std::isdigit(static_cast<unsigned char>(src[e]))) ++e;
      if (e < src.size() && src[e] == '.') {
        ++e;
        while (e < src.size() && std::isdigit(static_cast<unsigned char>(src[e]))) ++e;
      }
      if (e < src.size() && (src[e] == 'e' || src[e] == 'E')) {
        ++e;
        if (e < src.size() && (src[e] == '+' || src[e] == '-')) ++e;
        if (e >= src.size() || !std::isdigit(static_cast<unsigned char>(src[e]))) fail("bad exponent");
        while (e < src.size() && std::isdigit(static_cast<unsigned char>(src[e]))) ++e;
      }
      out.push_back({Token::Number, src.substr(i, e - i), line});
      i = e;
    } else {
      static const char* two[] = {":=", "<=", ">=", "<>"};
      bool done = false;
      for (const char* t : two) {
        if (src.compare(i, 2, t) == 0) {
          out.push_back({Token::Op, t, line});
          i += 2;
          done = true;
          break;
        }
      }
      if (done) continue;
      if (std::string("+-*/()<>=;:,").find(c) == std::string::npos)
        fail(std::string("unexpected '") + c + "'");
      out.push_back({Token::Op, std::string(1, c), line});
      ++i;
    }
  }
  out.push_back({Token::End, "", line});
  return out;
}

struct Expr {
  enum Kind { Num, Var, Neg, Not, Bin, Exp } kind = Num;
  double num = 0.0;
  std::string name, op;
  std::unique_ptr<Expr> a, b;
  int line = 0;
};

struct Stmt {
  enum Kind { Assign, If } kind = Assign;
  std::string target;
  std::unique_ptr<Expr> value;
  std::vector<std::pair<std::unique_ptr<Expr>, std::vector<Stmt>>> branches;  ///< IF / ELSIF
  std::vector<Stmt> otherwise;
  int line = 0;
};

/// The variables of a block (or of a formula): name -> type and value.
using Variables = std::map<std::string, Value>;

inline float toFloat(double v) {
  return static_cast<float>(v);
}

class Parser {
 public:
  explicit Parser(std::vector<Token> t) : t_(std::move(t)) {}

  const Token& peek() const { return t_[i_]; }
  bool is(const std::string& text) const { return t_[i_].kind != Token::Number && t_[i_].text == text; }
  void expect(const std::string& text) {
    if (!is(text)) fail("expected '" + text + "', got '" + peek().text + "'");
    ++i_;
  }
  std::string ident() {
    if (peek().kind != Token::Ident) fail("expected a name, got '" + peek().text + "'");
    return t_[i_++].text;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("ST line " + std::to_string(peek().line) + ": " + what);
  }

  std::unique_ptr<Expr> expr() { return binary(0); }

  std::vector<Stmt> statements(std::initializer_list<const char*> until) {
    std::vector<Stmt> out;
    for (;;) {
      for (const char* u : until)
        if (is(u)) return out;
      if (peek().kind == Token::End) fail("unexpected end of text");
      out.push_back(statement());
    }
  }

 private:
  static int precedence(const std::string& op) {
    if (op == "OR") return 1;
    if (op == "AND") return 2;
    if (op == "=" || op == "<>" || op == "<" || op == ">" || op == "<=" || op == ">=") return 3;
    if (op == "+" || op == "-") return 4;
    if (op == "*" || op == "/") return 5;
    return -1;
  }

  std::unique_ptr<Expr> binary(int minPrec) {
    auto left = unary();
    for (;;) {
      const std::string op = peek().kind == Token::Number ? "" : peek().text;
      const int p = precedence(op);
      if (p < 0 || p < minPrec) return left;
      ++i_;
      auto e = std::make_unique<Expr>();
      e->kind = Expr::Bin;
      e->op = op;
      e->line = peek().line;
      e->a = std::move(left);
      e->b = binary(p + 1);
      left = std::move(e);
    }
  }

  std::unique_ptr<Expr> unary() {
    auto e = std::make_unique<Expr>();
    e->line = peek().line;
    if (is("-") || is("NOT")) {
      e->kind = is("-") ? Expr::Neg : Expr::Not;
      ++i_;
      e->a = unary();
      return e;
    }
    if (is("(")) {
      ++i_;
      auto inner = expr();
      expect(")");
      return inner;
    }
    if (peek().kind == Token::Number) {
      e->kind = Expr::Num;
      const std::string& text = t_[i_++].text;
      if (std::from_chars(text.data(), text.data() + text.size(), e->num).ptr != text.data() + text.size())
        fail("bad number " + text);
      return e;
    }
    const std::string name = ident();
    if (name == "TRUE" || name == "FALSE") {
      e->kind = Expr::Num;
      e->num = name == "TRUE";
      e->name = "BOOL";
      return e;
    }
    if (is("(")) {
      if (name != "EXP") fail("function '" + name + "' is outside the subset");
      ++i_;
      e->kind = Expr::Exp;
      e->a = expr();
      expect(")");
      return e;
    }
    e->kind = Expr::Var;
    e->name = name;
    return e;
  }

  Stmt statement() {
    Stmt s;
    s.line = peek().line;
    if (is("IF")) {
      s.kind = Stmt::If;
      ++i_;
      auto cond = expr();
      expect("THEN");
      s.branches.emplace_back(std::move(cond), statements({"ELSIF", "ELSE", "END_IF"}));
      while (is("ELSIF")) {
        ++i_;
        auto c = expr();
        expect("THEN");
        s.branches.emplace_back(std::move(c), statements({"ELSIF", "ELSE", "END_IF"}));
      }
      if (is("ELSE")) {
        ++i_;
        s.otherwise = statements({"END_IF"});
      }
      expect("END_IF");
      expect(";");
      return s;
    }
    s.target = ident();
    expect(":=");
    s.value = expr();
    expect(";");
    return s;
  }

  std::vector<Token> t_;
  std::size_t i_ = 0;
};

inline Value evaluate(const Expr& e, const Variables& vars) {
  auto real = [](Type a, Type b) {
    if (a == Type::Real || b == Type::Real) return Type::Real;
    if (a == Type::LReal || b == Type::LReal) return Type::LReal;
    return Type::Literal;
  };
  auto round = [](Value v) {
    if (v.type == Type::Real) v.v = toFloat(v.v);
    return v;
  };
  switch (e.kind) {
    case Expr::Num:
      return {e.name == "BOOL" ? Type::Bool : Type::Literal, e.num};
    case Expr::Var: {
      const auto it = vars.find(e.name);
      if (it == vars.end())
        throw std::runtime_error("ST line " + std::to_string(e.line) + ": undeclared " + e.name);
      return it->second;
    }
    case Expr::Neg: {
      Value v = evaluate(*e.a, vars);
      v.v = -v.v;
      return v;
    }
    case Expr::Not: {
      const Value v = evaluate(*e.a, vars);
      return {Type::Bool, v.v != 0.0 ? 0.0 : 1.0};
    }
    case Expr::Exp: {
      const Value v = evaluate(*e.a, vars);
      if (v.type == Type::Real) return {Type::Real, std::exp(toFloat(v.v))};
      return {v.type, std::exp(v.v)};
    }
    case Expr::Bin: {
      const Value a = evaluate(*e.a, vars), b = evaluate(*e.b, vars);
      const std::string& op = e.op;
      if (op == "AND") return {Type::Bool, (a.v != 0.0 && b.v != 0.0) ? 1.0 : 0.0};
      if (op == "OR") return {Type::Bool, (a.v != 0.0 || b.v != 0.0) ? 1.0 : 0.0};
      if (op == "<") return {Type::Bool, a.v < b.v ? 1.0 : 0.0};
      if (op == ">") return {Type::Bool, a.v > b.v ? 1.0 : 0.0};
      if (op == "<=") return {Type::Bool, a.v <= b.v ? 1.0 : 0.0};
      if (op == ">=") return {Type::Bool, a.v >= b.v ? 1.0 : 0.0};
      if (op == "=") return {Type::Bool, a.v == b.v ? 1.0 : 0.0};
      if (op == "<>") return {Type::Bool, a.v != b.v ? 1.0 : 0.0};
      const Type t = real(a.type, b.type);
      // REAL: IEEE single operations (float operands, the double result rounded once to float, which
      // is the correctly rounded float result for + - * /).
      const double x = t == Type::Real ? toFloat(a.v) : a.v, y = t == Type::Real ? toFloat(b.v) : b.v;
      double r = 0.0;
      if (op == "+") r = x + y;
      if (op == "-") r = x - y;
      if (op == "*") r = x * y;
      if (op == "/") r = x / y;
      return round({t, r});
    }
  }
  return {};
}

/// A function block instance: declarations, statements and the variables kept between calls.
class Block {
 public:
  explicit Block(const std::string& source) {
    Parser p(tokenise(source));
    p.expect("FUNCTION_BLOCK");
    name_ = p.ident();
    while (p.is("VAR_INPUT") || p.is("VAR_OUTPUT") || p.is("VAR")) {
      const std::string section = p.peek().text;
      p.ident();
      while (!p.is("END_VAR")) {
        const std::string n = p.ident();
        p.expect(":");
        const std::string type = p.ident();
        Value v;
        if (type == "REAL")
          v.type = Type::Real;
        else if (type == "LREAL")
          v.type = Type::LReal;
        else if (type == "BOOL")
          v.type = Type::Bool;
        else
          p.fail("type " + type + " is outside the subset");
        if (p.is(":=")) {
          p.expect(":=");
          v.v = evaluate(*p.expr(), {}).v;
        }
        p.expect(";");
        if (vars_.count(n)) p.fail(n + " declared twice");
        vars_[n] = v;
        if (section == "VAR_INPUT") inputs_.push_back(n);
        if (section == "VAR_OUTPUT") outputs_.push_back(n);
      }
      p.expect("END_VAR");
    }
    body_ = p.statements({"END_FUNCTION_BLOCK"});
    p.expect("END_FUNCTION_BLOCK");
    if (p.peek().kind != Token::End) p.fail("text after END_FUNCTION_BLOCK");
  }

  const std::string& name() const { return name_; }
  const std::vector<std::string>& inputs() const { return inputs_; }
  const std::vector<std::string>& outputs() const { return outputs_; }

  void set(const std::string& input, double v) {
    const std::string n = upper(input);
    bool isInput = false;
    for (const auto& i : inputs_) isInput = isInput || i == n;
    if (!isInput) throw std::runtime_error("no input " + input);
    store(n, {Type::Literal, v}, 0);
  }
  double get(const std::string& name) const {
    const auto it = vars_.find(upper(name));
    if (it == vars_.end()) throw std::runtime_error("no variable " + name);
    return it->second.v;
  }
  /// One call of the block.
  void run() { execute(body_); }
  const Variables& variables() const { return vars_; }

 private:
  void store(const std::string& n, Value v, int line) {
    auto it = vars_.find(n);
    if (it == vars_.end()) throw std::runtime_error("ST line " + std::to_string(line) + ": undeclared " + n);
    if (it->second.type == Type::Real) v.v = toFloat(v.v);
    if (it->second.type == Type::Bool) v.v = v.v != 0.0 ? 1.0 : 0.0;
    it->second.v = v.v;
  }

  void execute(const std::vector<Stmt>& body) {
    for (const Stmt& s : body) {
      if (s.kind == Stmt::Assign) {
        for (const auto& i : inputs_)
          if (i == s.target)
            throw std::runtime_error("ST line " + std::to_string(s.line) + ": assigns the input " + i);
        store(s.target, evaluate(*s.value, vars_), s.line);
        continue;
      }
      bool done = false;
      for (const auto& [cond, branch] : s.branches) {
        if (evaluate(*cond, vars_).v != 0.0) {
          execute(branch);
          done = true;
          break;
        }
      }
      if (!done) execute(s.otherwise);
    }
  }

  std::string name_;
  Variables vars_;
  std::vector<std::string> inputs_, outputs_;
  std::vector<Stmt> body_;
};

/// Evaluates one expression of the subset (a vendor form's formula) in double precision.
inline double evaluateFormula(const std::string& text, const std::map<std::string, double>& values) {
  Parser p(tokenise(text));
  auto e = p.expr();
  if (p.peek().kind != Token::End) p.fail("text after the formula: '" + p.peek().text + "'");
  Variables vars;
  for (const auto& [k, v] : values) vars[upper(k)] = {Type::LReal, v};
  return evaluate(*e, vars).v;
}

}  // namespace metrofit::test::st
