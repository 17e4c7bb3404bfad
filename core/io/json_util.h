#pragma once
// JSON reading with errors a person can act on: syntax errors name file, line and column; nesting
// is limited (kMaxDepth) before parsing so hostile files cannot exhaust the stack; field accessors
// name the JSON path ("datasets[2].path") of a missing or mistyped field.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace metrofit {

inline constexpr int kMaxJsonDepth = 64;

/// Parses JSON text (UTF-8, BOM accepted). ParseError "file:line:col: ..." on bad syntax or nesting
/// deeper than kMaxJsonDepth.
nlohmann::json parseJson(std::string_view text, const std::string& source);
/// Reads and parses a JSON file.
nlohmann::json readJsonFile(const std::string& path);
/// Serialises with 2-space indentation and a final newline.
std::string dumpJson(const nlohmann::json& j);

/// Typed access to object members with ValidationError naming `source` and the field path.
class JsonReader {
 public:
  JsonReader(const nlohmann::json& j, std::string source, std::string path = {})
      : j_(j), source_(std::move(source)), path_(std::move(path)) {}

  const nlohmann::json& json() const { return j_; }
  const std::string& path() const { return path_; }
  bool has(const std::string& key) const { return j_.is_object() && j_.contains(key); }

  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  long integer(const std::string& key) const;
  bool boolean(const std::string& key, bool fallback) const;
  /// A member that must be an object / an array.
  JsonReader object(const std::string& key) const;
  JsonReader array(const std::string& key) const;
  /// Element i of an array reader.
  JsonReader at(std::size_t i) const;
  std::size_t size() const { return j_.size(); }

  /// ValidationError at this path (or at path.key when key is given).
  [[noreturn]] void fail(const std::string& what, const std::string& key = {}) const;
  /// Requires this node to be an object.
  void requireObject() const;

 private:
  const nlohmann::json& member(const std::string& key) const;
  std::string sub(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const nlohmann::json& j_;
  std::string source_;
  std::string path_;
};

}  // namespace metrofit
