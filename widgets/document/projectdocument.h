#pragma once
// The project document (STYLE.md §6-8): owns a metrofit::Project, the path it was loaded from or
// saved to, and the QUndoStack every edit goes through. "Modified" means "the undo stack is not
// clean". Views are editors of the document: they read project(), change it only through
// setValue() (which pushes a ChangeProjectValue command) and listen to the signals.
//
// Files are read and written by core (loadProject / saveProject, atomic write-then-rename); their
// metrofit::InputError / FileError exceptions pass through with their one-line messages, and a
// failed load or save leaves the document exactly as it was. A QFileSystemWatcher reports when the
// open file is changed on disk by another program (never for the document's own saves).
#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoCommand>
#include <memory>
#include <optional>
#include <vector>

#include "core/project/project.h"

class QFileSystemWatcher;
class QTimer;
class QUndoStack;

namespace metrofit {

class ProjectDocument;

/// Ids of the document's undo commands (QUndoCommand::id(), used for merging).
enum class UndoCommandId : int {
  ChangeProjectValue = 1,
  ChangeStudyValue = 2,
  ReplaceProject = 3,
  ChangeDatasets = 4,
};

/// A text field of the project that can be edited through the undo stack.
struct ProjectField {
  enum class Kind { Name, Description, StudyNotes };
  Kind kind = Kind::Name;
  QString study;  ///< for StudyNotes: a name from metrofit::study (studies[<study>]["notes"])

  static ProjectField name() { return {Kind::Name, {}}; }
  static ProjectField description() { return {Kind::Description, {}}; }
  static ProjectField studyNotes(const QString& study) { return {Kind::StudyNotes, study}; }

  bool operator==(const ProjectField&) const = default;
};

/// The generic change-value command (Tiled's ChangeValue): sets one project field and restores the
/// previous value on undo. Consecutive commands on the same field within one edit sequence merge
/// into one (typing a name is one undo step); a merge that returns to the original value makes the
/// command obsolete, so the stack drops it.
class ChangeProjectValue : public QUndoCommand {
 public:
  ChangeProjectValue(ProjectDocument* document, const ProjectField& field, const QString& value,
                     QUndoCommand* parent = nullptr);

  void undo() override;
  void redo() override;
  int id() const override { return static_cast<int>(UndoCommandId::ChangeProjectValue); }
  bool mergeWith(const QUndoCommand* other) override;

  const ProjectField& field() const { return field_; }

 private:
  ProjectDocument* document_;
  ProjectField field_;
  std::optional<QString> oldValue_;  ///< nullopt: the field did not exist (study notes)
  bool createdStudy_ = false;        ///< the study object did not exist before
  QString newValue_;
  quint64 sequence_;
};

/// Sets one JSON value inside a study (ProjectDocument::setStudyValue). The command keeps the whole
/// study's JSON before and after the edit, so undo restores it exactly (intermediate objects the
/// edit created disappear again; a study that did not exist is removed). Consecutive commands on
/// the same study and key within one edit sequence merge (typing in a spin box is one undo step); a
/// merge back to the original JSON makes the command obsolete.
class ChangeStudyValue : public QUndoCommand {
 public:
  ChangeStudyValue(ProjectDocument* document, const QString& study, const QString& key,
                   const nlohmann::json& value, const QString& text, QUndoCommand* parent = nullptr);

  void undo() override;
  void redo() override;
  int id() const override { return static_cast<int>(UndoCommandId::ChangeStudyValue); }
  bool mergeWith(const QUndoCommand* other) override;

  const QString& study() const { return study_; }
  const QString& key() const { return key_; }

 private:
  ProjectDocument* document_;
  QString study_;
  QString key_;
  std::optional<nlohmann::json> before_;  ///< nullopt: the study did not exist
  std::optional<nlohmann::json> after_;   ///< nullopt: the study is removed
  quint64 sequence_;
};

/// Replaces the whole project (ProjectDocument::replaceProject: recovering an autosaved copy); undo
/// restores the project as it was before. Never merges.
class ReplaceProject : public QUndoCommand {
 public:
  ReplaceProject(ProjectDocument* document, Project project, const QString& text,
                 QUndoCommand* parent = nullptr);

  void undo() override;
  void redo() override;
  int id() const override { return static_cast<int>(UndoCommandId::ReplaceProject); }

