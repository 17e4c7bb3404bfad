#pragma once
// The editing state of a setup model (core/setup/model.h) behind the relation-graph editor: a
// model VALUE, its own QUndoStack and the operations the editor offers. Every operation pushes one
// undo command that holds the model before and after (models are small: the paper's has 66 nodes
// and 88 arcs), so undo / redo restore the exact value. Nothing here needs a window: tests drive
// it directly.
//
// Edits may leave the model invalid (an arc to a node that does not exist, a cycle, lower >=
// upper): that is how a model is built. issues() lists the problems (core checkModel) for the
// graph to highlight; isValid() says whether the model may be used and saved.
#include <QObject>
#include <QString>
#include <optional>
#include <vector>

#include "core/setup/model.h"

class QUndoStack;

namespace metrofit {

/// The level of a node of the relation graph (paper: M, W, T, F, D).
enum class SetupLevel { Machine, Wks, Tool, Feature, Dimension };

class SetupModelEditor : public QObject {
  Q_OBJECT
 public:
  explicit SetupModelEditor(QObject* parent = nullptr);
  ~SetupModelEditor() override;

  const setup::Model& model() const { return model_; }
  QUndoStack* undoStack() const { return undoStack_; }
  /// Replaces the model (a load, not an edit): clears the undo stack and marks it clean.
  void setModel(const setup::Model& model);
  /// True when the model differs from the last setModel / markSaved.
  bool isModified() const;
  /// The current state is what is on disk now.
  void markSaved();
  /// Goes back to the model on disk (Revert) as one undo step, so Ctrl+Z brings the edits back; the
  /// state after it is the saved one (not modified). False (nothing pushed) when the model is `saved`.
  bool revertTo(const setup::Model& saved, const QString& text);
  /// Replaces the model by `model` as one undo step (e.g. recovered autosaved edits); the result is
  /// modified. False (nothing pushed) when the model is `model` already.
  bool replaceModel(const setup::Model& model, const QString& text);
  /// True when both models have the same content (modelToJson; the source is not compared).
  static bool sameModel(const setup::Model& a, const setup::Model& b);
  /// Reads the JSON form of setup::modelToJson WITHOUT validating it, so an edited model with
  /// problems (how a model is built) can be stored and read back (autosave). Throws
  /// nlohmann::json::exception on a wrong type and std::invalid_argument on an unknown kind.
  static setup::Model modelFromEditJson(const nlohmann::json& json, const std::string& source);

  /// Problems of the current model (checkModel), cached.
  const std::vector<setup::ModelIssue>& issues() const { return issues_; }
  bool isValid() const { return issues_.empty(); }

  /// Level of a node id, or nullopt when the model has no node of that id.
  std::optional<SetupLevel> levelOf(const QString& id) const;
  bool hasNode(const QString& id) const { return levelOf(id).has_value(); }
  /// A free id with this prefix ("W" -> "W9" when W1..W8 exist).
  QString freeId(const QString& prefix) const;

  // ---- edits (each one undo step; false and nothing pushed when the edit is not possible) ----
  /// Adds a node of a level; false when the id is empty or already used.
  bool addNode(SetupLevel level, const QString& id);
  /// Removes a node and every arc that touches it.
  bool removeNode(const QString& id);
  /// Renames a node (its arcs follow); false when the new id is empty or used.
  bool renameNode(const QString& id, const QString& newId);
  /// Changes the level of a setup datum (machine / wks / tool) only.
  bool setSetupKind(const QString& id, SetupLevel level);
  /// Adds an arc (weight +1 or -1; the end points need not exist yet). False for a duplicate.
  bool addArc(const QString& from, const QString& to, int weight);
  bool removeArc(int index);
  bool setArcWeight(int index, int weight);
  /// Tolerance of dimension `index`: nominal (nullopt = none), lower and upper limits (mm).
  bool setTolerance(int index, std::optional<double> nominal, double lower, double upper);
  /// The report mapping of dimension `index`: its label, what it is called in the CMM report
  /// ("oriball:Diameter", "LOC1:D", a DMIS label; core/setup/report.h); "" = the dimension's id.
  bool setLabel(int index, const QString& label);
  /// Index of the arc from -> to, or -1.
  int arcIndex(const QString& from, const QString& to) const;

 signals:
  /// The model changed (edit, undo, redo, setModel).
  void modelChanged();

 private:
  friend class SetupModelCommand;
  void push(const setup::Model& after, const QString& text);
  void apply(const setup::Model& model);

  setup::Model model_;
  std::vector<setup::ModelIssue> issues_;
  QUndoStack* undoStack_;
};

/// Short name of a level ("M", "W", "T", "F", "D") and its title ("Work offsets (W)", ...).
QString setupLevelLetter(SetupLevel level);
QString setupLevelTitle(SetupLevel level);

}  // namespace metrofit
