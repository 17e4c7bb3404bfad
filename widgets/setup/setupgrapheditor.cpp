#include "widgets/setup/setupgrapheditor.h"

#include "widgets/common/usernumber.h"

#include <QAction>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStyledItemDelegate>
#include <QTableWidget>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "widgets/common/tablecopy.h"
#include "widgets/setup/setupgraphview.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {

namespace {
enum Column { ColId, ColNominal, ColLower, ColUpper, ColReport, ColumnCount };

/// The "Report feature" cell: an editable combo box of the report's labels (typing another is allowed:
/// a label the report lacks is named by the Setup page's message when it reads the report).
class ReportFeatureDelegate : public QStyledItemDelegate {
 public:
  ReportFeatureDelegate(const QStringList* labels, QObject* parent)
      : QStyledItemDelegate(parent), labels_(labels) {}
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override {
    auto* combo = new QComboBox(parent);
    combo->setEditable(true);
    combo->addItem(QString());
    combo->addItems(*labels_);
    combo->setInsertPolicy(QComboBox::NoInsert);
    return combo;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    static_cast<QComboBox*>(editor)->setCurrentText(index.data(Qt::EditRole).toString());
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override {
    model->setData(index, static_cast<QComboBox*>(editor)->currentText().trimmed(), Qt::EditRole);
  }

 private:
  const QStringList* labels_;
};

QString formatMm(double v) {
  return QLocale().toString(v, 'f', 3);
}
}  // namespace

SetupGraphEditor::SetupGraphEditor(SetupModelEditor* editor, QWidget* parent)
    : QWidget(parent),
      editor_(editor),
      view_(new SetupGraphView(editor, this)),
      table_(new QTableWidget(this)),
      problems_(new QLabel(this)) {
  setObjectName(QStringLiteral("setupGraphEditor"));
  enableTableCopy(table_);
  auto* toolbar = new QToolBar(this);
  toolbar_ = toolbar;
  toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  toolbar->setIconSize(QSize(16, 16));

  auto add = [&](const QString& text, const QString& tip, auto slot, const QKeySequence& key = {}) {
    QAction* a = toolbar->addAction(text);
    a->setToolTip(key.isEmpty() ? tip
                                : tip + QStringLiteral(" (") + key.toString(QKeySequence::NativeText) + ')');
    if (!key.isEmpty()) {
      a->setShortcut(key);
      a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
      addAction(a);
    }
    connect(a, &QAction::triggered, this, slot);
    return a;
  };
  add(tr("Add node…"), tr("Add a machine point, work offset, tool, feature or dimension"),
      [this] { addNodeDialog(); });
  add(tr("Add arc…"), tr("Add an arc with weight +1 or −1"), [this] { addArcDialog(); });
  edit_ =
      add(tr("Edit…"), tr("Rename the selected node or change its kind; flip the weight of the selected arc"),
          [this] { editSelection(); });
  remove_ = add(
      tr("Remove"), tr("Remove the selected node (with its arcs) or arc"), [this] { removeSelection(); },
      QKeySequence(QKeySequence::Delete));
  toolbar->addSeparator();
  undo_ = editor_->undoStack()->createUndoAction(this, tr("Undo"));
  redo_ = editor_->undoStack()->createRedoAction(this, tr("Redo"));
  undo_->setToolTip(tr("Undo the last edit of the graph (Ctrl+Z while the graph has the focus)"));
  redo_->setToolTip(tr("Redo (Ctrl+Shift+Z while the graph has the focus)"));
  toolbar->addAction(undo_);
  toolbar->addAction(redo_);
  toolbar->addSeparator();
  // Zoom as "+" / "−" on the tool bar (the names stay the actions' text and tooltip): with the
  // page's Revert / Save model the bar then fits 1280 px in German and Polish too.
  add(
      tr("Zoom in"), tr("Zoom in (Ctrl+wheel)"), [this] { view_->zoomIn(); },
      QKeySequence(Qt::CTRL | Qt::Key_Equal))
      ->setIconText(QStringLiteral(" + "));
  add(
      tr("Zoom out"), tr("Zoom out (Ctrl+wheel)"), [this] { view_->zoomOut(); },
      QKeySequence(Qt::CTRL | Qt::Key_Minus))
      ->setIconText(QStringLiteral(" − "));
  add(
      tr("Fit"), tr("Fit the whole graph into the view"), [this] { view_->fitToView(); },
      QKeySequence(Qt::CTRL | Qt::Key_0));
  QAction* rows = toolbar->addAction(tr("Rows"));
  rows->setCheckable(true);
  rows->setToolTip(tr("Levels in rows instead of columns"));
  connect(rows, &QAction::toggled, this, [this](bool on) {
    view_->setOrientation(on ? SetupGraphView::Orientation::Rows : SetupGraphView::Orientation::Columns);
  });
  toolbar->addSeparator();
  // One "Export" button with the SVG and PNG exports in its menu.
  auto* exportMenu = new QMenu(this);
  QAction* svg = exportMenu->addAction(tr("Export SVG…"), this, [this] { exportDialog(true); });
  svg->setToolTip(tr("Save the graph as an SVG drawing"));
  QAction* png = exportMenu->addAction(tr("Export PNG…"), this, [this] { exportDialog(false); });
  png->setToolTip(tr("Save the graph as a PNG image"));
  exportMenu->setToolTipsVisible(true);
  auto* exportButton = new QToolButton(this);
  exportButton->setObjectName(QStringLiteral("setupGraphExport"));
  exportButton->setText(tr("Export"));
  exportButton->setToolTip(tr("Save the graph as an SVG drawing or a PNG image"));
  exportButton->setMenu(exportMenu);
  exportButton->setPopupMode(QToolButton::InstantPopup);
  toolbar->addWidget(exportButton);
  // Ctrl+= is also reached as Ctrl++ on many keyboards.
  auto* zoomPlus = new QAction(this);
  zoomPlus->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Plus));
  zoomPlus->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  connect(zoomPlus, &QAction::triggered, this, [this] { view_->zoomIn(); });
  addAction(zoomPlus);

  table_->setObjectName(QStringLiteral("setupDimensionTable"));
  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels(
      {tr("Dimension"), tr("Nominal\n(mm)"), tr("Lower\n(mm)"), tr("Upper\n(mm)"), tr("Report\nfeature")});
  table_->horizontalHeaderItem(ColReport)->setToolTip(
      tr("What the CMM report calls the dimension (feature:value, a DMIS label); empty: its id"));
  table_->setItemDelegateForColumn(ColReport, new ReportFeatureDelegate(&reportFeatures_, this));
  table_->horizontalHeaderItem(ColLower)->setToolTip(tr("Lower tolerance limit relative to the nominal, mm"));
  table_->horizontalHeaderItem(ColUpper)->setToolTip(tr("Upper tolerance limit relative to the nominal, mm"));
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setAlternatingRowColors(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectItems);
  table_->setMinimumWidth(280);
  connect(table_, &QTableWidget::itemChanged, this, &SetupGraphEditor::onCellChanged);
  connect(table_, &QTableWidget::currentCellChanged, this, [this](int row) {
    if (row >= 0 && row < static_cast<int>(editor_->model().dimensions.size()))
      view_->selectNode(
          QString::fromStdString(editor_->model().dimensions[static_cast<std::size_t>(row)].id));
  });

  problems_->setObjectName(QStringLiteral("setupModelProblems"));
  problems_->setWordWrap(true);
  problems_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  problems_->setStyleSheet(QStringLiteral("color: #b01818;"));

  auto* left = new QWidget(this);
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  leftLayout->addWidget(view_, 1);
  leftLayout->addWidget(problems_);
  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->setObjectName(QStringLiteral("setupGraphSplitter"));
  splitter->addWidget(left);
  splitter->addWidget(table_);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 1);
  splitter->setChildrenCollapsible(false);
  splitter->setSizes({900, 300});

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(toolbar);
  layout->addWidget(splitter, 1);

  view_->installEventFilter(this);
  table_->installEventFilter(this);
  connect(editor_, &SetupModelEditor::modelChanged, this, &SetupGraphEditor::refresh);
  connect(view_, &SetupGraphView::selectionChanged, this, &SetupGraphEditor::updateActions);
  connect(view_, &SetupGraphView::nodeActivated, this, &SetupGraphEditor::editNodeDialog);
  connect(view_, &SetupGraphView::arcActivated, this, [this](int index) {
    if (index >= 0 && index < static_cast<int>(editor_->model().arcs.size()))
      editor_->setArcWeight(index,
                            editor_->model().arcs[static_cast<std::size_t>(index)].weight > 0 ? -1 : 1);
  });
  refresh();
}

