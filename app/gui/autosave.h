#pragma once
// Autosave and crash recovery. Every few minutes (Preferences, QSettings key
// "autosave/intervalMinutes", default 3, 0 = off), while the document is modified, the project is
// written to a side file: "<project>.metrofit.autosave" next to the project, or for a project that
// was never saved "untitled-<pid>.metrofit.autosave" in QStandardPaths::AppDataLocation/autosave.
// The text is made on the GUI thread (the project JSON is small) and written atomically
// (writeFileAtomic) on a worker thread, so a slow disk never blocks the GUI. Autosaving only reads
// the document: the undo stack and the modified flag stay as they are.
//
// The side file is removed when the document becomes clean (saved, or undone back to the saved
// state, or replaced by New / Open after the user discarded the changes) and on a clean close
// (removeWritten()). When a project is opened and its side file is newer than the project, or at a
// start without a project an untitled side file of a process that is no longer running exists,
// the user is offered to recover it (Recover / Discard / Open original). The recovered content is
// applied on top of the original through the undo stack (ProjectDocument::replaceProject): the
// document is modified and nothing is written over the project until the user saves. The decision
// is a callback, so tests drive it without a dialog.
//
// Unsaved state kept outside the document (the setup page's relation-graph edits: the model is its
// own file with its own undo stack) is registered on the document with AutosaveExtras. While any of
// it is modified it is autosaved too (also when the document itself is clean), as a top-level
// object "unsaved": {key: value} in the side file (loadProject ignores it), and a recovery hands
// each value back to its source after the project is open.
#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QString>
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "widgets/common/backgroundrun.h"

class QTimer;
class QWidget;

namespace metrofit {

class ProjectDocument;
class Project;

/// Unsaved state outside a document that autosave keeps with it (see above). One per document (a
/// child of it, made on first use); sources are removed with their owner.
class AutosaveExtras : public QObject {
  Q_OBJECT
 public:
  struct Source {
    std::function<bool()> isModified;                    ///< unsaved changes to keep
    std::function<nlohmann::json()> save;                ///< the value written to the side file
    std::function<void(const nlohmann::json&)> restore;  ///< a recovered value (throws when unusable)
  };

  /// The extras of a document.
  static AutosaveExtras* of(ProjectDocument* document);

  /// Registers a source under a key of the "unsaved" object (replaces one of the same key).
  void add(const QString& key, QObject* owner, Source source);
  /// Unregisters the sources of an owner (call it from the owner's destructor).
  void remove(QObject* owner);

  bool anyModified() const;
  /// {key: value} of the modified sources (empty object when none).
  nlohmann::json save() const;
  /// Hands each value of {key: value} to its source; returns the messages of those that failed.
  QStringList restore(const nlohmann::json& unsaved);

  /// The owner calls these: its content changed / its modified state changed.
  void notifyChanged() { emit changed(); }
  void notifyModifiedChanged() { emit modifiedChanged(); }

 signals:
  void changed();
  void modifiedChanged();

 private:
  explicit AutosaveExtras(QObject* parent) : QObject(parent) {}
  struct Entry {
    QString key;
    QPointer<QObject> owner;
    Source source;
  };
  std::vector<Entry> entries_;
};

enum class RecoveryChoice {
  Recover,       ///< open the autosaved content (modified, not saved)
  Discard,       ///< delete the autosave file and open the project as saved
  OpenOriginal,  ///< open the project as saved and keep the autosave file for later
};

/// What the recovery question is about.
struct RecoveryOffer {
  QString projectFile;   ///< the project file; empty for a project that was never saved
  QString autosaveFile;  ///< the side file
  QDateTime autosaved;   ///< when the side file was written
  QDateTime saved;       ///< when the project file was written (invalid for an untitled project)
  QString projectName;   ///< the name in the autosaved project
  QStringList unsaved;   ///< keys of the autosaved unsaved state outside the project ("setup_model")
};

class Autosave : public QObject {
  Q_OBJECT
 public:
  static constexpr int kDefaultIntervalMinutes = 3;
  static constexpr int kMaxIntervalMinutes = 120;
  static constexpr const char* kIntervalSettingsKey = "autosave/intervalMinutes";
  static constexpr const char* kSuffix = ".autosave";

