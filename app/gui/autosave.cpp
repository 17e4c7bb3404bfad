#include "app/gui/autosave.h"

#include <signal.h>
#include <sys/types.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUndoStack>
#include <QWidget>
#include <algorithm>
#include <cerrno>
#include <exception>
#include <string>

#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/project/project.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

constexpr int kMsPerMinute = 60 * 1000;

std::string encodedPath(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

QString untitledFileName(qint64 pid) {
  return QStringLiteral("untitled-%1%2%3")
      .arg(pid)
      .arg(QLatin1String(Project::kFileSuffix), QLatin1String(Autosave::kSuffix));
}

/// True when a process with this id is running (or exists but belongs to someone else).
bool processIsRunning(qint64 pid) {
  if (pid <= 0) return false;
  if (::kill(static_cast<pid_t>(pid), 0) == 0) return true;
  return errno == EPERM;
}

QDateTime modified(const QString& path) {
  return QFileInfo(path).lastModified();
}

constexpr const char* kUnsavedKey = "unsaved";

}  // namespace

AutosaveExtras* AutosaveExtras::of(ProjectDocument* document) {
  static const QString name = QStringLiteral("metrofitAutosaveExtras");
  if (auto* extras = document->findChild<AutosaveExtras*>(name, Qt::FindDirectChildrenOnly)) return extras;
  auto* extras = new AutosaveExtras(document);
  extras->setObjectName(name);
  return extras;
}

void AutosaveExtras::add(const QString& key, QObject* owner, Source source) {
  std::erase_if(entries_, [&](const Entry& e) { return e.key == key || e.owner.isNull(); });
  entries_.push_back({key, owner, std::move(source)});
}

void AutosaveExtras::remove(QObject* owner) {
  std::erase_if(entries_, [&](const Entry& e) { return e.owner == owner || e.owner.isNull(); });
}

bool AutosaveExtras::anyModified() const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [](const Entry& e) { return !e.owner.isNull() && e.source.isModified(); });
}

nlohmann::json AutosaveExtras::save() const {
  nlohmann::json out = nlohmann::json::object();
  for (const Entry& e : entries_) {
    if (!e.owner.isNull() && e.source.isModified()) out[e.key.toStdString()] = e.source.save();
  }
  return out;
}

QStringList AutosaveExtras::restore(const nlohmann::json& unsaved) {
  QStringList failures;
  if (!unsaved.is_object()) return failures;
  for (const Entry& e : entries_) {
    const auto value = unsaved.find(e.key.toStdString());
    if (e.owner.isNull() || value == unsaved.end()) continue;
    try {
      e.source.restore(*value);
    } catch (const std::exception& ex) {
      failures << QStringLiteral("%1: %2").arg(e.key, QString::fromStdString(ex.what()));
    }
  }
  return failures;
}

Autosave::Autosave(ProjectDocument* document, QObject* parent)
    : QObject(parent),
      document_(document),
      extras_(AutosaveExtras::of(document)),
      timer_(new QTimer(this)),
      writer_(new BackgroundRun<QString>(this)),
      untitledFolder_(defaultUntitledFolder()) {
  connect(timer_, &QTimer::timeout, this, [this] { tick(); });
  connect(writer_, &BackgroundRunBase::finished, this, &Autosave::onWriteFinished);
  // The job catches what writeFileAtomic throws; anything else still ends the pending write.
  connect(writer_, &BackgroundRunBase::failed, this, [this](const QString& message) {
    if (!pending_) return;
    pending_ = false;
    emit failed(message);
  });
  connect(document_, &ProjectDocument::changed, this, [this] { ++generation_; });
  connect(extras_, &AutosaveExtras::changed, this, [this] { ++generation_; });
  // Saved (either half): the side file goes, so it never holds what is older than the files; while
  // the other half still has unsaved changes, the next tick writes them again.
  connect(document_, &ProjectDocument::modifiedChanged, this, [this](bool modified) {
    if (!modified) removeWritten();
  });
  connect(extras_, &AutosaveExtras::modifiedChanged, this, [this] {
    if (!extras_->anyModified()) removeWritten();
  });
  setIntervalMs(intervalSetting() * kMsPerMinute);
}

bool Autosave::anythingModified() const {
  return document_->isModified() || extras_->anyModified();
}

Autosave::~Autosave() {
  // A side file being written is finished (atomically), never left half-written.
  writer_->waitForWorker();
}

int Autosave::intervalSetting() {
  bool ok = false;
  const int minutes =
      QSettings().value(QString::fromLatin1(kIntervalSettingsKey), kDefaultIntervalMinutes).toInt(&ok);
  if (!ok) return kDefaultIntervalMinutes;
  return std::clamp(minutes, 0, kMaxIntervalMinutes);
}

void Autosave::setIntervalSetting(int minutes) {
  QSettings().setValue(QString::fromLatin1(kIntervalSettingsKey),
                       std::clamp(minutes, 0, kMaxIntervalMinutes));
}

