#include "widgets/document/projectdocument.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QStringList>
#include <QTimer>
#include <QUndoStack>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/project/datasets.h"
#include "core/project/stored_results.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {
namespace {

std::string toStd(const QString& s) {
  return s.toStdString();
}
QString fromStd(const std::string& s) {
  return QString::fromStdString(s);
}
std::string fileNameToStd(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

QString commandText(const ProjectField& field) {
  switch (field.kind) {
    case ProjectField::Kind::Name:
      return ProjectDocument::tr("Rename project");
    case ProjectField::Kind::Description:
      return ProjectDocument::tr("Edit project description");
    case ProjectField::Kind::StudyNotes:
      return ProjectDocument::tr("Edit notes of %1").arg(studyTitle(field.study));
  }
  return {};
}

constexpr int kDiskCheckDelayMs = 200;

/// The tokens of a JSON pointer relative to a study (throws json::parse_error when malformed).
std::vector<std::string> pointerTokens(const QString& key) {
  nlohmann::json::json_pointer pointer(toStd(key));
  std::vector<std::string> tokens;
  while (!pointer.empty()) {
    tokens.insert(tokens.begin(), pointer.back());
    pointer.pop_back();
  }
  return tokens;
}

/// The study's JSON with `value` set at `tokens` (null removes the member).
std::optional<nlohmann::json> withValue(const std::optional<nlohmann::json>& study,
                                        const std::vector<std::string>& tokens, const nlohmann::json& value) {
  if (tokens.empty()) {
    if (value.is_null()) return std::nullopt;
    return value;
  }
  nlohmann::json root = study.value_or(nlohmann::json::object());
  nlohmann::json* node = &root;
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
    if (!node->is_object()) *node = nlohmann::json::object();
    node = &(*node)[tokens[i]];
  }
  if (!node->is_object()) *node = nlohmann::json::object();
  if (value.is_null()) {
    node->erase(tokens.back());
  } else {
    (*node)[tokens.back()] = value;
  }
  return root;
}

/// Whether the member `key` of an object that is the member `parentKey` names a dataset: "dataset",
/// "model", a key ending in "_dataset" (the kinematics study's from_spc x_dataset / y_dataset) or a
/// member of "planes" (its circular tests per plane).
bool namesDataset(const std::string& parentKey, const std::string& key) {
  const std::string suffix = "_dataset";
  return key == "dataset" || key == "model" || parentKey == "planes" ||
         (key.size() > suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0);
}

/// Calls `visit(member, path)` for every string member of `node` that names a dataset (namesDataset, at
/// any depth).
template <typename Json, typename Visit>
void forEachDatasetMember(Json& node, const std::string& path, const Visit& visit,
                          const std::string& nodeKey = {}) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string child = path + "." + it.key();
      if (namesDataset(nodeKey, it.key()) && it.value().is_string()) {
        visit(it.value(), child);
      } else {
        forEachDatasetMember(it.value(), child, visit, it.key());
      }
    }
  } else if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      forEachDatasetMember(node[i], path + "[" + std::to_string(i) + "]", visit);
  }
}

/// Removes the members naming `id` (namesDataset, at any depth).
void eraseDatasetMembers(nlohmann::json& node, const std::string& id, const std::string& nodeKey = {}) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end();) {
      if (namesDataset(nodeKey, it.key()) && it->is_string() && it->get<std::string>() == id) {
        it = node.erase(it);
      } else {
        eraseDatasetMembers(*it, id, it.key());
        ++it;
      }
    }
  } else if (node.is_array()) {
    for (auto& value : node) eraseDatasetMembers(value, id);
  }
}

}  // namespace

// ---- ChangeProjectValue ----

ChangeProjectValue::ChangeProjectValue(ProjectDocument* document, const ProjectField& field,
                                       const QString& value, QUndoCommand* parent)
    : QUndoCommand(commandText(field), parent),
      document_(document),
      field_(field),
      oldValue_(document->rawValue(field)),
      createdStudy_(field.kind == ProjectField::Kind::StudyNotes && !document->hasStudy(field.study)),
      newValue_(value),
      sequence_(document->editSequence()) {}

void ChangeProjectValue::undo() {
  document_->applyValue(field_, oldValue_, createdStudy_);
}

