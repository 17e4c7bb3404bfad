#pragma once
// Names and one-paragraph descriptions of the project's studies and dataset kinds, shared by the
// navigator, the study pages and the undo command texts (translated, context "StudyInfo").
#include <QString>
#include <QStringList>
#include <vector>

class QComboBox;

namespace metrofit {

struct DatasetRef;

/// The studies in navigator order (the keys of metrofit::study::kAll).
QStringList studyKeys();
/// Title of a study ("Setup correction", ...); the key itself for an unknown study.
QString studyTitle(const QString& study);
/// What the study does, one paragraph.
QString studySummary(const QString& study);
/// Dataset kinds a study works on (the diagnosis works on every domain's data).
QStringList studyDatasetKinds(const QString& study);
/// Readable name of a dataset kind ("Thermal log"); the kind itself when unknown.
QString datasetKindTitle(const QString& kind);
/// A study page's dataset chooser, filled without emitting signals: cleared, then one item per dataset
/// (text and data: its id; tooltip: its description), the current item the dataset `select` (the
/// first when there is no such dataset). Returns the current index (-1: no datasets).
int fillDatasetCombo(QComboBox* combo, const std::vector<DatasetRef>& datasets, const QString& select);

}  // namespace metrofit
