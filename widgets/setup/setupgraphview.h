#pragma once
// The relation graph PM = (M, W, T, F, D, R) of a setup model drawn on a QGraphicsScene: one
// column (or row) per level in the order M, W, T, F, D, nodes as labelled boxes coloured by level,
// arcs as curves with an arrow head and their weight (+1 solid, −1 dashed and labelled). Arc end
// points that name no node of the model get a dashed "unknown" node in an extra column. The
// problems of the model (SetupModelEditor::issues()) are drawn on the graph: the nodes and arcs
// they involve get a red outline and the messages as their tooltip.
//
// Layout (readable for the paper's 66 nodes): features keep the model order (grouped by part)
// and are spaced evenly; every other level is sorted by the barycentre of its neighbours'
// positions and placed as close to that barycentre as the minimum spacing allows, so most arcs
// run nearly straight.
//
// Zoom: Ctrl+wheel, zoomIn() / zoomOut() (the editor binds Ctrl+= / Ctrl+-), fitToView().
// Export: SVG (QSvgGenerator) and PNG of the whole graph, written atomically (QSaveFile).
#include <QGraphicsView>
#include <QHash>
#include <QString>

namespace metrofit {
class SetupModelEditor;

class SetupGraphView : public QGraphicsView {
  Q_OBJECT
 public:
  enum class Orientation { Columns, Rows };

  explicit SetupGraphView(SetupModelEditor* editor, QWidget* parent = nullptr);
  ~SetupGraphView() override;

  Orientation orientation() const { return orientation_; }
  void setOrientation(Orientation orientation);

  /// Centre of a node in scene coordinates; (NaN, NaN) for an unknown id.
  QPointF nodePosition(const QString& id) const;
  bool hasNodeItem(const QString& id) const { return nodes_.contains(id); }
  /// True when a problem of the model involves the node (red outline).
  bool isNodeHighlighted(const QString& id) const;
  QString nodeToolTip(const QString& id) const;
  /// True when the node is drawn as an unknown arc end point.
  bool isUnknownNode(const QString& id) const;
  bool isArcHighlighted(int index) const;
  QString arcToolTip(int index) const;
  int arcItemCount() const { return arcs_.size(); }
  /// Text shown on arc `index` ("+1" / "−1").
  QString arcLabel(int index) const;

  /// Selected node id (empty when none) and selected arc index (-1 when none).
  QString selectedNode() const;
  int selectedArc() const;
  void selectNode(const QString& id);
  void selectArc(int index);

  double zoomFactor() const;
  void zoomIn();
  void zoomOut();
  void fitToView();

  /// Writes the whole graph as SVG / PNG; false with a readable message in *error on failure.
  bool exportSvg(const QString& path, QString* error = nullptr) const;
  bool exportPng(const QString& path, QString* error = nullptr, double scale = 2.0) const;

 signals:
  /// A node or an arc was double-clicked (the editor opens its edit dialog).
  void nodeActivated(const QString& id);
  void arcActivated(int index);
  void selectionChanged();

 protected:
  void wheelEvent(QWheelEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void rebuild();
  void scaleBy(double factor);

  SetupModelEditor* editor_;
  Orientation orientation_ = Orientation::Columns;
  QHash<QString, QGraphicsItem*> nodes_;
  QList<QGraphicsItem*> arcs_;  ///< by arc index
  bool autoFit_ = true;         ///< fit on resize until the user zooms
};

}  // namespace metrofit
