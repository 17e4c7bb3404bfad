#pragma once
// How a page names a stored result (core/project/stored_results.h): when it was computed, whether it
// is current, and its figures.
#include <QString>
#include <limits>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/project/stored_results.h"

namespace metrofit {

/// "2026-11-29 05:40 UTC" (the date and time in the UI language's short format) for the stored
/// "computed" value ("YYYY-MM-DDTHH:MM:SSZ"); "at an unknown time" when it is empty or unreadable.
QString storedTimeText(const std::string& computed);

/// A page's words for a stored result that is not current, each with %1 = when it was computed
/// (storedTimeText). The page translates them in its own context (tr()), since each names its own
/// settings, data file and run action.
struct StoredStateTexts {
  QString settingsChanged;  ///< StoredResultState::SettingsChanged: "out of date: the settings changed"
  QString dataChanged;      ///< StoredResultState::DataChanged: "out of date: the data file changed"
  QString dataMissing;      ///< StoredResultState::DataMissing: "cannot be checked: cannot be read"
};

/// The text for `stored` when it is not current: empty for None, else the page's text for the state
/// with the time filled in. std::nullopt for a current result: the page then shows its figures.
std::optional<QString> storedStateText(const StoredResult& stored, const StoredStateTexts& texts);

/// block[key] as a number; `missing` when `block` is no object, or the key is absent or not a number
/// (core writes a non-finite figure as null).
double storedFigure(const nlohmann::json& block, const char* key,
                    double missing = std::numeric_limits<double>::quiet_NaN());

/// block[key] as a whole number (a count); 0 when absent or not an integer.
long long storedCount(const nlohmann::json& block, const char* key);

}  // namespace metrofit
