// Units written in column names ("Zeit [min]", "Soll X [µm]", "Ist (inch)") and in role names
// ("nominal_mm", "time_s", "deviation_um"), and the factors between units of one quantity: how a column
// mapped to a role is read in the role's unit (CsvTable::mapColumns, issue 28).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace metrofit {

/// A unit as written ("µm", "μm", "um", "mikron", "°C", "1/min", "U/min", "obr/min", "sek", "Std",
/// "inch", "in", "Zoll", ...), as core spells it: "nm", "um", "mm", "cm", "m", "inch", "s", "min",
/// "h", "deg", "rad", "rpm", "degC", "K"; "" when unknown. Case and blanks are ignored.
std::string normalUnitName(std::string_view written);

/// The unit a column name writes in a trailing bracket or parenthesis ("Zeit [min]" -> "min",
/// "Soll X (µm)" -> "um"), as normalUnitName spells it; "" when there is none or it is unknown.
std::string columnNameUnit(std::string_view columnName);

/// The unit of a role by its suffix ("nominal_mm" -> "mm", "deviation_um" -> "um", "time_s" -> "s",
/// "angle_deg" -> "deg", "spindle_rpm" -> "rpm"); the points' coordinates px..pz and qx..qz are in mm;
/// "" for a role without a unit (id, part, nx, direction, ...).
std::string roleUnit(std::string_view role);

/// The factor that turns a value in `from` into `to` (value_to = value_from * factor) when both are
/// units of the same quantity (length, time, angle, speed); nullopt otherwise (also for temperatures:
/// °C and K differ by an offset, not a factor).
std::optional<double> unitFactor(std::string_view from, std::string_view to);

}  // namespace metrofit