QString SetupGraphEditor::problemsText() const {
  return problems_->text();
}

void SetupGraphEditor::refresh() {
  fillTable();
  const auto& issues = editor_->issues();
  if (issues.empty()) {
    problems_->clear();
    problems_->hide();
  } else {
    QStringList lines;
    const std::size_t shown = std::min<std::size_t>(issues.size(), 4);
    for (std::size_t i = 0; i < shown; ++i)
      lines << QString::fromStdString(issues[i].field) + QStringLiteral(": ") +
                   QString::fromStdString(issues[i].message);
    if (issues.size() > shown)
      lines << tr("… and %n more problem(s)", nullptr, static_cast<int>(issues.size() - shown));
    problems_->setText(
        tr("The model has %n problem(s) (outlined in red):", nullptr, static_cast<int>(issues.size())) +
        QLatin1Char('\n') + lines.join(QLatin1Char('\n')));
    problems_->show();
  }
  updateActions();
}

void SetupGraphEditor::fillTable() {
  filling_ = true;
  const QSignalBlocker blocker(table_);
  const auto& dims = editor_->model().dimensions;
  table_->setRowCount(static_cast<int>(dims.size()));
  for (std::size_t q = 0; q < dims.size(); ++q) {
    const int row = static_cast<int>(q);
    auto* id = new QTableWidgetItem(QString::fromStdString(dims[q].id));
    id->setFlags(id->flags() & ~Qt::ItemIsEditable);
    table_->setItem(row, ColId, id);
    const QString values[] = {dims[q].nominal ? QLocale().toString(*dims[q].nominal, 'f', 3) : QString(),
                              formatMm(dims[q].lower), formatMm(dims[q].upper)};
    for (int c = ColNominal; c <= ColUpper; ++c) {
      auto* item = new QTableWidgetItem(values[c - ColNominal]);
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      if (!(dims[q].lower < dims[q].upper) && c != ColNominal) item->setForeground(QColor(0xb0, 0x18, 0x18));
      table_->setItem(row, c, item);
    }
    auto* report = new QTableWidgetItem(QString::fromStdString(dims[q].label));
    if (!dims[q].label.empty() && !reportFeatures_.isEmpty() &&
        !reportFeatures_.contains(QString::fromStdString(dims[q].label), Qt::CaseInsensitive)) {
      report->setForeground(QColor(0xb0, 0x18, 0x18));
      report->setToolTip(tr("The study's report has no feature “%1”").arg(report->text()));
    }
    table_->setItem(row, ColReport, report);
  }
  // The column is the mapping to a report that names features (a CMM text report, DMIS); a CSV report
  // series names the dimensions by id, so without offered features and labels it stays hidden.
  const bool mapped =
      std::any_of(dims.begin(), dims.end(), [](const setup::Dimension& d) { return !d.label.empty(); });
  table_->setColumnHidden(ColReport, reportFeatures_.isEmpty() && !mapped);
  // With the mapping column the table asks for the room its columns need (up to a third of a 1280 px
  // page), so that the labels are read without scrolling sideways.
  table_->resizeColumnsToContents();
  const int needed = table_->horizontalHeader()->length() + 2 * table_->frameWidth() +
                     table_->verticalScrollBar()->sizeHint().width() + 2;
  table_->setMinimumWidth(std::clamp(needed, 280, 440));
  filling_ = false;
}

