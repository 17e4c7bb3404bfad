#pragma once
// The relation-graph editor: a toolbar (add / edit / remove nodes and arcs, undo / redo, zoom,
// fit, columns or rows, export SVG / PNG), the graph (SetupGraphView) and a side table of the
// dimensions whose nominal and tolerance limits are editable (each cell edit is one undo step),
// with the model's problems listed under the graph. The table's last column, "Report feature", is each
// dimension's report mapping (its label: what the CMM report calls it, core/setup/report.h), chosen
// from the study's report (setReportFeatures) or typed; each change is one undo step. It edits a
// SetupModelEditor: a model value with its own undo stack, so it works (and is tested) without a main window.
//
// Keys while the editor has focus: Ctrl+Z / Ctrl+Shift+Z (its own undo stack), Delete (remove
// the selection), Ctrl+= / Ctrl+- (zoom), Ctrl+0 (fit).
#include <QStringList>
#include <QWidget>

class QAction;
class QToolBar;
class QLabel;
class QTableWidget;
class QTableWidgetItem;

namespace metrofit {
class SetupGraphView;
class SetupModelEditor;

class SetupGraphEditor : public QWidget {
  Q_OBJECT
 public:
  explicit SetupGraphEditor(SetupModelEditor* editor, QWidget* parent = nullptr);

  SetupModelEditor* editor() const { return editor_; }
  SetupGraphView* view() const { return view_; }
  QTableWidget* dimensionTable() const { return table_; }
  /// The editor's tool bar.
  QToolBar* toolBar() const { return toolbar_; }
  /// The problems list shown under the graph (empty text when the model is valid).
  QString problemsText() const;

  /// What the study's CMM report measures, as dimension labels ("oriball:Diameter", "LOC1:D", DMIS
  /// labels), offered in the "Report feature" column; `format` names the report ("OGP step report").
  void setReportFeatures(const QStringList& labels, const QString& format = {});
  const QStringList& reportFeatures() const { return reportFeatures_; }
  /// The column of the dimension table holding the report mapping.
  static int reportColumn();

  /// Removes the selected node or arc (false when nothing is selected).
  bool removeSelection();
  /// Opens the edit dialog of the selection (a node: id and kind; an arc: flips its weight).
  void editSelection();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void refresh();
  void fillTable();
  void onCellChanged(QTableWidgetItem* item);
  void addNodeDialog();
  void addArcDialog();
  void editNodeDialog(const QString& id);
  void exportDialog(bool svg);
  void updateActions();

  SetupModelEditor* editor_;
  SetupGraphView* view_;
  QTableWidget* table_;
  QLabel* problems_;
  QToolBar* toolbar_ = nullptr;
  QAction* undo_ = nullptr;
  QAction* redo_ = nullptr;
  QAction* remove_ = nullptr;
  QAction* edit_ = nullptr;
  bool filling_ = false;
  QStringList reportFeatures_;
};

}  // namespace metrofit
