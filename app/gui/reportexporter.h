#pragma once
// Writes the PDF report of a project (metrofit::writeReport) on a worker thread while a busy
// progress dialog shows that the window is working. The worker gets a copy of the project.
#include <QFutureWatcher>
#include <QObject>
#include <QString>

class QProgressDialog;
class QWidget;

namespace metrofit {
class Project;

class ReportExporter : public QObject {
  Q_OBJECT
 public:
  /// The outcome of one export: ok, and the one-line error or the summary.
  struct Outcome {
    bool ok = false;
    QString message;
    int pages = 0;
  };

  explicit ReportExporter(QWidget* dialogParent);
  ~ReportExporter() override;

  /// Starts writing; false when an export is already running.
  bool start(const Project& project, const QString& projectPath, const QString& pdfPath);
  bool isRunning() const { return watcher_.isRunning(); }
  /// Blocks until the running export (if any) is done (used when the window closes).
  void waitForFinished() { watcher_.waitForFinished(); }

 signals:
  void finished(bool ok, const QString& message);

 private:
  QWidget* dialogParent_;
  QProgressDialog* progress_ = nullptr;
  QString pdfPath_;
  QFutureWatcher<Outcome> watcher_;
};

}  // namespace metrofit