void SetupGraphEditor::onCellChanged(QTableWidgetItem* item) {
  if (filling_ || item == nullptr) return;
  const int row = item->row();
  const auto& dims = editor_->model().dimensions;
  if (row < 0 || row >= static_cast<int>(dims.size())) return;
  if (item->column() == ColReport) {
    if (!editor_->setLabel(row, item->text())) fillTable();
    return;
  }
  const setup::Dimension& d = dims[static_cast<std::size_t>(row)];
  std::optional<double> nominal = d.nominal;
  double lower = d.lower, upper = d.upper;
  const std::optional<double> value = parseUserNumber(item->text());
  if (item->column() == ColNominal && item->text().trimmed().isEmpty()) {
    nominal.reset();
  } else if (!value) {
    fillTable();  // not a number: back to the model's value
    return;
  } else if (item->column() == ColNominal) {
    nominal = *value;
  } else if (item->column() == ColLower) {
    lower = *value;
  } else if (item->column() == ColUpper) {
    upper = *value;
  }
  if (!editor_->setTolerance(row, nominal, lower, upper)) fillTable();
}

void SetupGraphEditor::setReportFeatures(const QStringList& labels, const QString& format) {
  reportFeatures_ = labels;
  table_->horizontalHeaderItem(ColReport)->setToolTip(
      format.isEmpty()
          ? tr("What the CMM report calls the dimension (feature:value, a DMIS label); empty: its id")
          : tr("What the %1 calls the dimension (%n feature(s) offered); empty: its id", nullptr,
               static_cast<int>(labels.size()))
                .arg(format));
  fillTable();
}