 private:
  ProjectDocument* document_;
  Project before_;
  Project after_;
};

/// Changes the project's datasets (import, remove, rename, re-link) together with the study settings
/// that name them (ProjectDocument::addDataset, removeDataset, renameDataset, relinkDataset): the
/// command keeps the dataset list and the studies before and after, so undo restores both exactly.
/// Never merges.
class ChangeDatasets : public QUndoCommand {
 public:
  ChangeDatasets(ProjectDocument* document, std::vector<DatasetRef> datasets, nlohmann::json studies,
                 const QString& text, QUndoCommand* parent = nullptr);

  void undo() override;
  void redo() override;
  int id() const override { return static_cast<int>(UndoCommandId::ChangeDatasets); }

 private:
  ProjectDocument* document_;
  std::vector<DatasetRef> datasetsBefore_, datasetsAfter_;
  nlohmann::json studiesBefore_, studiesAfter_;
};

class ProjectDocument : public QObject {
  Q_OBJECT
 public:
  explicit ProjectDocument(QObject* parent = nullptr);
  ~ProjectDocument() override;

  const Project& project() const { return project_; }
  /// Absolute path of the project file; empty for a new, never saved project.
  QString fileName() const { return fileName_; }
  /// The project name for titles ("Untitled", translated, when it is empty or core's default name).
  QString displayName() const;
  QUndoStack* undoStack() const { return undoStack_; }
  bool isModified() const;

  /// Current value of a field ("" for absent study notes).
  QString value(const ProjectField& field) const;
  /// Changes a field through the undo stack (nothing happens when the value is unchanged).
  void setValue(const ProjectField& field, const QString& value);
  /// Ends the current edit sequence: the next change does not merge with the previous one
  /// (editors call it when an input field loses focus or editing is finished).
  void endEditSequence() { ++editSequence_; }

  /// A value inside a study's JSON (`studies[<study>]`). `key` is a JSON pointer relative to the
  /// study (RFC 6901: "/tolerance_mm", "/thermal/applied" in the "diagnosis" study; "" is the whole
  /// study); every token names an object member (arrays are read and written as whole values).
  /// Returns null when the study, the member or an object on the way does not exist. Throws
  /// nlohmann::json::parse_error for a malformed pointer (a programming error).
  nlohmann::json studyValue(const QString& study, const QString& key) const;
  /// Sets a value inside a study through the undo stack (one ChangeStudyValue command named
  /// `undoText`). Missing objects on the way (the study itself included) are created; a member that
  /// is not an object on the way is replaced by one. A null `value` removes the member (the whole
  /// study for the key ""). Nothing
  /// happens when studyValue() already equals `value`. Emits changed() and studyValueChanged().
  void setStudyValue(const QString& study, const QString& key, const nlohmann::json& value,
                     const QString& undoText);

  /// Replaces the whole project content through the undo stack (one ReplaceProject command named
  /// `undoText`; the file name stays). Nothing happens when the content is equal. Emits changed().
  void replaceProject(const Project& project, const QString& undoText);

  /// Which project the document holds: a new number for every newProject() and load() (File › New,
  /// Open, reload), the same across save() and saveAs(). A page drops every result, chart and text it
  /// shows when the generation changes, and keeps them when only the file name changed (Save As).
  quint64 generation() const { return generation_; }
  /// The dataset with its path resolved to an absolute one (datasetPath): equal before and after a
  /// Save As to another folder (which rewrites relative paths), so pages compare these to tell "the
  /// same data" from "other data".
  DatasetRef resolvedDataset(const DatasetRef& dataset) const;

  /// Stores a study's result for a dataset in the project (results.<study>.<datasetId>, see
  /// core/project/stored_results.h). Not an edit: no undo step, the document's modified state stays
  /// and changed() is not emitted (results follow edits, they are not edits); the next save writes it.
  /// Until then hasUnsavedResults() is true (unsavedResultsChanged), so that closing, New and Open ask
  /// before the result is lost.
  void setStoredResult(const QString& study, const QString& datasetId, const nlohmann::json& entry);
  /// A result was stored (setStoredResult) since the last load, save or New: quitting now loses it.
  bool hasUnsavedResults() const { return unsavedResults_; }

  /// A new empty project without a file; clears the undo stack.
  void newProject();
  /// Replaces the project with the file's content; clears the undo stack. Throws
  /// metrofit::InputError (FileError, ParseError, ValidationError); the document is unchanged then.
  void load(const QString& path);
  /// Saves to fileName(). Throws FileError (also when there is no file name yet: use saveAs).
  void save();
  /// Saves to a new path and makes it the document's file. Throws FileError; on failure the
  /// document keeps its file name and stays modified.
  void saveAs(const QString& path);

