#include "widgets/setup/setupmodeleditor.h"

#include <QCoreApplication>
#include <QUndoCommand>
#include <QUndoStack>
#include <algorithm>
#include <set>
#include <stdexcept>

namespace metrofit {

/// One edit: the model before and after.
class SetupModelCommand : public QUndoCommand {
 public:
  SetupModelCommand(SetupModelEditor* editor, setup::Model before, setup::Model after, const QString& text)
      : QUndoCommand(text), editor_(editor), before_(std::move(before)), after_(std::move(after)) {}
  void undo() override { editor_->apply(before_); }
  void redo() override { editor_->apply(after_); }

 private:
  SetupModelEditor* editor_;
  setup::Model before_, after_;
};

namespace {

struct EditorText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::SetupModelEditor)
};

std::string str(const QString& s) {
  return s.toStdString();
}

setup::DatumKind kindOf(SetupLevel level) {
  switch (level) {
    case SetupLevel::Machine:
      return setup::DatumKind::Machine;
    case SetupLevel::Tool:
      return setup::DatumKind::Tool;
    default:
      return setup::DatumKind::Wks;
  }
}

}  // namespace

QString setupLevelLetter(SetupLevel level) {
  switch (level) {
    case SetupLevel::Machine:
      return QStringLiteral("M");
    case SetupLevel::Wks:
      return QStringLiteral("W");
    case SetupLevel::Tool:
      return QStringLiteral("T");
    case SetupLevel::Feature:
      return QStringLiteral("F");
    case SetupLevel::Dimension:
      return QStringLiteral("D");
  }
  return {};
}

QString setupLevelTitle(SetupLevel level) {
  switch (level) {
    case SetupLevel::Machine:
      return EditorText::tr("Machine points (M)");
    case SetupLevel::Wks:
      return EditorText::tr("Work offsets (W)");
    case SetupLevel::Tool:
      return EditorText::tr("Tools (T)");
    case SetupLevel::Feature:
      return EditorText::tr("Features (F)");
    case SetupLevel::Dimension:
      return EditorText::tr("Dimensions (D)");
  }
  return {};
}

SetupModelEditor::SetupModelEditor(QObject* parent) : QObject(parent), undoStack_(new QUndoStack(this)) {
  issues_ = setup::checkModel(model_);
}

SetupModelEditor::~SetupModelEditor() {
  // Commands point back at the editor: drop them before the members go (silently: the listeners of
  // the stack may be half destroyed already).
  undoStack_->blockSignals(true);
  undoStack_->clear();
}

void SetupModelEditor::setModel(const setup::Model& model) {
  undoStack_->clear();
  apply(model);
  undoStack_->setClean();
}

bool SetupModelEditor::isModified() const {
  return !undoStack_->isClean();
}

void SetupModelEditor::markSaved() {
  undoStack_->setClean();
}

bool SetupModelEditor::sameModel(const setup::Model& a, const setup::Model& b) {
  return setup::modelToJson(a) == setup::modelToJson(b);
}

bool SetupModelEditor::revertTo(const setup::Model& saved, const QString& text) {
  if (sameModel(model_, saved)) {
    // Nothing to take back (e.g. edits undone by hand): only the file's source may differ.
    model_.source = saved.source;
    undoStack_->setClean();
    return false;
  }
  push(saved, text);
  undoStack_->setClean();
  return true;
}

bool SetupModelEditor::replaceModel(const setup::Model& model, const QString& text) {
  if (sameModel(model_, model)) return false;
  push(model, text);
  return true;
}

