#include "core/io/units.h"

#include <array>
#include <cctype>
#include <numbers>

namespace metrofit {
namespace {

struct UnitFactor {
  const char* unit;
  const char* quantity;
  double inBase;  ///< the unit in its quantity's base unit (mm, min, deg, rpm)
};

constexpr std::array<UnitFactor, 13> kUnits{{
    {"nm", "length", 1e-6},
    {"um", "length", 1e-3},
    {"mm", "length", 1.0},
    {"cm", "length", 10.0},
    {"m", "length", 1000.0},
    {"inch", "length", 25.4},
    {"s", "time", 1.0 / 60.0},
    {"min", "time", 1.0},
    {"h", "time", 60.0},
    {"deg", "angle", 1.0},
    {"rad", "angle", 180.0 / std::numbers::pi},
    {"rpm", "speed", 1.0},
    {"degC", "temperature", 1.0},
}};

const UnitFactor* find(std::string_view unit) {
  for (const UnitFactor& u : kUnits)
    if (unit == u.unit) return &u;
  return nullptr;
}

bool endsWith(std::string_view s, std::string_view suffix) {
  return s.size() > suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

std::string normalUnitName(std::string_view written) {
  std::string l;
  for (char c : written)
    if (!std::isspace(static_cast<unsigned char>(c)))
      l += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (l == "\xC2\xB5m" || l == "\xCE\xBCm" || l == "um" || l == "mym" || l == "mikron" || l == "micron")
    return "um";
  if (l == "nm" || l == "mm" || l == "cm" || l == "m") return l;
  if (l == "inch" || l == "in" || l == "zoll" || l == "cal" || l == "\"") return "inch";
  if (l == "\xC2\xB0"
           "c" ||
      l == "degc" || l == "c")
    return "degC";
  if (l == "k") return "K";
  if (l == "s" || l == "sec" || l == "sek") return "s";
  if (l == "min") return "min";
  if (l == "h" || l == "std") return "h";
  if (l == "1/min" || l == "u/min" || l == "rpm" || l == "min-1" || l == "min^-1" || l == "obr/min" ||
      l == "min\xE2\x81\xBB\xC2\xB9")
    return "rpm";
  if (l == "\xC2\xB0" || l == "deg") return "deg";
  if (l == "rad") return "rad";
  return {};
}

std::string columnNameUnit(std::string_view columnName) {
  std::string_view n = columnName;
  while (!n.empty() && std::isspace(static_cast<unsigned char>(n.back()))) n.remove_suffix(1);
  if (n.empty() || (n.back() != ']' && n.back() != ')')) return {};
  const char open = n.back() == ']' ? '[' : '(';
  const auto at = n.rfind(open);
  if (at == std::string_view::npos) return {};
  return normalUnitName(n.substr(at + 1, n.size() - at - 2));
}

std::string roleUnit(std::string_view role) {
  for (const char* suffix : {"_mm", "_um", "_nm", "_deg", "_rad", "_s", "_min", "_h", "_rpm"})
    if (endsWith(role, suffix)) return std::string(std::string_view(suffix).substr(1));
  if (role.size() == 2 && (role[0] == 'p' || role[0] == 'q') &&
      (role[1] == 'x' || role[1] == 'y' || role[1] == 'z'))
    return "mm";
  return {};
}

std::optional<double> unitFactor(std::string_view from, std::string_view to) {
  const UnitFactor* f = find(from);
  const UnitFactor* t = find(to);
  if (!f || !t || std::string_view(f->quantity) != t->quantity) return std::nullopt;
  if (std::string_view(f->quantity) == "temperature") return 1.0;  // degC to degC only
  return from == to ? 1.0 : f->inBase / t->inBase;
}

}  // namespace metrofit
