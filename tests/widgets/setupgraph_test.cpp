// Tests of the setup relation-graph editor (widgets/setup) without a main window: undo / redo of
// node, arc and tolerance edits on the editor's own stack, the highlighting of model problems
// (cycle, unknown node) on the graph, the layout (one column per level), the SVG / PNG export, and
// the convergence chart's runs, legend and reference line. Images go to $METROFIT_TEST_OUT.
#include <gtest/gtest.h>

#include <QColor>
#include <QFile>
#include <QImage>
#include <QTableWidget>
#include <QUndoStack>
#include <cmath>
#include <map>
#include <set>

#include "core/setup/model.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/setup/setupconvergenceview.h"
#include "widgets/setup/setupgrapheditor.h"
#include "widgets/setup/setupgraphview.h"
#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {
namespace {

setup::Model paperModel() {
  return setup::readModel((test::sourceDir() / "resources/demo/setup/paper_example.json").string());
}

std::string json(const setup::Model& m) {
  return setup::modelToJson(m).dump();
}

int arcsTouching(const setup::Model& m, const std::string& id) {
  int n = 0;
  for (const auto& a : m.arcs) n += (a.from == id || a.to == id) ? 1 : 0;
  return n;
}

class SetupGraphTest : public ::testing::Test {
 protected:
  void SetUp() override {
    original_ = paperModel();
    editor_.setModel(original_);
  }
  setup::Model original_;
  SetupModelEditor editor_;
};

TEST_F(SetupGraphTest, LoadIsNotAnEdit) {
  EXPECT_EQ(editor_.undoStack()->count(), 0);
  EXPECT_FALSE(editor_.isModified());
  EXPECT_TRUE(editor_.isValid());
  EXPECT_EQ(editor_.model().setup.size(), 10u);
  EXPECT_EQ(editor_.model().dimensions.size(), 28u);
}

TEST_F(SetupGraphTest, AddNodeUndoRedo) {
  ASSERT_TRUE(editor_.addNode(SetupLevel::Wks, QStringLiteral("W9")));
  EXPECT_EQ(editor_.levelOf(QStringLiteral("W9")), SetupLevel::Wks);
  EXPECT_EQ(editor_.model().setup.size(), 11u);
  EXPECT_TRUE(editor_.isModified());
  EXPECT_FALSE(editor_.addNode(SetupLevel::Feature, QStringLiteral("W9"))) << "ids are one namespace";
  EXPECT_FALSE(editor_.addNode(SetupLevel::Feature, QStringLiteral("  "))) << "empty id";
  EXPECT_EQ(editor_.undoStack()->count(), 1);
  editor_.undoStack()->undo();
  EXPECT_FALSE(editor_.hasNode(QStringLiteral("W9")));
  EXPECT_EQ(json(editor_.model()), json(original_));
  EXPECT_FALSE(editor_.isModified());
  editor_.undoStack()->redo();
  EXPECT_TRUE(editor_.hasNode(QStringLiteral("W9")));
  EXPECT_EQ(editor_.freeId(QStringLiteral("W")), QStringLiteral("W10"));
  ASSERT_TRUE(editor_.addNode(SetupLevel::Dimension, QStringLiteral("P5.D1")));
  EXPECT_EQ(editor_.model().dimensions.back().lower, -0.1);
  EXPECT_EQ(editor_.model().dimensions.back().upper, 0.1);
}

TEST_F(SetupGraphTest, RemoveNodeTakesItsArcsAndUndoRestoresThem) {
  const int t5Arcs = arcsTouching(original_, "T5");
  ASSERT_GT(t5Arcs, 0);
  ASSERT_TRUE(editor_.removeNode(QStringLiteral("T5")));
  EXPECT_FALSE(editor_.hasNode(QStringLiteral("T5")));
  EXPECT_EQ(editor_.model().arcs.size(), original_.arcs.size() - static_cast<std::size_t>(t5Arcs));
  EXPECT_EQ(arcsTouching(editor_.model(), "T5"), 0);
  EXPECT_EQ(editor_.undoStack()->undoText(), QStringLiteral("Remove T5"));
  editor_.undoStack()->undo();
  EXPECT_EQ(json(editor_.model()), json(original_)) << "arcs back in their places";
  editor_.undoStack()->redo();
  EXPECT_EQ(arcsTouching(editor_.model(), "T5"), 0);
  EXPECT_FALSE(editor_.removeNode(QStringLiteral("nope")));
}

TEST_F(SetupGraphTest, RenameAndKindEditsCarryTheArcs) {
  const int w1Arcs = arcsTouching(original_, "W1");
  ASSERT_TRUE(editor_.renameNode(QStringLiteral("W1"), QStringLiteral("G54")));
  EXPECT_EQ(arcsTouching(editor_.model(), "G54"), w1Arcs);
  EXPECT_EQ(arcsTouching(editor_.model(), "W1"), 0);
  EXPECT_TRUE(editor_.isValid());
  EXPECT_FALSE(editor_.renameNode(QStringLiteral("G54"), QStringLiteral("T5"))) << "id in use";
  ASSERT_TRUE(editor_.setSetupKind(QStringLiteral("G54"), SetupLevel::Machine));
  EXPECT_EQ(editor_.levelOf(QStringLiteral("G54")), SetupLevel::Machine);
  EXPECT_TRUE(editor_.isValid()) << "machine -> feature is an allowed shortcut";
  EXPECT_EQ(editor_.undoStack()->undoText(), QStringLiteral("Change the kind of G54"));
  editor_.undoStack()->undo();
  editor_.undoStack()->undo();
  EXPECT_EQ(json(editor_.model()), json(original_));
}

TEST_F(SetupGraphTest, ArcEditsUndoRedo) {
  SetupGraphView view(&editor_);
  const int n = static_cast<int>(original_.arcs.size());
  ASSERT_TRUE(editor_.addArc(QStringLiteral("W2"), QStringLiteral("P1.F1"), -1));
  EXPECT_EQ(static_cast<int>(editor_.model().arcs.size()), n + 1);
  EXPECT_EQ(view.arcItemCount(), n + 1);
  EXPECT_EQ(view.arcLabel(n), QStringLiteral("−1"));
  EXPECT_FALSE(editor_.addArc(QStringLiteral("W2"), QStringLiteral("P1.F1"), 1)) << "duplicate";
  EXPECT_FALSE(editor_.addArc(QStringLiteral("W2"), QStringLiteral("P1.F2"), 2)) << "weight must be +-1";
  ASSERT_TRUE(editor_.setArcWeight(n, 1));
  EXPECT_EQ(editor_.model().arcs.back().weight, 1.0);
  EXPECT_EQ(view.arcLabel(n), QStringLiteral("+1"));
  ASSERT_TRUE(editor_.removeArc(0));
  EXPECT_EQ(static_cast<int>(editor_.model().arcs.size()), n);
  EXPECT_EQ(editor_.undoStack()->count(), 3);
  editor_.undoStack()->undo();  // remove
  editor_.undoStack()->undo();  // weight
  EXPECT_EQ(editor_.model().arcs.back().weight, -1.0);
  EXPECT_EQ(view.arcLabel(n), QStringLiteral("−1"));
  editor_.undoStack()->undo();  // add
  EXPECT_EQ(json(editor_.model()), json(original_));
  editor_.undoStack()->redo();
  editor_.undoStack()->redo();
  editor_.undoStack()->redo();
  EXPECT_EQ(static_cast<int>(editor_.model().arcs.size()), n);
  EXPECT_EQ(editor_.model().arcs.back().from, "W2");
}

TEST_F(SetupGraphTest, ToleranceEditsInTheTableAreUndoable) {
  SetupGraphEditor widget(&editor_);
  QTableWidget* table = widget.dimensionTable();
  ASSERT_EQ(table->rowCount(), 28);
  EXPECT_EQ(table->item(1, 0)->text(), QStringLiteral("P1.D2"));
  table->item(1, 2)->setText(QStringLiteral("-0.05"));  // lower limit of P1.D2
  EXPECT_DOUBLE_EQ(editor_.model().dimensions[1].lower, -0.05);
  EXPECT_EQ(editor_.undoStack()->undoText(), QStringLiteral("Edit tolerance of P1.D2"));
  table->item(1, 3)->setText(QStringLiteral("0.07"));
  EXPECT_DOUBLE_EQ(editor_.model().dimensions[1].upper, 0.07);
  table->item(1, 1)->setText(QString());  // no nominal
  EXPECT_FALSE(editor_.model().dimensions[1].nominal.has_value());
  table->item(1, 2)->setText(QStringLiteral("abc"));  // not a number: back to the model's value
  EXPECT_DOUBLE_EQ(editor_.model().dimensions[1].lower, -0.05);
  EXPECT_EQ(table->item(1, 2)->text(), QStringLiteral("-0.050"));
  EXPECT_EQ(editor_.undoStack()->count(), 3);
  editor_.undoStack()->undo();
  EXPECT_DOUBLE_EQ(*editor_.model().dimensions[1].nominal, 25.0);
  editor_.undoStack()->undo();
  editor_.undoStack()->undo();
  EXPECT_DOUBLE_EQ(editor_.model().dimensions[1].lower, -0.08);
  EXPECT_DOUBLE_EQ(editor_.model().dimensions[1].upper, 0.08);
  EXPECT_EQ(table->item(1, 2)->text(), QStringLiteral("-0.080")) << "the table follows undo";
  editor_.undoStack()->redo();
  EXPECT_EQ(table->item(1, 2)->text(), QStringLiteral("-0.050"));
  // lower >= upper is allowed as an edit, and shown as a problem.
  table->item(1, 2)->setText(QStringLiteral("0.09"));
  EXPECT_FALSE(editor_.isValid());
  EXPECT_TRUE(widget.view()->isNodeHighlighted(QStringLiteral("P1.D2")));
  EXPECT_TRUE(widget.problemsText().contains(QStringLiteral("is not below upper limit")))
      << widget.problemsText().toStdString();
}

TEST_F(SetupGraphTest, CycleIsHighlightedOnTheGraph) {
  SetupGraphView view(&editor_);
  EXPECT_FALSE(view.isNodeHighlighted(QStringLiteral("P1.F1")));
  ASSERT_TRUE(editor_.addArc(QStringLiteral("P1.D1"), QStringLiteral("P1.F1"), 1));
  const int arc = static_cast<int>(editor_.model().arcs.size()) - 1;
  ASSERT_FALSE(editor_.isValid());
  EXPECT_TRUE(view.isNodeHighlighted(QStringLiteral("P1.F1")));
  EXPECT_TRUE(view.isNodeHighlighted(QStringLiteral("P1.D1")));
  EXPECT_FALSE(view.isNodeHighlighted(QStringLiteral("P2.F1")));
  EXPECT_TRUE(view.isArcHighlighted(arc));
  EXPECT_FALSE(view.isArcHighlighted(0));
  EXPECT_TRUE(view.nodeToolTip(QStringLiteral("P1.F1")).contains(QStringLiteral("closes a cycle")))
      << view.nodeToolTip(QStringLiteral("P1.F1")).toStdString();
  EXPECT_TRUE(view.arcToolTip(arc).contains(QStringLiteral("arcs[%1]").arg(arc)))
      << view.arcToolTip(arc).toStdString();
  editor_.undoStack()->undo();
  EXPECT_TRUE(editor_.isValid());
  EXPECT_FALSE(view.isNodeHighlighted(QStringLiteral("P1.F1")));
}

TEST_F(SetupGraphTest, UnknownNodeIsDrawnAndHighlighted) {
  SetupGraphView view(&editor_);
  ASSERT_TRUE(editor_.addArc(QStringLiteral("W1"), QStringLiteral("P9.F1"), 1));
  const int arc = static_cast<int>(editor_.model().arcs.size()) - 1;
  ASSERT_TRUE(view.hasNodeItem(QStringLiteral("P9.F1")));
  EXPECT_TRUE(view.isUnknownNode(QStringLiteral("P9.F1")));
  EXPECT_TRUE(view.isNodeHighlighted(QStringLiteral("P9.F1")));
  EXPECT_TRUE(view.nodeToolTip(QStringLiteral("P9.F1")).contains(QStringLiteral("not a node of the model")));
  EXPECT_TRUE(view.isArcHighlighted(arc));
  EXPECT_TRUE(view.arcToolTip(arc).contains(QStringLiteral("unknown node 'P9.F1'")))
      << view.arcToolTip(arc).toStdString();
  // The unknown end sits in its own column, right of the dimensions.
  EXPECT_GT(view.nodePosition(QStringLiteral("P9.F1")).x(), view.nodePosition(QStringLiteral("P1.D1")).x());
  // Adding the node resolves it.
  ASSERT_TRUE(editor_.addNode(SetupLevel::Feature, QStringLiteral("P9.F1")));
  EXPECT_FALSE(view.isUnknownNode(QStringLiteral("P9.F1")));
  EXPECT_FALSE(view.isArcHighlighted(arc));
}

TEST_F(SetupGraphTest, EachLevelHasItsOwnColumn) {
  SetupGraphView view(&editor_);
  std::map<SetupLevel, std::set<double>> xs;
  std::map<SetupLevel, std::vector<double>> ys;
  auto collect = [&](const std::string& id, SetupLevel level) {
    const QPointF p = view.nodePosition(QString::fromStdString(id));
    ASSERT_TRUE(std::isfinite(p.x())) << id;
    xs[level].insert(p.x());
    ys[level].push_back(p.y());
  };
  for (const auto& s : original_.setup)
    collect(s.id, s.kind == setup::DatumKind::Tool ? SetupLevel::Tool : SetupLevel::Wks);
  for (const auto& f : original_.features) collect(f.id, SetupLevel::Feature);
  for (const auto& d : original_.dimensions) collect(d.id, SetupLevel::Dimension);
  double previous = -1e9;
  for (SetupLevel level : {SetupLevel::Wks, SetupLevel::Tool, SetupLevel::Feature, SetupLevel::Dimension}) {
    ASSERT_EQ(xs[level].size(), 1u) << setupLevelLetter(level).toStdString() << ": one column per level";
    EXPECT_GT(*xs[level].begin(), previous + 60.0)
        << "columns in the order W, T, F, D with room for the arcs";
    previous = *xs[level].begin();
    std::sort(ys[level].begin(), ys[level].end());
    for (std::size_t i = 1; i < ys[level].size(); ++i)
      EXPECT_GE(ys[level][i] - ys[level][i - 1], 20.0) << "nodes of a column do not overlap";
  }
  // Dimensions sit level with their features (D1 = F1).
  EXPECT_NEAR(view.nodePosition(QStringLiteral("P1.D1")).y(), view.nodePosition(QStringLiteral("P1.F1")).y(),
              1e-9);
  // Rows: one row per level.
  view.setOrientation(SetupGraphView::Orientation::Rows);
  std::set<double> rowY;
  for (const auto& f : original_.features) rowY.insert(view.nodePosition(QString::fromStdString(f.id)).y());
  EXPECT_EQ(rowY.size(), 1u);
  EXPECT_GT(view.nodePosition(QStringLiteral("P1.D1")).y(), *rowY.begin());
}

TEST_F(SetupGraphTest, ExportsSvgAndPng) {
  SetupGraphView view(&editor_);
  view.resize(900, 700);
  test::TempDir dir;
  const QString svg = QString::fromStdString(dir.file("graph.svg"));
  QString error;
  ASSERT_TRUE(view.exportSvg(svg, &error)) << error.toStdString();
  QFile file(svg);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QString text = QString::fromUtf8(file.readAll());
  EXPECT_TRUE(text.startsWith(QStringLiteral("<?xml"))) << text.left(80).toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("<svg")));
  EXPECT_TRUE(text.contains(QStringLiteral("<title>Relation graph of Paper example")));
  for (const char* label : {">W1<", ">T23<", ">P4.F7<", ">P4.D7<", ">Dimensions (D)<", ">−1<"})
    EXPECT_TRUE(text.contains(QString::fromUtf8(label))) << label;
  EXPECT_EQ(test::listFolder(dir.path()), std::vector<std::string>{"graph.svg"}) << "no temporary file left";

  // A problem shows in the PNG as the red outline.
  ASSERT_TRUE(editor_.addArc(QStringLiteral("W1"), QStringLiteral("P9.F1"), 1));
  const QString png = QString::fromStdString(dir.file("graph.png"));
  ASSERT_TRUE(view.exportPng(png, &error)) << error.toStdString();
  QImage image(png);
  ASSERT_FALSE(image.isNull());
  EXPECT_GT(image.width(), 800);
  int red = 0;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) {
      const QColor c = image.pixelColor(x, y);
      red += (c.red() > 190 && c.green() < 80 && c.blue() < 80) ? 1 : 0;
    }
  EXPECT_GT(red, 20);
  image.save(QString::fromStdString((test::outDir() / "setupgraph_export.png").string()));
  EXPECT_FALSE(view.exportSvg(QStringLiteral("/nonexistent-folder/x.svg"), &error));
  EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent-folder/x.svg"))) << error.toStdString();
}