QString Autosave::autosaveFileFor(const QString& projectFile) {
  return projectFile + QLatin1String(kSuffix);
}

QString Autosave::defaultUntitledFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

void Autosave::setIntervalMs(int ms) {
  if (ms <= 0) {
    timer_->stop();
    timer_->setInterval(0);
    return;
  }
  timer_->start(ms);
}

int Autosave::intervalMs() const {
  return timer_->isActive() ? timer_->interval() : 0;
}

QString Autosave::autosaveFile() const {
  const QString file = document_->fileName();
  if (!file.isEmpty()) return autosaveFileFor(file);
  return QDir(untitledFolder_).filePath(untitledFileName(QCoreApplication::applicationPid()));
}

bool Autosave::tick() {
  if (pending_ || !anythingModified()) return false;
  const QString target = autosaveFile();
  if (target == writtenFile_ && generation_ == writtenGeneration_) return false;  // nothing new
  if (document_->fileName().isEmpty() && !QDir().mkpath(untitledFolder_)) {
    emit failed(tr("cannot create the autosave folder %1").arg(QDir::toNativeSeparators(untitledFolder_)));
    return false;
  }
  // Serialising the small project JSON is quick; the write (with fsync) goes to a worker.
  nlohmann::json json = document_->project().toJson();
  if (nlohmann::json unsaved = extras_->save(); !unsaved.empty()) json[kUnsavedKey] = std::move(unsaved);
  std::string text = dumpJson(json);
  pending_ = true;
  pendingFile_ = target;
  pendingGeneration_ = generation_;
  writer_->start([path = encodedPath(target), text = std::move(text)](RunObserver&) -> QString {
    try {
      writeFileAtomic(path, text);
    } catch (const std::exception& e) {
      return QString::fromStdString(e.what());
    }
    return {};
  });
  return true;
}

void Autosave::waitForWrite() {
  if (!pending_) return;
  writer_->waitForFinished();  // emits finished (onWriteFinished) or failed now, not from the event loop
}

void Autosave::onWriteFinished() {
  if (!pending_) return;  // handled already
  pending_ = false;
  const QString error = writer_->takeResult().value_or(QString());
  if (!error.isEmpty()) {
    emit failed(error);
    return;
  }
  if (!anythingModified()) {
    // Saved (or undone to the saved state) while the worker wrote: the copy is not needed.
    QFile::remove(pendingFile_);
    return;
  }
  if (!writtenFile_.isEmpty() && writtenFile_ != pendingFile_) QFile::remove(writtenFile_);
  writtenFile_ = pendingFile_;
  writtenGeneration_ = pendingGeneration_;
  emit written(writtenFile_);
}

void Autosave::removeWritten() {
  waitForWrite();
  if (writtenFile_.isEmpty()) return;
  QFile::remove(writtenFile_);
  writtenFile_.clear();
}

RecoveryChoice Autosave::decide(const RecoveryOffer& offer) {
  if (decider_) return decider_(offer);
  return askUser(qobject_cast<QWidget*>(parent()), offer);
}

std::optional<RecoveryChoice> Autosave::open(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  const QString side = autosaveFileFor(absolute);
  std::optional<Project> autosaved;
  nlohmann::json unsaved;
  RecoveryOffer offer;
  // Our own side file of this session belongs to the content being replaced (reload from disk).
  if (side != writtenFile_ && QFileInfo::exists(side) && QFileInfo::exists(absolute) &&
      modified(side) > modified(absolute)) {
    try {
      autosaved = readSideFile(side, &unsaved);
    } catch (const std::exception& e) {
      emit failed(tr("The autosaved copy cannot be read: %1").arg(QString::fromStdString(e.what())));
    }
    if (autosaved) {
      offer = {absolute, side, modified(side), modified(absolute), QString::fromStdString(autosaved->name),
               {}};
      for (const auto& [key, value] : unsaved.items()) offer.unsaved << QString::fromStdString(key);
    }
  }
  if (!autosaved) {
    document_->load(absolute);
    return std::nullopt;
  }
  const RecoveryChoice choice = decide(offer);
  document_->load(absolute);  // throws: nothing changed, the side file stays
  switch (choice) {
    case RecoveryChoice::Recover:
      document_->replaceProject(*autosaved, tr("Recover autosaved changes"));
      restoreExtras(unsaved);
      writtenFile_ = side;  // removed again by a save or a discard
      writtenGeneration_ = generation_;
      break;
    case RecoveryChoice::Discard:
      QFile::remove(side);
      break;
    case RecoveryChoice::OpenOriginal:
      break;
  }
  return choice;
}

