#pragma once
// A small reader of ISO 10303-21 ("STEP Part 21") clear-text files: enough for the STEP-NC
// toolpath files Metrofit writes (export.h) and for simple files of other tools.
//
// Syntax read (ISO 10303-21:2016, clauses 5-8): the ISO-10303-21; ... END-ISO-10303-21; frame, a
// HEADER section and one or more DATA sections (DATA; or DATA(...);), simple entity instances
// `#id = NAME(params);`, comments /* ... */ between tokens, and the parameter forms
//   $ (unset), * (derived), integers, reals (1., -0.5, 1.E-05), 'strings' ('' is a quote, \\ a
//   backslash; other \ directives are kept as written), .ENUMS. (.T./.F. included), #references,
//   (lists), TYPED_NAME(parameter).
// Not read (ParseError naming the line): complex instances #id=(A(...)B(...)); binary "..." values.
// After parsing, every #reference must name a defined instance and ids must be unique.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace metrofit {

struct P21Value {
  enum class Kind { Unset, Derived, Integer, Real, String, Enum, Reference, List, Typed };
  Kind kind = Kind::Unset;
  double number = 0.0;          ///< Integer and Real
  long reference = 0;           ///< Reference: the instance id
  std::string text;             ///< String content, Enum name (without dots), Typed type name
  std::vector<P21Value> items;  ///< List elements; Typed: its one parameter

  bool isNumber() const { return kind == Kind::Integer || kind == Kind::Real; }
};

struct P21Entity {
  long id = 0;       ///< 0 for header entities
  std::string type;  ///< upper case as written
  std::vector<P21Value> params;
  long line = 0;  ///< physical line of the '#id' (or of the header entity name)
};

struct P21File {
  std::string source;
  std::vector<P21Entity> header;
  std::map<long, P21Entity> data;

  /// The header entity of that type, or nullptr.
  const P21Entity* headerEntity(std::string_view type) const;
  /// The schema names of FILE_SCHEMA.
  std::vector<std::string> schemas() const;
  /// Instance #id; ParseError naming the file when it does not exist.
  const P21Entity& entity(long id) const;
  /// Instances of a type, in id order.
  std::vector<const P21Entity*> ofType(std::string_view type) const;
};

/// Parses Part 21 text; ParseError "source:line:col: ..." on any syntax error, a duplicate id or a
/// dangling reference; ValidationError when FILE_DESCRIPTION, FILE_NAME or FILE_SCHEMA is missing.
P21File parsePart21(std::string_view text, const std::string& source);
P21File readPart21(const std::string& path);

/// The toolpath of a STEP-NC file as export.h writes it: the first WORKPLAN, its
/// MACHINING_WORKINGSTEPs in order, each workingstep's operation (the referenced entity that has a
/// TOOLPATH_LIST), the list's CUTTER_LOCATION_TRAJECTORYs and their POLYLINE of CARTESIAN_POINTs.
struct StepNcToolpath {
  std::string workplan;  ///< the workplan's id (name)
  std::vector<std::string> workingsteps;
  std::vector<Eigen::Vector3d> points;  ///< all polyline points in order, mm
};

/// ValidationError naming the line of the entity where the chain breaks.
StepNcToolpath stepNcToolpath(const P21File& file);

}  // namespace metrofit