void ChangeProjectValue::redo() {
  document_->applyValue(field_, newValue_);
}

bool ChangeProjectValue::mergeWith(const QUndoCommand* other) {
  const auto* o = static_cast<const ChangeProjectValue*>(other);  // same id() guarantees the type
  if (o->document_ != document_ || !(o->field_ == field_) || o->sequence_ != sequence_) return false;
  newValue_ = o->newValue_;
  // Typing back to where the sequence started leaves nothing to undo.
  setObsolete(!createdStudy_ && oldValue_.has_value() && *oldValue_ == newValue_);
  return true;
}

// ---- ChangeStudyValue ----

ChangeStudyValue::ChangeStudyValue(ProjectDocument* document, const QString& study, const QString& key,
                                   const nlohmann::json& value, const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      document_(document),
      study_(study),
      key_(key),
      before_(document->rawStudy(study)),
      after_(withValue(before_, pointerTokens(key), value)),
      sequence_(document->editSequence()) {}

void ChangeStudyValue::undo() {
  document_->applyStudy(study_, key_, before_);
}

void ChangeStudyValue::redo() {
  document_->applyStudy(study_, key_, after_);
}

bool ChangeStudyValue::mergeWith(const QUndoCommand* other) {
  const auto* o = static_cast<const ChangeStudyValue*>(other);  // same id() guarantees the type
  if (o->document_ != document_ || o->study_ != study_ || o->key_ != key_ || o->sequence_ != sequence_)
    return false;
  after_ = o->after_;
  setObsolete(before_ == after_);
  return true;
}

// ---- ReplaceProject ----

ReplaceProject::ReplaceProject(ProjectDocument* document, Project project, const QString& text,
                               QUndoCommand* parent)
    : QUndoCommand(text, parent),
      document_(document),
      before_(document->project()),
      after_(std::move(project)) {}

void ReplaceProject::undo() {
  document_->applyProject(before_);
}

void ReplaceProject::redo() {
  document_->applyProject(after_);
}

// ---- ChangeDatasets ----

ChangeDatasets::ChangeDatasets(ProjectDocument* document, std::vector<DatasetRef> datasets,
                               nlohmann::json studies, const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      document_(document),
      datasetsBefore_(document->project().datasets),
      datasetsAfter_(std::move(datasets)),
      studiesBefore_(document->project().studies),
      studiesAfter_(std::move(studies)) {}

void ChangeDatasets::undo() {
  document_->applyDatasets(datasetsBefore_, studiesBefore_);
}

void ChangeDatasets::redo() {
  document_->applyDatasets(datasetsAfter_, studiesAfter_);
}

// ---- ProjectDocument ----

ProjectDocument::ProjectDocument(QObject* parent)
    : QObject(parent),
      undoStack_(new QUndoStack(this)),
      watcher_(new QFileSystemWatcher(this)),
      diskCheck_(new QTimer(this)) {
  diskCheck_->setSingleShot(true);
  diskCheck_->setInterval(kDiskCheckDelayMs);
  connect(undoStack_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
  connect(watcher_, &QFileSystemWatcher::fileChanged, this, &ProjectDocument::onWatchedFileChanged);
  connect(diskCheck_, &QTimer::timeout, this, &ProjectDocument::checkFileOnDisk);
}

ProjectDocument::~ProjectDocument() = default;

QString ProjectDocument::displayName() const {
  const QString name = fromStd(project_.name).trimmed();
  // A new project's name is core's default "Untitled" (Project::name): shown in the UI language.
  return name.isEmpty() || name == fromStd(Project{}.name) ? tr("Untitled") : name;
}

bool ProjectDocument::isModified() const {
  return !undoStack_->isClean();
}

bool ProjectDocument::hasStudy(const QString& study) const {
  return project_.studies.contains(toStd(study));
}

std::optional<QString> ProjectDocument::rawValue(const ProjectField& field) const {
  switch (field.kind) {
    case ProjectField::Kind::Name:
      return fromStd(project_.name);
    case ProjectField::Kind::Description:
      return fromStd(project_.description);
    case ProjectField::Kind::StudyNotes: {
      const auto s = project_.studies.find(toStd(field.study));
      if (s == project_.studies.end() || !s->is_object()) return std::nullopt;
      const auto n = s->find("notes");
      if (n == s->end() || !n->is_string()) return std::nullopt;
      return fromStd(n->get<std::string>());
    }
  }
  return std::nullopt;
}

QString ProjectDocument::value(const ProjectField& field) const {
  return rawValue(field).value_or(QString());
}

void ProjectDocument::setValue(const ProjectField& field, const QString& value) {
  if (this->value(field) == value) return;
  undoStack_->push(new ChangeProjectValue(this, field, value));
}

void ProjectDocument::applyValue(const ProjectField& field, const std::optional<QString>& value,
                                 bool removeStudy) {
  switch (field.kind) {
    case ProjectField::Kind::Name:
      project_.name = toStd(value.value_or(QString()));
      break;
    case ProjectField::Kind::Description:
      project_.description = toStd(value.value_or(QString()));
      break;
    case ProjectField::Kind::StudyNotes: {
      const std::string key = toStd(field.study);
      nlohmann::json& study = project_.studies[key];
      if (!study.is_object()) study = nlohmann::json::object();
      if (value) {
        study["notes"] = toStd(*value);
      } else {
        study.erase("notes");
        if (removeStudy && study.empty()) project_.studies.erase(key);
      }
      break;
    }
  }
  emit changed();
  emit fieldChanged(field);
}

std::optional<nlohmann::json> ProjectDocument::rawStudy(const QString& study) const {
  const auto s = project_.studies.find(toStd(study));
  if (s == project_.studies.end()) return std::nullopt;
  return *s;
}

nlohmann::json ProjectDocument::studyValue(const QString& study, const QString& key) const {
  const std::vector<std::string> tokens = pointerTokens(key);
  const auto s = project_.studies.find(toStd(study));
  if (s == project_.studies.end()) return nullptr;
  const nlohmann::json* node = &*s;
  for (const std::string& token : tokens) {
    if (!node->is_object()) return nullptr;
    const auto it = node->find(token);
    if (it == node->end()) return nullptr;
    node = &*it;
  }
  return *node;
}

void ProjectDocument::setStudyValue(const QString& study, const QString& key, const nlohmann::json& value,
                                    const QString& undoText) {
  if (studyValue(study, key) == value) return;
  undoStack_->push(new ChangeStudyValue(this, study, key, value, undoText));
}

void ProjectDocument::applyStudy(const QString& study, const QString& key,
                                 const std::optional<nlohmann::json>& json) {
  if (json) {
    project_.studies[toStd(study)] = *json;
  } else {
    project_.studies.erase(toStd(study));
  }
  emit changed();
  emit studyValueChanged(study, key);
}

void ProjectDocument::replaceProject(const Project& project, const QString& undoText) {
  if (project == project_) return;
  ++editSequence_;
  undoStack_->push(new ReplaceProject(this, project, undoText));
  ++editSequence_;
}

void ProjectDocument::applyProject(const Project& project) {
  project_ = project;
  emit changed();
}

DatasetRef ProjectDocument::resolvedDataset(const DatasetRef& dataset) const {
  DatasetRef d = dataset;
  d.path = toStd(datasetPath(dataset));
  for (std::string& file : d.paths) {
    DatasetRef one = dataset;
    one.path = file;
    file = toStd(datasetPath(one));
  }
  return d;
}

void ProjectDocument::setStoredResult(const QString& study, const QString& datasetId,
                                      const nlohmann::json& entry) {
  metrofit::setStoredResult(project_, toStd(study), toStd(datasetId), entry);
  setUnsavedResults(true);
}

void ProjectDocument::setUnsavedResults(bool unsaved) {
  if (unsaved == unsavedResults_) return;
  unsavedResults_ = unsaved;
  emit unsavedResultsChanged(unsaved);
}

void ProjectDocument::newProject() {
  ++generation_;
  project_ = Project{};
  setFileName(QString());
  undoStack_->clear();
  setUnsavedResults(false);
  ++editSequence_;
  emit changed();
}

void ProjectDocument::load(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  Project loaded = loadProject(fileNameToStd(absolute));  // throws; nothing changed yet
  ++generation_;
  project_ = std::move(loaded);
  setFileName(absolute);
  undoStack_->clear();
  setUnsavedResults(false);
  ++editSequence_;
  emit changed();
}

void ProjectDocument::save() {
  if (fileName_.isEmpty()) {
    throw FileError(ErrorContext{},
                    toStd(tr("the project has not been saved yet; choose a file name with Save As")));
  }
  saveAs(fileName_);
}

void ProjectDocument::saveAs(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  // Relative dataset paths are relative to the project's folder: saved elsewhere, they are rewritten
  // so that they still name the same files.
  Project toSave = project_;
  const QDir newFolder = QFileInfo(absolute).absoluteDir();
  const QDir oldFolder = QFileInfo(projectPathForDatasets()).absoluteDir();
  for (DatasetRef& d : toSave.datasets) {
    // Every file of a DMIS series too ("paths"; the first is "path").
    for (std::string& file : d.paths) {
      if (QDir::isAbsolutePath(fromStd(file))) continue;
      file = toStd(QDir::fromNativeSeparators(
          newFolder.relativeFilePath(QDir::cleanPath(oldFolder.absoluteFilePath(fromStd(file))))));
    }
    const QString current = fromStd(d.path);
    if (QDir::isAbsolutePath(current)) continue;
    d.path = toStd(QDir::fromNativeSeparators(newFolder.relativeFilePath(datasetPath(d))));
  }
  // Our own write must not look like a change by another program: stop watching while we write.
  if (!fileName_.isEmpty()) watcher_->removePath(fileName_);
  try {
    saveProject(toSave, fileNameToStd(absolute));
  } catch (...) {
    watch(fileName_);
    throw;
  }
  const bool rebased = toSave.datasets != project_.datasets;
  project_ = std::move(toSave);
  setFileName(absolute);
  undoStack_->setClean();
  setUnsavedResults(false);
  ++editSequence_;
  if (rebased) emit changed();
}

QString ProjectDocument::datasetPath(const DatasetRef& dataset) const {
  if (fileName_.isEmpty()) return QDir::current().absoluteFilePath(fromStd(dataset.path));
  return QDir::cleanPath(
      QFile::decodeName(QByteArray::fromStdString(resolveDatasetPath(fileNameToStd(fileName_), dataset))));
}

QString ProjectDocument::projectPathForDatasets() const {
  return fileName_.isEmpty() ? QDir::current().absoluteFilePath(QStringLiteral("untitled.metrofit"))
                             : fileName_;
}

QStringList ProjectDocument::datasetReferences(const QString& id) const {
  QStringList out;
  const std::string key = toStd(id);
  forEachDatasetMember(project_.studies, "studies",
                       [&](const nlohmann::json& value, const std::string& path) {
                         if (value.get<std::string>() == key) out << fromStd(path);
                       });
  return out;
}

std::size_t ProjectDocument::datasetIndex(const QString& id) const {
  for (std::size_t i = 0; i < project_.datasets.size(); ++i)
    if (project_.datasets[i].id == toStd(id)) return i;
  throw ValidationError(ErrorContext{{}, 0, 0, "id"}, toStd(tr("the project has no dataset '%1'").arg(id)));
}

void ProjectDocument::applyDatasets(const std::vector<DatasetRef>& datasets, const nlohmann::json& studies) {
  project_.datasets = datasets;
  project_.studies = studies;
  emit changed();
}

void ProjectDocument::addDataset(const DatasetRef& dataset) {
  if (dataset.id.empty())
    throw ValidationError(ErrorContext{{}, 0, 0, "id"}, toStd(tr("a dataset needs an id")));
  if (project_.dataset(dataset.id) != nullptr)
    throw ValidationError(ErrorContext{{}, 0, 0, "id"},
                          toStd(tr("the project already has a dataset '%1'").arg(fromStd(dataset.id))));
  std::vector<DatasetRef> datasets = project_.datasets;
  datasets.push_back(dataset);
  ++editSequence_;
  undoStack_->push(new ChangeDatasets(this, std::move(datasets), project_.studies,
                                      tr("Import dataset %1").arg(fromStd(dataset.id))));
}

void ProjectDocument::removeDataset(const QString& id) {
  const std::size_t index = datasetIndex(id);
  std::vector<DatasetRef> datasets = project_.datasets;
  datasets.erase(datasets.begin() + static_cast<std::ptrdiff_t>(index));
  nlohmann::json studies = project_.studies;
  eraseDatasetMembers(studies, toStd(id));
  ++editSequence_;
  undoStack_->push(
      new ChangeDatasets(this, std::move(datasets), std::move(studies), tr("Remove dataset %1").arg(id)));
}

void ProjectDocument::renameDataset(const QString& id, const QString& newId) {
  const std::size_t index = datasetIndex(id);
  const QString name = newId.trimmed();
  if (name == id) return;
  if (name.isEmpty()) throw ValidationError(ErrorContext{{}, 0, 0, "id"}, toStd(tr("a dataset needs an id")));
  if (project_.dataset(toStd(name)) != nullptr)
    throw ValidationError(ErrorContext{{}, 0, 0, "id"},
                          toStd(tr("the project already has a dataset '%1'").arg(name)));
  std::vector<DatasetRef> datasets = project_.datasets;
  datasets[index].id = toStd(name);
  nlohmann::json studies = project_.studies;
  const std::string oldKey = toStd(id);
  forEachDatasetMember(studies, "studies", [&](nlohmann::json& value, const std::string&) {
    if (value.get<std::string>() == oldKey) value = toStd(name);
  });
  ++editSequence_;
  undoStack_->push(new ChangeDatasets(this, std::move(datasets), std::move(studies),
                                      tr("Rename dataset %1 to %2").arg(id, name)));
}

void ProjectDocument::relinkDataset(const QString& id, const QString& file) {
  relinkDataset(id, QStringList{file});
}

void ProjectDocument::relinkDataset(const QString& id, const QStringList& files) {
  if (files.isEmpty()) return;
  const std::size_t index = datasetIndex(id);
  DatasetRef moved = project_.datasets[index];
  const QDir folder = QFileInfo(projectPathForDatasets()).absoluteDir();
  const auto stored = [&folder](const QString& file) {
    const QString absolute = QFileInfo(file).absoluteFilePath();
    const QString relative = folder.relativeFilePath(absolute);
    // Another root (Windows drive) cannot be reached relatively: keep the absolute path.
    return toStd(QDir::fromNativeSeparators(QDir::isAbsolutePath(relative) ? absolute : relative));
  };
  moved.path = stored(files.front());
  // Several files: a DMIS series, one file per workpiece, in the order given (summarizeDataset checks
  // that each is DMIS output); one file: that file (a series re-linked to one file is that file).
  moved.paths.clear();
  if (files.size() > 1)
    for (const QString& f : files) moved.paths.push_back(stored(f));
  (void)summarizeDataset(fileNameToStd(projectPathForDatasets()), moved);  // throws; nothing changed yet
  if (moved == project_.datasets[index]) return;
  std::vector<DatasetRef> datasets = project_.datasets;
  datasets[index] = moved;
  ++editSequence_;
  undoStack_->push(
      new ChangeDatasets(this, std::move(datasets), project_.studies, tr("Re-link dataset %1").arg(id)));
}

void ProjectDocument::setFileName(const QString& path) {
  if (!watcher_->files().isEmpty()) watcher_->removePaths(watcher_->files());
  diskCheck_->stop();
  const bool renamed = path != fileName_;
  fileName_ = path;
  watch(path);
  if (renamed) emit fileNameChanged(fileName_);
}

void ProjectDocument::watch(const QString& path) {
  if (path.isEmpty()) return;
  stamp_ = stampOf(path);
  if (QFileInfo::exists(path)) watcher_->addPath(path);
}

ProjectDocument::Stamp ProjectDocument::stampOf(const QString& path) {
  const QFileInfo info(path);
  if (!info.exists()) return {};
  return {info.size(), info.lastModified().toMSecsSinceEpoch()};
}

void ProjectDocument::onWatchedFileChanged(const QString& path) {
  if (path != fileName_) return;
  diskCheck_->start();
}

void ProjectDocument::checkFileOnDisk() {
  if (fileName_.isEmpty()) return;
  // Programs that save atomically replace the file; the watcher then drops it, so watch again.
  if (QFileInfo::exists(fileName_) && !watcher_->files().contains(fileName_)) watcher_->addPath(fileName_);
  const Stamp now = stampOf(fileName_);
  if (now == stamp_) return;
  stamp_ = now;
  emit fileChangedOnDisk(fileName_);
}

}  // namespace metrofit