int SetupGraphEditor::reportColumn() {
  return ColReport;
}

bool SetupGraphEditor::removeSelection() {
  const QString node = view_->selectedNode();
  if (!node.isEmpty()) return editor_->removeNode(node);
  const int arc = view_->selectedArc();
  if (arc >= 0) return editor_->removeArc(arc);
  return false;
}

void SetupGraphEditor::editSelection() {
  const QString node = view_->selectedNode();
  if (!node.isEmpty()) {
    editNodeDialog(node);
    return;
  }
  const int arc = view_->selectedArc();
  if (arc >= 0 && arc < static_cast<int>(editor_->model().arcs.size()))
    editor_->setArcWeight(arc, editor_->model().arcs[static_cast<std::size_t>(arc)].weight > 0 ? -1 : 1);
}

void SetupGraphEditor::updateActions() {
  const bool selected = !view_->selectedNode().isEmpty() || view_->selectedArc() >= 0;
  remove_->setEnabled(selected);
  edit_->setEnabled(selected);
}

bool SetupGraphEditor::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) {
    auto* key = static_cast<QKeyEvent*>(event);
    const bool undo = key->matches(QKeySequence::Undo);
    const bool redo = key->matches(QKeySequence::Redo);
    if (undo || redo) {
      if (event->type() == QEvent::ShortcutOverride) {
        event->accept();  // ours, not the main window's (the project's undo stack)
      } else {
        undo ? editor_->undoStack()->undo() : editor_->undoStack()->redo();
      }
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

void SetupGraphEditor::addNodeDialog() {
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Add node"));
  auto* level = new QComboBox(&dialog);
  for (SetupLevel l :
       {SetupLevel::Wks, SetupLevel::Tool, SetupLevel::Machine, SetupLevel::Feature, SetupLevel::Dimension})
    level->addItem(setupLevelTitle(l), static_cast<int>(l));
  auto* id = new QLineEdit(&dialog);
  auto suggest = [this, level, id] {
    id->setText(editor_->freeId(setupLevelLetter(static_cast<SetupLevel>(level->currentData().toInt()))));
  };
  connect(level, &QComboBox::currentIndexChanged, &dialog, suggest);
  suggest();
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(tr("&Level:"), level);
  form->addRow(tr("&Id:"), id);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return;
  if (!editor_->addNode(static_cast<SetupLevel>(level->currentData().toInt()), id->text())) {
    QMessageBox::warning(this, tr("Add node"),
                         tr("The id \"%1\" is empty or already used by another node.").arg(id->text()));
    return;
  }
  view_->selectNode(id->text().trimmed());
}

void SetupGraphEditor::addArcDialog() {
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Add arc"));
  auto* from = new QComboBox(&dialog);
  auto* to = new QComboBox(&dialog);
  from->setEditable(true);
  to->setEditable(true);
  const setup::Model& m = editor_->model();
  for (const auto& s : m.setup) from->addItem(QString::fromStdString(s.id));
  for (const auto& f : m.features) {
    from->addItem(QString::fromStdString(f.id));
    to->addItem(QString::fromStdString(f.id));
  }
  for (const auto& s : m.setup)
    if (s.kind != setup::DatumKind::Tool) to->addItem(QString::fromStdString(s.id));
  for (const auto& d : m.dimensions) to->addItem(QString::fromStdString(d.id));
  const QString selected = view_->selectedNode();
  if (!selected.isEmpty()) from->setCurrentText(selected);
  auto* weight = new QComboBox(&dialog);
  weight->addItem(tr("+1 (the target moves with the source)"), 1);
  weight->addItem(tr("−1 (the target moves against the source)"), -1);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(tr("&From:"), from);
  form->addRow(tr("&To:"), to);
  form->addRow(tr("&Weight:"), weight);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return;
  if (!editor_->addArc(from->currentText(), to->currentText(), weight->currentData().toInt())) {
    QMessageBox::warning(
        this, tr("Add arc"),
        tr("The arc %1 → %2 exists already or an end is empty.").arg(from->currentText(), to->currentText()));
  }
}

void SetupGraphEditor::editNodeDialog(const QString& nodeId) {
  const std::optional<SetupLevel> level = editor_->levelOf(nodeId);
  if (!level) return;
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Edit %1").arg(nodeId));
  auto* id = new QLineEdit(nodeId, &dialog);
  auto* kind = new QComboBox(&dialog);
  const bool datum = *level == SetupLevel::Machine || *level == SetupLevel::Wks || *level == SetupLevel::Tool;
  for (SetupLevel l : {SetupLevel::Wks, SetupLevel::Tool, SetupLevel::Machine})
    kind->addItem(setupLevelTitle(l), static_cast<int>(l));
  kind->setCurrentIndex(kind->findData(static_cast<int>(*level)));
  kind->setEnabled(datum);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  auto* form = new QFormLayout(&dialog);
  form->addRow(tr("&Id:"), id);
  if (datum) form->addRow(tr("&Kind:"), kind);
  form->addRow(buttons);
  if (dialog.exec() != QDialog::Accepted) return;
  QString current = nodeId;
  const QString wanted = id->text().trimmed();
  if (wanted != nodeId) {
    if (!editor_->renameNode(nodeId, wanted)) {
      QMessageBox::warning(this, tr("Edit node"),
                           tr("The id \"%1\" is empty or already used by another node.").arg(wanted));
      return;
    }
    current = wanted;
  }
  if (datum) editor_->setSetupKind(current, static_cast<SetupLevel>(kind->currentData().toInt()));
}

void SetupGraphEditor::exportDialog(bool svg) {
  const QString name = QString::fromStdString(editor_->model().name).isEmpty()
                           ? QStringLiteral("setup-graph")
                           : QString::fromStdString(editor_->model().name);
  QString path =
      QFileDialog::getSaveFileName(this, svg ? tr("Export graph as SVG") : tr("Export graph as PNG"),
                                   name + (svg ? QStringLiteral(".svg") : QStringLiteral(".png")),
                                   svg ? tr("SVG drawings (*.svg)") : tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  QString error;
  const bool ok = svg ? view_->exportSvg(path, &error) : view_->exportPng(path, &error);
  if (!ok) QMessageBox::critical(this, tr("Cannot export the graph"), error);
}

}  // namespace metrofit