setup::Model SetupModelEditor::modelFromEditJson(const nlohmann::json& j, const std::string& source) {
  const auto pair = [](const nlohmann::json& v) {
    return std::pair<double, double>(v.at(0).get<double>(), v.at(1).get<double>());
  };
  setup::Model m;
  m.source = source;
  m.name = j.value("name", std::string());
  m.axis = j.value("axis", std::string("Z"));
  m.stepMm = j.value("step_mm", 0.001);
  if (j.contains("bounds_mm")) m.boundsMm = pair(j.at("bounds_mm"));
  for (const auto& e : j.at("setup")) {
    setup::SetupDatum d;
    d.id = e.at("id").get<std::string>();
    const std::string kind = e.at("kind").get<std::string>();
    if (kind == "machine") {
      d.kind = setup::DatumKind::Machine;
    } else if (kind == "wks") {
      d.kind = setup::DatumKind::Wks;
    } else if (kind == "tool") {
      d.kind = setup::DatumKind::Tool;
    } else {
      throw std::invalid_argument("unknown setup datum kind '" + kind + "'");
    }
    if (e.contains("bounds_mm")) d.boundsMm = pair(e.at("bounds_mm"));
    d.registerNumber = e.value("register", 0);
    m.setup.push_back(std::move(d));
  }
  for (const auto& e : j.at("features")) m.features.push_back({e.at("id").get<std::string>()});
  for (const auto& e : j.at("dimensions")) {
    setup::Dimension d;
    d.id = e.at("id").get<std::string>();
    if (e.contains("nominal")) d.nominal = e.at("nominal").get<double>();
    d.lower = e.at("lower").get<double>();
    d.upper = e.at("upper").get<double>();
    d.label = e.value("label", std::string());
    m.dimensions.push_back(std::move(d));
  }
  for (const auto& e : j.at("arcs")) {
    m.arcs.push_back(
        {e.at("from").get<std::string>(), e.at("to").get<std::string>(), e.at("weight").get<double>()});
  }
  return m;
}

void SetupModelEditor::apply(const setup::Model& model) {
  model_ = model;
  issues_ = setup::checkModel(model_);
  emit modelChanged();
}

void SetupModelEditor::push(const setup::Model& after, const QString& text) {
  undoStack_->push(new SetupModelCommand(this, model_, after, text));
}

std::optional<SetupLevel> SetupModelEditor::levelOf(const QString& qid) const {
  const std::string id = str(qid);
  for (const auto& s : model_.setup) {
    if (s.id != id) continue;
    switch (s.kind) {
      case setup::DatumKind::Machine:
        return SetupLevel::Machine;
      case setup::DatumKind::Wks:
        return SetupLevel::Wks;
      case setup::DatumKind::Tool:
        return SetupLevel::Tool;
    }
  }
  for (const auto& f : model_.features)
    if (f.id == id) return SetupLevel::Feature;
  for (const auto& d : model_.dimensions)
    if (d.id == id) return SetupLevel::Dimension;
  return std::nullopt;
}

QString SetupModelEditor::freeId(const QString& prefix) const {
  for (int n = 1;; ++n) {
    const QString id = prefix + QString::number(n);
    if (!hasNode(id)) return id;
  }
}

bool SetupModelEditor::addNode(SetupLevel level, const QString& qid) {
  const QString trimmed = qid.trimmed();
  if (trimmed.isEmpty() || hasNode(trimmed)) return false;
  setup::Model m = model_;
  const std::string id = str(trimmed);
  switch (level) {
    case SetupLevel::Machine:
    case SetupLevel::Wks:
    case SetupLevel::Tool: {
      setup::SetupDatum d;
      d.id = id;
      d.kind = kindOf(level);
      m.setup.push_back(d);
      break;
    }
    case SetupLevel::Feature:
      m.features.push_back({id});
      break;
    case SetupLevel::Dimension: {
      setup::Dimension d;
      d.id = id;
      d.lower = -0.1;
      d.upper = 0.1;
      m.dimensions.push_back(d);
      break;
    }
  }
  push(m, EditorText::tr("Add %1").arg(trimmed));
  return true;
}

bool SetupModelEditor::removeNode(const QString& qid) {
  if (!hasNode(qid)) return false;
  const std::string id = str(qid);
  setup::Model m = model_;
  std::erase_if(m.setup, [&](const setup::SetupDatum& d) { return d.id == id; });
  std::erase_if(m.features, [&](const setup::Feature& f) { return f.id == id; });
  std::erase_if(m.dimensions, [&](const setup::Dimension& d) { return d.id == id; });
  std::erase_if(m.arcs, [&](const setup::Arc& a) { return a.from == id || a.to == id; });
  push(m, EditorText::tr("Remove %1").arg(qid));
  return true;
}

