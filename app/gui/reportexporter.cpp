#include "app/gui/reportexporter.h"

#include <QDir>
#include <QProgressDialog>
#include <QWidget>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "core/project/project.h"
#include "widgets/report/report.h"

namespace metrofit {

ReportExporter::ReportExporter(QWidget* dialogParent) : QObject(dialogParent), dialogParent_(dialogParent) {
  connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, [this] {
    if (progress_) {
      progress_->close();
      progress_->deleteLater();
      progress_ = nullptr;
    }
    const Outcome outcome = watcher_.result();
    emit finished(outcome.ok, outcome.ok ? tr("Report written to %1 (%n page(s)).", nullptr, outcome.pages)
                                               .arg(QDir::toNativeSeparators(pdfPath_))
                                         : outcome.message);
  });
}

ReportExporter::~ReportExporter() { watcher_.waitForFinished(); }

bool ReportExporter::start(const Project& project, const QString& projectPath, const QString& pdfPath) {
  if (isRunning()) return false;
  pdfPath_ = pdfPath;
  progress_ = new QProgressDialog(tr("Writing the report…"), QString(), 0, 0, dialogParent_);
  progress_->setWindowTitle(tr("Export report"));
  progress_->setWindowModality(Qt::WindowModal);
  progress_->setMinimumDuration(0);
  progress_->setCancelButton(nullptr);
  progress_->show();
  ReportOptions options;
  options.projectPath = projectPath;
  watcher_.setFuture(QtConcurrent::run([project, pdfPath, options]() -> Outcome {
    try {
      const ReportSummary summary = writeReport(project, pdfPath, options);
      return {true, {}, summary.pages};
    } catch (const std::exception& e) {
      return {false, QString::fromStdString(e.what()), 0};
    }
  }));
  return true;
}

}  // namespace metrofit