  /// Absolute path of a dataset of the project (resolved against the project's folder; relative to
  /// the working directory when the project has no file yet).
  QString datasetPath(const DatasetRef& dataset) const;
  /// The path dataset paths are relative to (core's `projectPath`): the project file, or for a
  /// project without a file a file in the working directory (as datasetPath resolves them).
  QString projectPathForDatasets() const;

  /// Study settings that name a dataset: every "dataset", "model" or "*_dataset" member and every member
  /// of a "planes" object (at any depth of `studies`) whose value is `id`, as "studies.thermal.dataset",
  /// "studies.kinematics.spc.dataset", "studies.kinematics.from_spc.x_dataset",
  /// "studies.kinematics.planes.yz".
  QStringList datasetReferences(const QString& id) const;
  /// Adds a dataset (checked by core's addDataset, core/project/datasets.h) through the undo stack
  /// ("Import dataset <id>"). ValidationError when the id is empty or already in the project.
  void addDataset(const DatasetRef& dataset);
  /// Removes a dataset and the study settings that name it (datasetReferences: the studies fall back
  /// to their defaults) in one undo step. ValidationError for an unknown id.
  void removeDataset(const QString& id);
  /// Renames a dataset and updates the study settings that name it, in one undo step. ValidationError
  /// (field "id") for an unknown id, an empty new id or one the project already has.
  void renameDataset(const QString& id, const QString& newId);
  /// Points a dataset at another file (a moved file): the file is read as the dataset's kind with its
  /// dialect and mapping first (core's summarizeDataset; InputError naming file, line and field when it
  /// cannot be read, and nothing changes), then stored relative to the project's folder. One undo step.
  void relinkDataset(const QString& id, const QString& file);
  /// The same with several files: a DMIS series (cmm_report or dmis), one file per workpiece, in order.
  void relinkDataset(const QString& id, const QStringList& files);

 signals:
  /// The project content changed (load, new, undo, redo, any edit).
  void changed();
  /// One field changed (after changed()).
  void fieldChanged(const metrofit::ProjectField& field);
  /// A study value changed through setStudyValue, its undo or redo (after changed()).
  void studyValueChanged(const QString& study, const QString& key);
  void fileNameChanged(const QString& fileName);
  void modifiedChanged(bool modified);
  /// hasUnsavedResults() changed (a run stored its result; a save, load or New cleared it).
  void unsavedResultsChanged(bool unsaved);
  /// The open file was changed or removed on disk by another program.
  void fileChangedOnDisk(const QString& fileName);

 private:
  friend class ChangeProjectValue;
  friend class ChangeStudyValue;
  friend class ReplaceProject;
  friend class ChangeDatasets;
  void applyDatasets(const std::vector<DatasetRef>& datasets, const nlohmann::json& studies);
  /// The index of a dataset, or a ValidationError naming the id.
  std::size_t datasetIndex(const QString& id) const;
  void applyProject(const Project& project);
  /// Replaces a study's JSON without the undo stack (nullopt removes the study).
  void applyStudy(const QString& study, const QString& key, const std::optional<nlohmann::json>& json);
  std::optional<nlohmann::json> rawStudy(const QString& study) const;
  /// Applies a value without the undo stack (nullopt removes study notes; removeStudy drops an
  /// emptied study object).
  void applyValue(const ProjectField& field, const std::optional<QString>& value, bool removeStudy = false);
  std::optional<QString> rawValue(const ProjectField& field) const;
  bool hasStudy(const QString& study) const;
  quint64 editSequence() const { return editSequence_; }

  void setFileName(const QString& path);
  void setUnsavedResults(bool unsaved);
  void watch(const QString& path);
  void onWatchedFileChanged(const QString& path);
  void checkFileOnDisk();

  Project project_;
  QString fileName_;
  QUndoStack* undoStack_;
  QFileSystemWatcher* watcher_;
  QTimer* diskCheck_;  ///< coalesces the watcher's bursts of notifications
  quint64 editSequence_ = 0;
  quint64 generation_ = 0;
  bool unsavedResults_ = false;
  /// Size and modification time of the file as the document last wrote or read it.
  struct Stamp {
    qint64 size = -1;
    qint64 mtimeMs = -1;
    bool operator==(const Stamp&) const = default;
  };
  Stamp stamp_;
  static Stamp stampOf(const QString& path);
};

}  // namespace metrofit

Q_DECLARE_METATYPE(metrofit::ProjectField)