TEST_F(SetupGraphTest, ZoomAndFit) {
  SetupGraphView view(&editor_);
  view.resize(800, 600);
  view.fitToView();
  const double fit = view.zoomFactor();
  view.zoomIn();
  EXPECT_NEAR(view.zoomFactor(), fit * 1.25, 1e-9);
  view.zoomOut();
  view.zoomOut();
  EXPECT_NEAR(view.zoomFactor(), fit / 1.25, 1e-9);
  view.fitToView();
  EXPECT_NEAR(view.zoomFactor(), fit, 1e-9);
}

TEST(SetupConvergenceViewTest, RunsOverlaidWithTheExactReference) {
  SetupConvergenceView view;
  view.resize(900, 500);
  const int a = view.addRun(QStringLiteral("cripso"), 1);
  const int b = view.addRun(QStringLiteral("pso"), 2);
  view.appendPoints(a, {{100, 0.01, 0.05, 0.05}, {200, 0.05, 0.04, 0.46}});
  view.appendPoints(a, {{300, 0.07, 0.03, 0.67}});
  view.appendPoints(b, {{100, 0.02, 0.06, 0.14}});
  setup::SetupScore exact{0.0797, 0.0327, 0.7643};
  view.setExact(exact);
  EXPECT_TRUE(view.hasExact());
  ASSERT_EQ(view.runs().size(), 2u);
  EXPECT_EQ(view.runs()[0].trace.size(), 3u);
  EXPECT_EQ(view.seriesCount(), 2 * 3 + 2);
  const QStringList legend = view.legendLabels();
  EXPECT_TRUE(legend.contains(QStringLiteral("CRIPSO, seed 1"))) << legend.join(',').toStdString();
  EXPECT_TRUE(legend.contains(QStringLiteral("PSO, seed 2")));
  EXPECT_TRUE(legend.contains(QStringLiteral("exact optimum f1 = 0.0797 mm")));
  view.clearRuns();
  EXPECT_EQ(view.seriesCount(), 2);
}

}  // namespace
}  // namespace metrofit
