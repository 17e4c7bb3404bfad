#pragma once
// Validation of a project's study settings against what the methods read (the keys and value checks of
// each study's settings type, core/study/study_settings.h), so that a bad setting is
// an error naming the study and the field, never a quiet default (a thermal study whose target names
// a column the log lacks, a dataset of a misspelled kind, an unknown setting, a study that names a
// dataset of the wrong kind). The report runs it before it draws anything, the GUI when a project
// is opened.
//
// Two steps: checkStudies needs only the project (studies, keys, dataset ids and kinds);
// checkStudyColumns needs the columns of the datasets (read by the caller) for the settings that
// name columns (thermal target and inputs, the SPC column).
#include <functional>
#include <string>
#include <vector>

#include "core/project/project.h"
#include "core/study/study_settings.h"

namespace metrofit {

/// One bad setting: the field as the project file spells it ("studies.thermal.target",
/// "datasets[3].kind") and what is wrong with it.
using StudyIssue = SettingIssue;

/// The dataset kinds a project may hold (dataset_kind::..., plus the import formats).
const std::vector<std::string>& knownDatasetKinds();

/// Problems of the study settings that the project alone shows: unknown studies and keys, keys of
/// the wrong type, datasets that do not exist or are of the wrong kind, unknown dataset kinds.
/// "notes" (the GUI's notes) is allowed in every study. Empty when all is well.
std::vector<StudyIssue> checkStudies(const Project& project);

/// The column names of a dataset, or nullptr when the caller did not read it.
using DatasetColumns = std::function<const std::vector<std::string>*(const std::string& datasetId)>;

/// Problems of settings that name columns: studies.thermal target / inputs, the diagnosis's thermal
/// target / inputs, studies.kinematics.spc.column.
std::vector<StudyIssue> checkStudyColumns(const Project& project, const DatasetColumns& columns);

/// Throws ValidationError naming `source` and the field of the first problem (checkStudies, then
/// checkStudyColumns when `columns` is given).
void validateStudies(const Project& project, const std::string& source, const DatasetColumns& columns = {});

}  // namespace metrofit
