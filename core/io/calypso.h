#pragma once
// Zeiss Calypso table files (the "table file" export of a measurement plan, docs/file-formats.md#zeiss-
// calypso-table-files): three tab-separated text files per run, named after the plan,
//   <plan>_chr.txt  characteristics: one row per characteristic of a measured part, columns (by name,
//                   in any order, case-insensitive; others are ignored) planid, partnb, id, type,
//                   idsymbol, actual, nominal, uppertol, lowertol, deviation, ...; uppertol / lowertol
//                   are the tolerance limits relative to the nominal (lowertol usually negative),
//                   deviation = actual - nominal;
//   <plan>_fet.txt  features: one row per measured feature, columns x y z (actual position),
//                   x_nom y_nom z_nom (nominal position) and optionally nx ny nz (the normal, or axis),
//                   with id, type, planid, partnb;
//   <plan>_hdr.txt  the header of the run: planid, partnb, date, time, ... (one row per measured part).
// The first line names the columns; every following non-blank line is a row. Cells are separated by
// tabs (';' when the header line has no tab); numbers are written with a decimal comma or point (both
// read; a number has no digit grouping); the file is UTF-8 or Windows-1252 (core/io/text_encoding.h).
// Files are recognised by their column names, not by their file names. Errors (ParseError,
// ValidationError) name the file, the line and the column.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {

struct CalypsoCharacteristic {
  std::string planId, part, id, type, idSymbol;  ///< planid, partnb (the measured part), id, type, idsymbol
  double actual = 0.0;
  std::optional<double> nominal;
  std::optional<double> upperTol, lowerTol;  ///< relative to the nominal
  std::optional<double> deviation;           ///< as written (checked against actual - nominal)
  double rounding = 0.0;                     ///< half a unit of the last written digit of the actual
  long line = 0;
};

struct CalypsoCharacteristics {
  std::string source;
  std::vector<std::string> parts;  ///< the partnb values in order of first appearance ("" when none)
  std::vector<std::string> dates;  ///< per part: "date time" from the _hdr file beside it (may be empty)
  std::vector<CalypsoCharacteristic> rows;
};

/// A _chr table: the first line names at least id, actual and nominal, and planid or partnb.
bool looksLikeCalypsoCharacteristics(std::string_view text);
/// A _fet table: the first line names x, y, z, x_nom, y_nom and z_nom.
bool looksLikeCalypsoFeatures(std::string_view text);
/// A _hdr table: the first line names planid and partnb and date, but not actual.
bool looksLikeCalypsoHeader(std::string_view text);
/// Either a _chr or a _fet table.
inline bool looksLikeCalypso(std::string_view text) {
  return looksLikeCalypsoCharacteristics(text) || looksLikeCalypsoFeatures(text);
}

/// Reads a _chr table. ValidationError when a deviation disagrees with actual - nominal beyond the
/// rounding of the written digits, or the tolerances are inverted (lowertol above uppertol).
CalypsoCharacteristics calypsoCharacteristicsFromText(std::string_view text, const std::string& source);
/// Reads a _chr file and, when it is named *_chr.txt and a *_hdr.txt lies beside it, takes each part's
/// date and time from there.
CalypsoCharacteristics readCalypsoCharacteristics(const std::string& path);
/// The dates (date + " " + time) per partnb of a _hdr table.
std::vector<std::pair<std::string, std::string>> calypsoHeaderDates(std::string_view text,
                                                                    const std::string& source);

/// A _fet table as probe points (docs/file-formats.md#contact-probed-points): the table
/// id,surface,qx,qy,qz,[nx,ny,nz,]px,py,pz with q = (x_nom, y_nom, z_nom), p = (x, y, z), surface = the
/// feature's type, the normal (made unit length) when the file has nx ny nz and every row a non-zero
/// one. The rows of the first measured part (partnb) only; ValidationError when the file has several
/// parts (a matching needs one) or a row misses a number.
CsvTable calypsoFeaturesProbeTable(std::string_view text, const std::string& source);

}  // namespace metrofit