bool SetupModelEditor::renameNode(const QString& qid, const QString& qnewId) {
  const QString trimmed = qnewId.trimmed();
  if (!hasNode(qid) || trimmed.isEmpty() || trimmed == qid || hasNode(trimmed)) return false;
  const std::string id = str(qid), newId = str(trimmed);
  setup::Model m = model_;
  for (auto& s : m.setup)
    if (s.id == id) s.id = newId;
  for (auto& f : m.features)
    if (f.id == id) f.id = newId;
  for (auto& d : m.dimensions)
    if (d.id == id) d.id = newId;
  for (auto& a : m.arcs) {
    if (a.from == id) a.from = newId;
    if (a.to == id) a.to = newId;
  }
  push(m, EditorText::tr("Rename %1 to %2").arg(qid, trimmed));
  return true;
}

bool SetupModelEditor::setSetupKind(const QString& qid, SetupLevel level) {
  if (level == SetupLevel::Feature || level == SetupLevel::Dimension) return false;
  const std::string id = str(qid);
  setup::Model m = model_;
  for (auto& s : m.setup) {
    if (s.id != id) continue;
    if (s.kind == kindOf(level)) return false;
    s.kind = kindOf(level);
    push(m, EditorText::tr("Change the kind of %1").arg(qid));
    return true;
  }
  return false;
}

int SetupModelEditor::arcIndex(const QString& qfrom, const QString& qto) const {
  const std::string from = str(qfrom), to = str(qto);
  for (std::size_t a = 0; a < model_.arcs.size(); ++a)
    if (model_.arcs[a].from == from && model_.arcs[a].to == to) return static_cast<int>(a);
  return -1;
}

bool SetupModelEditor::addArc(const QString& from, const QString& to, int weight) {
  if (from.trimmed().isEmpty() || to.trimmed().isEmpty() || (weight != 1 && weight != -1)) return false;
  if (arcIndex(from.trimmed(), to.trimmed()) >= 0) return false;
  setup::Model m = model_;
  m.arcs.push_back({str(from.trimmed()), str(to.trimmed()), static_cast<double>(weight)});
  push(m, EditorText::tr("Add arc %1 → %2").arg(from.trimmed(), to.trimmed()));
  return true;
}

bool SetupModelEditor::removeArc(int index) {
  if (index < 0 || index >= static_cast<int>(model_.arcs.size())) return false;
  setup::Model m = model_;
  const setup::Arc arc = m.arcs[static_cast<std::size_t>(index)];
  m.arcs.erase(m.arcs.begin() + index);
  push(m, EditorText::tr("Remove arc %1 → %2")
              .arg(QString::fromStdString(arc.from), QString::fromStdString(arc.to)));
  return true;
}

bool SetupModelEditor::setArcWeight(int index, int weight) {
  if (index < 0 || index >= static_cast<int>(model_.arcs.size()) || (weight != 1 && weight != -1))
    return false;
  setup::Model m = model_;
  setup::Arc& arc = m.arcs[static_cast<std::size_t>(index)];
  if (arc.weight == weight) return false;
  arc.weight = weight;
  push(m, EditorText::tr("Set weight of %1 → %2 to %3")
              .arg(QString::fromStdString(arc.from), QString::fromStdString(arc.to),
                   weight > 0 ? QStringLiteral("+1") : QStringLiteral("−1")));
  return true;
}

bool SetupModelEditor::setTolerance(int index, std::optional<double> nominal, double lower, double upper) {
  if (index < 0 || index >= static_cast<int>(model_.dimensions.size())) return false;
  setup::Model m = model_;
  setup::Dimension& d = m.dimensions[static_cast<std::size_t>(index)];
  if (d.nominal == nominal && d.lower == lower && d.upper == upper) return false;
  d.nominal = nominal;
  d.lower = lower;
  d.upper = upper;
  push(m, EditorText::tr("Edit tolerance of %1").arg(QString::fromStdString(d.id)));
  return true;
}

bool SetupModelEditor::setLabel(int index, const QString& label) {
  if (index < 0 || index >= static_cast<int>(model_.dimensions.size())) return false;
  setup::Model m = model_;
  setup::Dimension& d = m.dimensions[static_cast<std::size_t>(index)];
  const std::string wanted = str(label.trimmed());
  if (d.label == wanted) return false;
  d.label = wanted;
  push(m, wanted.empty() ? EditorText::tr("Clear the report feature of %1").arg(QString::fromStdString(d.id))
                         : EditorText::tr("Map %1 to the report feature %2")
                               .arg(QString::fromStdString(d.id), label.trimmed()));
  return true;
}

}  // namespace metrofit
