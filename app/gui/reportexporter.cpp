#include "app/gui/reportexporter.h"

#include "app/gui/language.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProgressDialog>
#include <QTemporaryDir>
#include <QWidget>
#include <exception>
#include <stdexcept>

#include "core/project/project.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {

ReportExporter::ReportExporter(QWidget* dialogParent)
    : QObject(dialogParent),
      dialogParent_(dialogParent),
      cliPath_(QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("metrofit-cli"))) {}

ReportExporter::~ReportExporter() {
  if (process_) {
    process_->disconnect(this);
    process_->kill();
    process_->waitForFinished(5000);
  }
}

bool ReportExporter::start(const ProjectDocument& document, const QString& pdfPath) {
  if (isRunning()) return false;
  pdfPath_ = QFileInfo(pdfPath).absoluteFilePath();
  cancelled_ = false;

  QString projectFile = document.fileName();
  shownName_ = projectFile.isEmpty() ? tr("the unsaved project") : QFileInfo(projectFile).fileName();
  snapshot_.reset();
  if (projectFile.isEmpty() || document.isModified()) {
    snapshot_ = std::make_unique<QTemporaryDir>();
    Project project = document.project();
    for (DatasetRef& d : project.datasets) d.path = QFile::encodeName(document.datasetPath(d)).toStdString();
    const QString name =
        projectFile.isEmpty() ? QStringLiteral("project.metrofit") : QFileInfo(projectFile).fileName();
    projectFile = snapshot_->filePath(name);
    try {
      if (!snapshot_->isValid()) throw std::runtime_error(snapshot_->errorString().toStdString());
      saveProject(project, QFile::encodeName(projectFile).toStdString());
    } catch (const std::exception& e) {
      snapshot_.reset();
      // Reported from the event loop, like every other outcome.
      const QString message = tr("Cannot prepare the report: %1").arg(QString::fromStdString(e.what()));
      QMetaObject::invokeMethod(
          this, [this, message] { emit finished(Outcome::Failed, message); }, Qt::QueuedConnection);
      return true;
    }
  }

  passedFile_ = projectFile;
  process_ = new QProcess(this);
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));  // the report needs no display
  process_->setProcessEnvironment(env);
  process_->setProgram(cliPath_);
  // The report speaks the language the window does (numbers keep the decimal point in every one).
  process_->setArguments({QStringLiteral("report"), QStringLiteral("--project"), projectFile,
                          QStringLiteral("--out"), pdfPath_, QStringLiteral("--lang"), currentLanguage()});
  connect(process_, &QProcess::finished, this, &ReportExporter::onProcessFinished);
  connect(process_, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
    if (error == QProcess::FailedToStart) {
      finish(Outcome::Failed,
             tr("Cannot run %1: %2").arg(QDir::toNativeSeparators(cliPath_), process_->errorString()));
    }
  });

  progress_ = new QProgressDialog(tr("Writing the report…"), tr("Cancel"), 0, 0, dialogParent_);
  progress_->setWindowTitle(tr("Export report"));
  progress_->setWindowModality(Qt::WindowModal);
  progress_->setMinimumDuration(0);
  progress_->setAutoClose(false);
  progress_->setAutoReset(false);
  connect(progress_, &QProgressDialog::canceled, this, &ReportExporter::cancel);
  progress_->show();

  process_->start();
  return true;
}

void ReportExporter::cancel() {
  if (!process_) return;
  cancelled_ = true;
  process_->kill();
}

void ReportExporter::waitForFinished() {
  if (process_) process_->waitForFinished(-1);
}

void ReportExporter::onProcessFinished(int exitCode, QProcess::ExitStatus status) {
  if (cancelled_) {
    finish(Outcome::Cancelled, tr("The report export was cancelled."));
  } else if (status != QProcess::NormalExit) {
    finish(Outcome::Failed,
           tr("metrofit-cli stopped unexpectedly while writing %1.").arg(QDir::toNativeSeparators(pdfPath_)));
  } else if (exitCode == 0) {
    finish(Outcome::Written, tr("Report written to %1.").arg(QDir::toNativeSeparators(pdfPath_)));
  } else {
    // metrofit-cli ends every failure with one line that says what is wrong.
    const QStringList lines =
        QString::fromLocal8Bit(process_->readAllStandardError()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    finish(Outcome::Failed, lines.isEmpty() ? tr("metrofit-cli failed with exit code %1.").arg(exitCode)
                                            : userMessage(lines.last().trimmed()));
  }
}

QString ReportExporter::userMessage(QString line) const {
  // "metrofit-cli: /tmp/metrofit-xPqdqI/demo.metrofit: field ...: ..." -> "demo.metrofit: field ...": the
  // user knows the file by its name, not by the snapshot's folder or the helper program.
  const QString prefix = QStringLiteral("metrofit-cli: ");
  if (line.startsWith(prefix)) line.remove(0, prefix.size());
  if (!passedFile_.isEmpty()) {
    line.replace(passedFile_, shownName_);
    line.replace(QDir::toNativeSeparators(passedFile_), shownName_);
  }
  return line;
}

void ReportExporter::finish(Outcome outcome, const QString& message) {
  if (progress_) {
    progress_->disconnect(this);
    progress_->close();
    progress_->deleteLater();
    progress_ = nullptr;
  }
  if (process_) {
    process_->disconnect(this);
    process_->deleteLater();
    process_ = nullptr;
  }
  snapshot_.reset();
  emit finished(outcome, message);
}

}  // namespace metrofit
