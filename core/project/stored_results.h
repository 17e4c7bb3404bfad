#pragma once
// Results stored in the project file (Project::results, docs/file-formats.md#stored-results): what a
// study page computed, kept with the settings and a hash of the data it came from, so that a saved and
// reopened project shows it (marked as stored, with when it was computed) and says when the settings or
// the data file changed since (the stored result is then out of date, never shown as current).
//
//   "results": {"<study>": {"<dataset id>": {"settings": {...}, "data_hash": "fnv1a64:<16 hex>",
//                                            "computed": "2026-11-29T05:40:12Z", ...figures...}}}
//
// The figures are the study's own (thermal: thermalResultJson, matching: matchingResultJson in
// core/study); this file only keeps and checks the envelope. Unknown keys are kept.
#include <string>

#include <nlohmann/json.hpp>

#include "core/project/project.h"

namespace metrofit {

/// "fnv1a64:" and 16 lowercase hex digits: FNV-1a 64 of the dataset file's bytes and of the way the
/// project reads it (kind, dialect, column mapping). FileError when the file cannot be read.
std::string datasetDataHash(const std::string& projectPath, const DatasetRef& dataset);

/// The current time in UTC as "YYYY-MM-DDTHH:MM:SSZ".
std::string utcTimestamp();

/// How a stored result relates to the project as it is now.
enum class StoredResultState {
  None,             ///< nothing stored for this study and dataset
  Current,          ///< same settings, same data: the stored figures are the ones a run would give
  SettingsChanged,  ///< the study's settings differ from those the result was computed with
  DataChanged,      ///< the data file (or how it is read) changed since
  DataMissing,      ///< the data file cannot be read now
};

struct StoredResult {
  StoredResultState state = StoredResultState::None;
  nlohmann::json entry;  ///< the stored object (settings, data_hash, computed, figures); null for None
  std::string computed;  ///< when it was computed (entry["computed"]), "" when unknown
};

/// results[study][dataset.id], checked against `settings` (compared as JSON) and the data's hash now.
StoredResult storedResult(const Project& project, const std::string& projectPath, const std::string& study,
                          const DatasetRef& dataset, const nlohmann::json& settings);

/// The entry to store: `figures` plus "settings", "data_hash" (of the file now) and "computed" (now).
/// FileError when the data file cannot be read.
nlohmann::json makeStoredResult(const std::string& projectPath, const DatasetRef& dataset,
                                const nlohmann::json& settings, nlohmann::json figures);

/// Sets results[study][datasetId] = entry (creates the objects on the way).
void setStoredResult(Project& project, const std::string& study, const std::string& datasetId,
                     nlohmann::json entry);

}  // namespace metrofit
