#pragma once
// The PDF report of a project: page 1 the summary (what was measured, what each study found, what to
// change on the machine, the error before and after, what the closed loop leaves unexplained), then
// one section per study the project declares, each ending with its conclusion and recommendation
// (inputs, settings, charts as vector graphics, tables, corrections, error before/after), the
// references and an appendix with the data provenance. The same code serves the GUI's "Export report" and
// `metrofit-cli report`. Needs a QGuiApplication (QApplication for charts); works with
// QT_QPA_PLATFORM=offscreen and does not use VTK (3D point sets are drawn as 2D projections with QPainter).
#include <QString>
#include <QStringList>

namespace metrofit {
class Project;

struct ReportOptions {
  QString projectPath;  ///< where the project was loaded from (resolves dataset paths)
  QString title;        ///< defaults to the project name
  int resolutionDpi = 300;
};

struct ReportSummary {
  int pages = 0;
  QStringList sections;  ///< titles of the sections written, in order
};

/// Writes the report atomically (QSaveFile) to pdfPath. Throws metrofit::ValidationError naming the
/// study and the field when a study setting is bad (core/study/study_check.h: checked before
/// anything is drawn), metrofit::InputError when a dataset of the project cannot be read, metrofit::FileError
/// when the PDF cannot be written, metrofit::OptionsError when resolutionDpi is outside [72, 1200]. On any
/// error pdfPath is left as it was (absent, or the previous file).
ReportSummary writeReport(const Project& project, const QString& pdfPath, const ReportOptions& options);

}  // namespace metrofit
