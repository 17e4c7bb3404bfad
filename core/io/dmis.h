// DMIS (ANSI/DMIS 105.2, Dimensional Measuring Interface Standard) text: the statement tokenizer
// shared by the DMIS readers (core/setup/report.h: a setup report; core/project/dataset_content.h:
// the feature table of a dataset). Only what both need: statements with their line, the
// `KIND(label)=MAJOR/minor,...` split, `$$` comments, `@` continuations; numbers of a statement; the
// units of UNITS/...; where the diameter sits after CART in FEAT/type,CART,x,y,z,....
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace metrofit {

/// One DMIS statement (continuation lines joined, the `$$` comment removed).
struct DmisStatement {
  long line = 0;      ///< 1-based line where the statement starts
  std::string kind;   ///< "F", "FA", "T", "TA", ... (upper case); empty without `KIND(label)=`
  std::string label;  ///< inside the parentheses, as written
  std::string major;  ///< major word (upper case): FEAT, TOL, UNITS, DMISMN, ...
  std::vector<std::string>
      minor;  ///< comma separated words after '/', trimmed (a trailing empty one dropped)

  /// "F(label)" for a labelled statement, else the major word: the field named in errors.
  std::string field() const;
};

/// Splits DMIS text into statements. ParseError (file, line) on binary data (a control byte), a
/// malformed `KIND(label)=` and a file ending in a continuation `@`. A UTF-8 byte-order mark is skipped.
std::vector<DmisStatement> dmisStatements(std::string_view text, const std::string& source);

/// The i-th minor word of `s` as a number; ParseError naming `what`, the file, line and field when it is
/// missing or not a number.
double dmisNumber(const DmisStatement& s, std::size_t i, const std::string& source, const std::string& what);

/// Millimetres per unit of UNITS/MM|CM|INCH|FEET; ParseError naming the file and line otherwise.
double dmisUnitMm(const DmisStatement& units, const std::string& source);

/// Index of the diameter among the numbers after CART, by feature type (DMIS 5.3 FEAT syntax):
/// CIRCLE and CYLNDR x,y,z,i,j,k,diam -> 6; SPHERE x,y,z,diam -> 3; none for other types.
std::optional<std::size_t> dmisDiameterIndex(const std::string& upperCaseType);

/// True when the text's first statement is DMISMN/DMISMD (a program or module) or FILNAM (an output
/// file of a CMM).
bool looksLikeDmisText(std::string_view text);

}  // namespace metrofit
