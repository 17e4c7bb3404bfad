#pragma once
// Typed errors that carry their context (STYLE.md §9).
//
// Core never prints and never exits: it throws. Every error that a user can cause with a file or
// an option derives from InputError; the CLI maps InputError to exit code 2 and prints what() as
// one line, the GUI shows it in a message box. Any other std::exception is an internal failure
// (exit code 1).
//
// what() is formatted like a compiler diagnostic, so editors and people can jump to the cause:
//   "data/log.csv:12:3: column 'T1': 'abc' is not a number"
//   "model.json: field 'bounds_mm': lower bound 0.1 is above upper bound -0.1"
#include <stdexcept>
#include <string>

namespace metrofit {

/// Where an error was found. Empty / zero members are omitted from the message.
struct ErrorContext {
  std::string file;   ///< file path as the user gave it
  long line = 0;      ///< 1-based physical line number, 0 if unknown
  long column = 0;    ///< 1-based column (field index for CSV), 0 if unknown
  std::string field;  ///< column name, JSON pointer or option name

  /// "file:line:col: field 'x'" (the parts that are known).
  std::string prefix() const;
};

/// Base of all Metrofit errors.
class Error : public std::runtime_error {
 public:
  Error(ErrorContext context, std::string what);
  const ErrorContext& context() const noexcept { return context_; }
  /// The message without its location prefix.
  const std::string& detail() const noexcept { return detail_; }

 private:
  ErrorContext context_;
  std::string detail_;
};

/// Bad input from the user: a malformed file, an invalid field, an invalid option (exit code 2).
class InputError : public Error {
 public:
  using Error::Error;
};

/// A file could not be parsed (syntax): CSV quoting, JSON syntax, encoding.
class ParseError : public InputError {
 public:
  using InputError::InputError;
};

/// A file parsed but its content is invalid (semantics): missing column, reversed bounds, cycle.
class ValidationError : public InputError {
 public:
  using InputError::InputError;
};

/// Options of a method are invalid (Options::isValid said no).
class OptionsError : public InputError {
 public:
  using InputError::InputError;
};

/// A file could not be opened, read or written.
class FileError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace metrofit
