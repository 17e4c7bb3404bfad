#pragma once
// What an imported file most likely is, and which of its columns are which roles: the guesses the
// import dialog and `metrofit-cli project add` start from, for files as shops write them (issue 28).
//
// Column names are matched ignoring case, spaces and underscores, with their unit read from a
// trailing bracket ("Zeit [min]", "Temperatur T1 [°C]", "Drehzahl [1/min]", "Abweichung (µm)") and by
// the common German and Polish words next to the English ones:
//   time        time, zeit, czas                       -> time_s / time_min / time_h by the unit
//   speed       spindle, drehzahl, prędkość, obroty    -> spindle_rpm (thermal logs)
//   nominal     nominal, nom, soll, nennmaß, nominalna -> nominal_mm (CMM report), qx/qy/qz (points)
//   actual      measured, meas, actual, ist, aktuell, istwert, zmierzona, rzeczywista
//                                                      -> measured_mm (CMM report), px/py/pz (points)
//   dimension   dimension, feature, characteristic, merkmal, maß, wymiar, cecha
//   part        part, teil, werkstück, część, detal
//   tolerances  lower/upper tol(erance), untere/obere toleranz, ut/ot, tol-/tol+, dolna/górna tolerancja
//   point id    id, nr, no, punkt, point, pkt
//   surface     surface, fläche, powierzchnia
//   raw points  x, y, z alone                          -> px, py, pz (measured points without nominals)
//   circle test angle, winkel, kąt -> angle_deg; deviation, abweichung, odchyłka -> deviation_um/_mm
// A role is only suggested when the column's unit (if it names one) is a unit of the role's quantity:
// the column is then read converted to the role's unit ("Soll X [µm]" as qx in mm, "Zeit [s]" as
// time_min: CsvTable::mapColumns, core/io/units.h), so no value is read in a unit it was not written
// in, and a column in °C is never a length. Other columns keep their names (a thermal log's sensors are
// read by their names, with the unit from the bracket: core/thermal/thermal_log.h).
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/io/csv.h"

namespace metrofit {

/// The kind (command-line spelling, datasetKindNames()) a file most likely is, from its name's
/// extension and its content read with `options` (header detection included): a JSON setup model, DMIS
/// output, a QIF 3 document ("qif"), an MTConnect SHDR log or Streams document ("mtconnect"), a Q-DAS DFQ
/// file ("dfq"), a Zeiss Calypso _chr or _fet table
/// ("calypso"), a CMM text report
/// (OGP, PC-DMIS), a hole table, an STL part (.stl, or ASCII STL content), or a CSV kind by its column
/// names and their
/// roles (suggestColumnRoles), "feature-series" when nothing else fits.
std::string guessDatasetKind(const std::string& fileName, std::string_view text,
                             const CsvReadOptions& options = {});

/// (role, column) pairs for the file's columns `header` read as `kind` (command-line spelling), in
/// header order; columns that already are a role's name (exactly) are left out (they need no
/// mapping), and each role is given at most once.
std::vector<std::pair<std::string, std::string>> suggestColumnRoles(const std::string& kind,
                                                                    const std::vector<std::string>& header);

/// A column name split into its words (lower case, without the trailing unit bracket) and its unit as
/// written in the bracket, normalised: "um", "mm", "nm", "degC", "s", "min", "h", "rpm", "deg", or ""
/// (none or unknown). "Zeit [min]" -> {"zeit"}, "min"; "Soll X" -> {"soll", "x"}, "".
struct ColumnName {
  std::vector<std::string> words;
  std::string unit;
};
ColumnName splitColumnName(const std::string& name);

}  // namespace metrofit
