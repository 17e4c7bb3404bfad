#pragma once
// Writes the PDF report of the open project without blocking the window: `metrofit-cli report`
// (which calls metrofit::writeReport) runs as a child process while a busy progress dialog with a
// Cancel button is shown.
//
// Why a process and not a worker thread: writeReport draws Qt Charts, and Qt Charts is not
// thread-safe: ChartPresenter::textBoundingRect() lays out text in one static QGraphicsTextItem
// shared by every chart in the process, so a report written on a worker thread while the window
// shows charts crashes (seen in QTextDocument::setHtml under LegendMarkerItem::sizeHint).
//
// What is reported is what the user sees: a saved, unmodified project is passed as it is; otherwise
// a snapshot of the document (dataset paths made absolute) is written to a temporary folder.
#include <QObject>
#include <QProcess>
#include <QString>
#include <memory>

class QProgressDialog;
class QTemporaryDir;
class QWidget;

namespace metrofit {
class ProjectDocument;

class ReportExporter : public QObject {
  Q_OBJECT
 public:
  enum class Outcome { Written, Failed, Cancelled };
  Q_ENUM(Outcome)

  explicit ReportExporter(QWidget* dialogParent);
  ~ReportExporter() override;

  /// The metrofit-cli executable (default: next to this program).
  QString cliPath() const { return cliPath_; }
  void setCliPath(const QString& path) { cliPath_ = path; }

  /// Starts writing the report of the document to pdfPath; false when an export is already running.
  /// The outcome arrives with finished().
  bool start(const ProjectDocument& document, const QString& pdfPath);
  bool isRunning() const { return process_ != nullptr; }
  /// Stops a running export (finished(Cancelled, ...) follows).
  void cancel();
  /// Blocks until a running export is done (used when the window closes).
  void waitForFinished();

 signals:
  /// The outcome and a status line (Written, Cancelled) or the one-line error (Failed).
  void finished(metrofit::ReportExporter::Outcome outcome, const QString& message);

 private:
  void onProcessFinished(int exitCode, QProcess::ExitStatus status);
  void finish(Outcome outcome, const QString& message);
  /// metrofit-cli's error line as the user should read it: without the program's name, the project
  /// named by its file name (not the temporary snapshot's path).
  QString userMessage(QString line) const;

  QWidget* dialogParent_;
  QString cliPath_;
  QString pdfPath_;
  QString passedFile_;  ///< the project file given to metrofit-cli (a snapshot's when modified)
  QString shownName_;   ///< how the user knows that project: its file name
  QProcess* process_ = nullptr;
  QProgressDialog* progress_ = nullptr;
  std::unique_ptr<QTemporaryDir> snapshot_;
  bool cancelled_ = false;
};

}  // namespace metrofit