  using Decider = std::function<RecoveryChoice(const RecoveryOffer&)>;

  /// Starts the timer with the interval of the settings. The parent widget (when the parent is
  /// one) is the parent of the recovery dialog.
  explicit Autosave(ProjectDocument* document, QObject* parent = nullptr);
  /// Waits for a write in progress.
  ~Autosave() override;

  /// The interval in the settings, minutes (0: autosave is off).
  static int intervalSetting();
  static void setIntervalSetting(int minutes);
  /// The side file of a project file ("<project>.autosave").
  static QString autosaveFileFor(const QString& projectFile);
  /// QStandardPaths::AppDataLocation + "/autosave".
  static QString defaultUntitledFolder();
  /// The recovery dialog (Recover / Discard / Open original; Escape keeps the file: OpenOriginal).
  static RecoveryChoice askUser(QWidget* parent, const RecoveryOffer& offer);

  /// Timer interval in milliseconds; 0 stops the timer (tick() still works).
  void setIntervalMs(int ms);
  int intervalMs() const;
  /// Where the side files of untitled projects go (tests use a temporary folder).
  void setUntitledFolder(const QString& folder) { untitledFolder_ = folder; }
  QString untitledFolder() const { return untitledFolder_; }
  /// The recovery decision (default: askUser with the parent widget).
  void setDecider(Decider decider) { decider_ = std::move(decider); }

  /// The side file for the document as it is now.
  QString autosaveFile() const;
  /// The side file this object wrote last and has not removed yet (empty when none).
  QString writtenFile() const { return writtenFile_; }
  bool isWriting() const { return pending_; }

  /// Starts writing the document to its side file when it is modified and changed since the last
  /// autosave; true when a write was started. A write still in progress is not interrupted (false).
  bool tick();
  /// Waits until a write in progress has finished (and handles its result).
  void waitForWrite();
  /// Removes the side file this object wrote (clean save, clean close, discarded changes).
  void removeWritten();

  /// Opens a project like ProjectDocument::load (throws the same errors; the document is unchanged
  /// then), first offering to recover its side file when that is newer than the project. Returns
  /// the choice, nullopt when nothing was offered.
  std::optional<RecoveryChoice> open(const QString& path);
  /// At a start without a project: offers the newest side file of an untitled project whose
  /// process is no longer running. Returns the choice, nullopt when there was none.
  std::optional<RecoveryChoice> recoverUntitled();
  /// The side file recoverUntitled() would offer (empty when none).
  QString orphanedUntitledFile() const;

 signals:
  /// A side file was written (after the worker finished).
  void written(const QString& file);
  /// Writing or reading a side file failed (the one-line message).
  void failed(const QString& message);

 private:
  void onWriteFinished();
  RecoveryChoice decide(const RecoveryOffer& offer);
  /// The document or an extra has unsaved changes.
  bool anythingModified() const;
  /// Reads a side file: the project and its "unsaved" object (throws like loadProject).
  Project readSideFile(const QString& path, nlohmann::json* unsaved) const;
  /// Hands the recovered "unsaved" object to the extras (failures go to failed()).
  void restoreExtras(const nlohmann::json& unsaved);

  ProjectDocument* document_;
  AutosaveExtras* extras_;
  QTimer* timer_;
  /// The write of the side file (writeFileAtomic) off the GUI thread; result: the error message, empty on
  /// success.
  BackgroundRun<QString>* writer_;
  Decider decider_;
  QString untitledFolder_;
  QString writtenFile_;
  QString pendingFile_;
  bool pending_ = false;
  quint64 generation_ = 0;  ///< counts document changes
  quint64 writtenGeneration_ = 0;
  quint64 pendingGeneration_ = 0;
};

}  // namespace metrofit