QString Autosave::orphanedUntitledFile() const {
  static const QRegularExpression pattern(
      QStringLiteral("^untitled-(\\d+)%1%2$")
          .arg(QRegularExpression::escape(QLatin1String(Project::kFileSuffix)),
               QRegularExpression::escape(QLatin1String(kSuffix))));
  const QDir folder(untitledFolder_);
  QString newest;
  QDateTime newestTime;
  const QFileInfoList files = folder.entryInfoList({QStringLiteral("untitled-*")}, QDir::Files);
  for (const QFileInfo& info : files) {
    const QRegularExpressionMatch match = pattern.match(info.fileName());
    if (!match.hasMatch()) continue;
    const qint64 pid = match.captured(1).toLongLong();
    if (pid == QCoreApplication::applicationPid() || processIsRunning(pid)) continue;
    if (newest.isEmpty() || info.lastModified() > newestTime) {
      newest = info.absoluteFilePath();
      newestTime = info.lastModified();
    }
  }
  return newest;
}

std::optional<RecoveryChoice> Autosave::recoverUntitled() {
  const QString side = orphanedUntitledFile();
  if (side.isEmpty()) return std::nullopt;
  Project autosaved;
  nlohmann::json unsaved;
  try {
    autosaved = readSideFile(side, &unsaved);
  } catch (const std::exception& e) {
    emit failed(tr("The autosaved copy cannot be read: %1").arg(QString::fromStdString(e.what())));
    return std::nullopt;
  }
  RecoveryOffer offer{QString(), side, modified(side), QDateTime(), QString::fromStdString(autosaved.name),
                      {}};
  for (const auto& [key, value] : unsaved.items()) offer.unsaved << QString::fromStdString(key);
  const RecoveryChoice choice = decide(offer);
  switch (choice) {
    case RecoveryChoice::Recover:
      document_->newProject();
      document_->replaceProject(autosaved, tr("Recover autosaved changes"));
      restoreExtras(unsaved);
      // The next autosave goes to this process's file and removes the recovered one.
      writtenFile_ = side;
      writtenGeneration_ = generation_;
      break;
    case RecoveryChoice::Discard:
      QFile::remove(side);
      break;
    case RecoveryChoice::OpenOriginal:
      break;
  }
  return choice;
}

Project Autosave::readSideFile(const QString& path, nlohmann::json* unsaved) const {
  const std::string file = encodedPath(path);
  const nlohmann::json json = readJsonFile(file);
  Project project = Project::fromJson(json, file);
  *unsaved = nlohmann::json::object();
  if (json.is_object()) {
    const auto u = json.find(kUnsavedKey);
    if (u != json.end() && u->is_object()) *unsaved = *u;
  }
  return project;
}

void Autosave::restoreExtras(const nlohmann::json& unsaved) {
  for (const QString& failure : extras_->restore(unsaved))
    emit failed(tr("An autosaved edit cannot be recovered: %1").arg(failure));
}

RecoveryChoice Autosave::askUser(QWidget* parent, const RecoveryOffer& offer) {
  const QLocale locale;
  const QString when = locale.toString(offer.autosaved, QLocale::ShortFormat);
  QString text;
  if (offer.projectFile.isEmpty()) {
    text = tr("Metrofit was not closed properly. An autosaved copy of the unsaved project “%1” from %2 "
              "was found.\n\nDo you want to recover it?")
               .arg(offer.projectName, when);
  } else {
    text = tr("The project %1 has an autosaved copy from %2 that is newer than the file (saved %3). "
              "Metrofit was probably not closed properly.\n\nDo you want to recover the autosaved "
              "changes? They are opened as unsaved changes; the project file is only overwritten "
              "when you save.")
               .arg(QDir::toNativeSeparators(offer.projectFile), when,
                    locale.toString(offer.saved, QLocale::ShortFormat));
  }
  if (offer.unsaved.contains(QStringLiteral("setup_model")))
    text += QStringLiteral("\n\n") +
            tr("The autosaved copy includes unsaved edits of the setup model (relation graph); they are "
               "recovered as unsaved edits too.");
  QMessageBox box(QMessageBox::Question, tr("Recover autosaved changes"), text, QMessageBox::NoButton,
                  parent);
  box.setObjectName(QStringLiteral("recoveryBox"));
  QPushButton* recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
  QPushButton* discard = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
  QPushButton* original = box.addButton(
      offer.projectFile.isEmpty() ? tr("&Keep for later") : tr("&Open original"), QMessageBox::RejectRole);
  recover->setToolTip(tr("Open the autosaved content as unsaved changes"));
  discard->setToolTip(tr("Delete the autosaved copy"));
  original->setToolTip(tr("Leave the autosaved copy where it is and continue without it"));
  box.setDefaultButton(recover);
  box.setEscapeButton(original);
  box.exec();
  if (box.clickedButton() == recover) return RecoveryChoice::Recover;
  if (box.clickedButton() == discard) return RecoveryChoice::Discard;
  return RecoveryChoice::OpenOriginal;
}

}  // namespace metrofit
