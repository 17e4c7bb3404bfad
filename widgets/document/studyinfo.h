#pragma once
// Names and one-paragraph descriptions of the project's studies and dataset kinds, shared by the
// navigator, the study pages and the undo command texts (translated, context "StudyInfo").
#include <QString>
#include <QStringList>

namespace metrofit {

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

}  // namespace metrofit
