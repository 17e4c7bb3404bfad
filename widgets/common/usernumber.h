#pragma once
// A number a user typed in a GUI field: in the UI's locale or in the C format (under German both
// "0,02" and "0.02"), group separators refused in both, so that "1.000" is not 1000 under German and
// "0,5" not 5 under C. One reader for the pages' free-text number fields.
#include <QLocale>
#include <QString>
#include <cmath>
#include <optional>

namespace metrofit {

/// The value, or nullopt for a text that is no finite number (an empty text included).
inline std::optional<double> parseUserNumber(const QString& text) {
  const QString t = text.trimmed();
  QLocale ui;
  ui.setNumberOptions(QLocale::RejectGroupSeparator);
  QLocale c = QLocale::c();
  c.setNumberOptions(QLocale::RejectGroupSeparator);
  bool ok = false;
  double v = ui.toDouble(t, &ok);
  if (!ok) v = c.toDouble(t, &ok);
  if (!ok || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace metrofit
