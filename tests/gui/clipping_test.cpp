// Nothing is clipped or elided at the default window size (1280 x 800) in English, German and Polish
// (issue 28 item 5, findings F3 and F18 of ../shared/notes/gui-run.md): the demo project is opened,
// each page's study is run once, and every tab of every page is shown in turn. In each view, every
// visible label, button, check box, combo box, tab, group box title, spin box and table is checked
// against the room its text needs:
//  * a label without word wrap is at least as wide as its text; a word-wrapped label as high as the
//    text needs at its width;
//  * a button, a check box, a group box title, a spin box's value and a combo box's current text fit;
//  * the tabs of a tab bar are not elided and need no scroll buttons;
//  * a table needs no sideways scrolling (no column hidden past the right edge), each column is as
//    wide as its header's longest line, and no cell's word is cut (cells may wrap onto a higher row);
//    a table of at most 8 rows and a read-only text of at most 8 lines (a frame) show all of them;
//  * no chart text (title, axis title, tick label, legend entry) is shortened with an ellipsis: Qt
//    Charts elides what does not fit, the scene's text items show it.
// The real 46 h CAIVIAC log (16 sensors) is shown on the thermal trend and hysteresis views too.
// Every failure names the language, the view, the widget and what is cut. A screenshot of each view
// is kept in the test's output folder (test::outDir()).
#include <gtest/gtest.h>

#include <cmath>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QStyleOptionGroupBox>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocument>
#include <QTextEdit>
#include <QToolButton>
#include <QTranslator>
#include <QTreeView>
#include <QUndoStack>
#include <set>
#include <string>
#include <vector>

#include "app/gui/machinedialog.h"
#include "app/gui/mainwindow.h"
#include "app/gui/pageid.h"
#include "app/gui/thermalpage.h"
#include "core/project/report_model.h"
#include "qtapp.h"
#include "testsupport.h"
#include "ui_language.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/importer/importdialog.h"
#include "widgets/setup/reportmodeldialog.h"

namespace metrofit {
namespace {

/// Tables and read-only text boxes with at most this many rows/lines must show all of them.
constexpr int kShortLines = 8;

/// Text as shown: without the mnemonic '&' of buttons and labels.
QString shown(QString text) {
  text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
  text.remove(QLatin1Char('&'));
  text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
  return text;
}

/// Whether w is shown and not wholly scrolled out of sight (a scroll area's own region is covered by
/// its viewport: then the viewport's counts).
bool reallyVisible(const QWidget* w) {
  if (!w->isVisible() || w->width() <= 0 || w->height() <= 0) return false;
  if (const auto* area = qobject_cast<const QAbstractScrollArea*>(w))
    return !area->viewport()->visibleRegion().isEmpty();
  return !w->visibleRegion().isEmpty();
}

std::string name(const QWidget* w) {
  std::string s = w->metaObject()->className();
  if (!w->objectName().isEmpty()) s += " '" + w->objectName().toStdString() + "'";
  return s;
}

/// The cut texts in the visible part of `root`, one line each.
class ClipCheck {
 public:
  std::vector<std::string> failures;

  void check(QWidget* root) {
    for (QWidget* w : root->findChildren<QWidget*>()) {
      if (!reallyVisible(w)) continue;
      if (auto* l = qobject_cast<QLabel*>(w))
        label(l);
      else if (auto* b = qobject_cast<QAbstractButton*>(w))
        button(b);
      else if (auto* c = qobject_cast<QComboBox*>(w))
        combo(c);
      else if (auto* t = qobject_cast<QTabBar*>(w))
        tabBar(t);
      else if (auto* s = qobject_cast<QAbstractSpinBox*>(w))
        spin(s);
      else if (auto* g = qobject_cast<QGroupBox*>(w))
        group(g);
      if (auto* v = qobject_cast<QTableView*>(w)) table(v);
      if (auto* e = qobject_cast<QPlainTextEdit*>(w)) textBox(e, e->verticalScrollBar(), e->toPlainText());
      if (auto* e = qobject_cast<QTextEdit*>(w)) textBox(e, e->verticalScrollBar(), e->toPlainText());
      if (auto* g = qobject_cast<QGraphicsView*>(w)) graphics(g);
    }
  }

 private:
  void fail(const QWidget* w, const std::string& what) { failures.push_back(name(w) + ": " + what); }

  void label(QLabel* l) {
    if (l->text().isEmpty() || !l->pixmap().isNull()) return;
    // Labels a scroll area or a splitter may make narrower on purpose elide nothing: a QLabel cuts.
    if (l->wordWrap()) {
      const int need = l->heightForWidth(l->width());
      if (need > l->height() + 1)
        fail(l, "wrapped text needs " + std::to_string(need) + " px height, has " +
                    std::to_string(l->height()) + ": \"" + shown(l->text()).left(80).toStdString() + "\"");
      // A single word longer than the label is cut even when wrapping.
      if (!Qt::mightBeRichText(l->text())) {
        const QFontMetrics fm(l->font());
        for (const QString& word :
             l->text().split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts))
          if (fm.horizontalAdvance(word) > l->contentsRect().width() + 1)
            fail(l, "word \"" + word.toStdString() + "\" wider than the label");
      }
      return;
    }
    const int need = l->sizeHint().width();
    if (need > l->width() + 1)
      fail(l, "needs " + std::to_string(need) + " px, has " + std::to_string(l->width()) + ": \"" +
                  shown(l->text()).left(80).toStdString() + "\"");
    const int needH = l->sizeHint().height();
    if (needH > l->height() + 1)
      fail(l, "needs " + std::to_string(needH) + " px height, has " + std::to_string(l->height()) + ": \"" +
                  shown(l->text()).left(80).toStdString() + "\"");
  }

  void button(QAbstractButton* b) {
    if (b->text().isEmpty()) return;
    if (qobject_cast<QToolButton*>(b) &&
        static_cast<QToolButton*>(b)->toolButtonStyle() == Qt::ToolButtonIconOnly)
      return;
    // Tab bar scroll arrows and the like have no text; a header section is not a widget.
    const int need = b->minimumSizeHint().width();
    if (need > b->width() + 1)
      fail(b, "needs " + std::to_string(need) + " px, has " + std::to_string(b->width()) + ": \"" +
                  shown(b->text()).toStdString() + "\"");
  }

  void combo(QComboBox* c) {
    if (c->currentText().isEmpty()) return;
    QStyleOptionComboBox opt;
    opt.initFrom(c);
    opt.editable = c->isEditable();
    opt.currentText = c->currentText();
    opt.frame = c->hasFrame();
    const QRect field =
        c->style()->subControlRect(QStyle::CC_ComboBox, &opt, QStyle::SC_ComboBoxEditField, c);
    const int need = c->fontMetrics().horizontalAdvance(c->currentText());
    if (need > field.width() + 1)
      fail(c, "current text needs " + std::to_string(need) + " px, field " + std::to_string(field.width()) +
                  ": \"" + c->currentText().toStdString() + "\"");
  }

  void tabBar(QTabBar* t) {
    for (QToolButton* arrow : t->findChildren<QToolButton*>())
      if (arrow->isVisible()) {
        fail(t, "tabs do not fit: scroll arrows shown (first tab \"" + shown(t->tabText(0)).toStdString() +
                    "\")");
        return;
      }
    for (int i = 0; i < t->count(); ++i) {
      if (!t->isTabVisible(i)) continue;
      const QFontMetrics fm(t->font());
      const int need = fm.horizontalAdvance(shown(t->tabText(i)));
      if (t->tabRect(i).width() < need) fail(t, "tab \"" + shown(t->tabText(i)).toStdString() + "\" elided");
    }
  }

  void spin(QAbstractSpinBox* s) {
    const QLineEdit* edit = s->findChild<QLineEdit*>();
    if (edit == nullptr) return;
    const QString text = s->text();
    const int need = s->fontMetrics().horizontalAdvance(text);
    if (need > edit->width())
      fail(s, "value needs " + std::to_string(need) + " px, field " + std::to_string(edit->width()) + ": \"" +
                  text.toStdString() + "\"");
  }

  void group(QGroupBox* g) {
    if (g->title().isEmpty()) return;
    const int need = g->fontMetrics().horizontalAdvance(shown(g->title())) + (g->isCheckable() ? 20 : 0);
    if (need > g->width())
      fail(g, "title needs " + std::to_string(need) + " px: \"" + shown(g->title()).toStdString() + "\"");
  }

  /// A read-only text box of a few lines (an NC frame, a note) shows all of them.
  void textBox(QAbstractScrollArea* box, const QScrollBar* bar, const QString& text) {
    const auto* plain = qobject_cast<QPlainTextEdit*>(box);
    const auto* rich = qobject_cast<QTextEdit*>(box);
    const bool readOnly = (plain && plain->isReadOnly()) || (rich && rich->isReadOnly());
    if (!readOnly || text.count(QLatin1Char('\n')) >= kShortLines) return;
    if (bar->isVisible() && bar->maximum() > 0)
      fail(box, "a text of " + std::to_string(text.count(QLatin1Char('\n')) + 1) + " lines scrolls: \"" +
                    text.left(60).toStdString() + "\"");
  }

  /// Text a chart (Qt Charts or any QGraphicsScene) shortened with an ellipsis: titles, axis labels,
  /// legend entries.
  void graphics(QGraphicsView* view) {
    if (view->scene() == nullptr) return;
    for (QGraphicsItem* item : view->scene()->items()) {
      if (!item->isVisible()) continue;
      QString text;
      if (auto* t = dynamic_cast<QGraphicsTextItem*>(item))
        text = t->toPlainText();
      else if (auto* t = dynamic_cast<QGraphicsSimpleTextItem*>(item))
        text = t->text();
      if (qEnvironmentVariableIsSet("METROFIT_CLIP_DEBUG") && !text.isEmpty())
        std::fprintf(stderr, "graphics %s: %s\n", name(view).c_str(), text.toUtf8().constData());
      if (text.contains(QChar(0x2026)) || text.endsWith(QStringLiteral("...")))
        fail(view, "chart text elided: \"" + text.toStdString() + "\"");
    }
  }

  void table(QTableView* t) {
    const QAbstractItemModel* m = t->model();
    if (m == nullptr) return;
    // A short table (a machine's axes, a frame's values) shows every row.
    if (m->rowCount() <= kShortLines && t->verticalScrollBar()->isVisible() &&
        t->verticalScrollBar()->maximum() > 0)
      fail(t, "shows " + std::to_string(t->viewport()->height()) + " px of " + std::to_string(m->rowCount()) +
                  " rows (first column \"" + m->headerData(0, Qt::Horizontal).toString().toStdString() +
                  "\")");
    const QHeaderView* h = t->horizontalHeader();
    if (t->horizontalScrollBar()->isVisible() || h->length() > t->viewport()->width() + 1)
      fail(t, "scrolls sideways: columns " + std::to_string(h->length()) + " px, room " +
                  std::to_string(t->viewport()->width()) + " px (first column \"" +
                  m->headerData(0, Qt::Horizontal).toString().toStdString() + "\")");
    const int rows = std::min(m->rowCount(), 200);
    for (int c = 0; c < m->columnCount(); ++c) {
      if (t->isColumnHidden(c)) continue;
      const int width = t->columnWidth(c);
      const QString header = m->headerData(c, Qt::Horizontal).toString();
      if (h->isVisible()) {
        const QFontMetrics hf(h->font());
        for (const QString& line : header.split(QLatin1Char('\n')))
          if (hf.horizontalAdvance(line) > width)
            fail(t, "header \"" + line.toStdString() + "\" wider than its column (" + std::to_string(width) +
                        " px)");
      }
      for (int r = 0; r < rows; ++r) {
        if (t->isRowHidden(r) || t->columnSpan(r, c) > 1) continue;
        const QModelIndex index = m->index(r, c);
        const QString text = index.data(Qt::DisplayRole).toString();
        if (text.isEmpty()) continue;
        QFont font = t->font();
        if (const QVariant f = index.data(Qt::FontRole); f.isValid()) font = f.value<QFont>();
        const QFontMetrics fm(font);
        const int room = width - 6;  // the cell's margins
        bool cut = false;
        for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts))
          if (fm.horizontalAdvance(word) > room) cut = true;
        if (!cut && t->wordWrap()) {
          const QRect box = fm.boundingRect(QRect(0, 0, room, 100000), Qt::TextWordWrap, text);
          cut = box.height() > t->rowHeight(r) + 1;
        } else if (!cut) {
          cut = fm.horizontalAdvance(text) > room;
        }
        if (cut) {
          fail(t, "row " + std::to_string(r) + " column \"" + header.toStdString() + "\" (" +
                      std::to_string(width) + " px) cut: \"" + text.left(60).toStdString() + "\"");
          break;  // one failure per column is enough
        }
      }
    }
  }
};

/// Waits until the page runs nothing (no enabled, shown control with the Escape shortcut: its Cancel).
void waitIdle(QWidget* page, int timeoutMs) {
  const QKeySequence cancel(Qt::Key_Escape);
  QElapsedTimer timer;
  timer.start();
  QTest::qWait(100);
  while (timer.elapsed() < timeoutMs) {
    bool running = false;
    for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
      if (b->shortcut() == cancel && b->isVisible() && b->isEnabled()) running = true;
    if (!running) return;
    QTest::qWait(100);
  }
}

/// Every tab widget of `root` that is shown, outermost first.
std::vector<QTabWidget*> shownTabWidgets(QWidget* root) {
  std::vector<QTabWidget*> out;
  for (QTabWidget* t : root->findChildren<QTabWidget*>())
    if (reallyVisible(t)) out.push_back(t);
  return out;
}

class ClippingTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ClippingTest, NothingIsCutAtTheDefaultWindowSize) {
  const QString language = QString::fromLatin1(GetParam());
  const test::ScopedUiLanguage ui(language);
  ASSERT_TRUE(ui.ok()) << ui.why();
  std::set<std::string> reported;
  std::vector<std::string> failures;
  {
    QTemporaryDir dir;
    MainWindow window;
    QString error;
    ASSERT_TRUE(window.openProject(extractDemoProject(dir.filePath(QStringLiteral("demo"))), &error))
        << error.toStdString();
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    auto* run = window.findChild<QAction*>(QStringLiteral("runStudy"));
    ASSERT_NE(run, nullptr);
    int shot = 0;
    const auto checkView = [&](const std::string& view) {
      QTest::qWait(150);
      ClipCheck check;
      check.check(&window);
      for (const std::string& f : check.failures)
        if (reported.insert(f).second) failures.push_back(language.toStdString() + " " + view + ": " + f);
      window.grab().save(QString::fromStdString(
          (test::outDir() / ("clipping-" + language.toStdString() + "-" + std::to_string(++shot) + ".png"))
              .string()));
    };
    for (int p = 0; p < kPageCount; ++p) {
      const Page page = static_cast<Page>(p);
      window.showPage(page);
      QWidget* widget = window.page(page);
      QTest::qWait(100);
      if (page != Page::Overview) {
        run->trigger();
        waitIdle(widget, 120000);
      }
      const std::string pageName = std::to_string(p);
      checkView("page " + pageName);
      // Every tab of every tab widget of the page (nested ones as they appear).
      std::set<QTabWidget*> done;
      for (bool more = true; more;) {
        more = false;
        for (QTabWidget* tabs : shownTabWidgets(widget)) {
          if (!done.insert(tabs).second) continue;
          more = true;
          for (int i = 0; i < tabs->count(); ++i) {
            if (!tabs->isTabEnabled(i) || !tabs->isTabVisible(i)) continue;
            tabs->setCurrentIndex(i);
            checkView("page " + pageName + " tab \"" + shown(tabs->tabText(i)).toStdString() + "\"");
            // Tab widgets inside this tab.
            for (QTabWidget* inner : shownTabWidgets(tabs->widget(i))) {
              if (!done.insert(inner).second) continue;
              for (int j = 0; j < inner->count(); ++j) {
                if (!inner->isTabEnabled(j) || !inner->isTabVisible(j)) continue;
                inner->setCurrentIndex(j);
                checkView("page " + pageName + " tab \"" + shown(tabs->tabText(i)).toStdString() + "\" / \"" +
                          shown(inner->tabText(j)).toStdString() + "\"");
              }
            }
          }
          break;  // the set of shown tab widgets may have changed
        }
      }
    }
    // The real 46 h log's 16 sensors on the trend and as hysteresis small multiples (gui-run F14).
    window.showPage(Page::Thermal);
    window.thermalPage()->selectDataset(QStringLiteral("thermal_caiviac"));
    for (const char* view : {"trend", "hysteresis"}) {
      QMetaObject::invokeMethod(window.thermalPage(), "showView", Q_ARG(QString, QString::fromLatin1(view)));
      QTest::qWait(500);  // the hysteresis charts are computed off the GUI thread
      checkView(std::string("thermal_caiviac ") + view);
    }
    // The dialogs a user meets on the way: the machine definition and the import of a German log.
    {
      MachineDialog machine(machine::MachineDefinition{}, machine::FrameFormat::Heidenhain, &window);
      machine.show();
      QTest::qWait(150);
      ClipCheck check;
      check.check(&machine);
      for (const std::string& f : check.failures)
        failures.push_back(language.toStdString() + " machine dialog: " + f);
      machine.grab().save(QString::fromStdString(
          (test::outDir() / ("clipping-" + language.toStdString() + "-machine-dialog.png")).string()));
    }
    {
      const QString log = dir.filePath(QStringLiteral("Spindel Aufwärmung.csv"));
      QFile f(log);
      ASSERT_TRUE(f.open(QIODevice::WriteOnly));
      f.write(
          "Aufwärmversuch Spindel, Maschine 4\n"
          "Zeit [min];Temperatur T1 [\xc2\xb0"
          "C];Verlagerung K3 [\xc2\xb5m];Drehzahl [1/min]\n");
      for (int row = 0; row < 50; ++row)
        f.write(QStringLiteral("%1;%2;%3;%4\n")
                    .arg(row)
                    .arg(21.0 + 0.1 * row, 0, 'f', 2)
                    .arg(-0.4 * row, 0, 'f', 2)
                    .arg(row < 25 ? 6000 : 0)
                    .replace(QLatin1Char('.'), QLatin1Char(','))
                    .toUtf8());
      f.close();
      ImportDialog import(window.document()->project(), window.document()->projectPathForDatasets(), &window);
      import.setFile(log);
      import.show();
      QTest::qWait(300);
      ClipCheck check;
      check.check(&import);
      for (const std::string& f : check.failures)
        failures.push_back(language.toStdString() + " import dialog: " + f);
      import.grab().save(QString::fromStdString(
          (test::outDir() / ("clipping-" + language.toStdString() + "-import-dialog.png")).string()));
    }
    // Raw measured points in German spreadsheet conventions: the nominals box (issue 28 item 4).
    {
      const QString raw = dir.filePath(QStringLiteral("Kugel Punkte.csv"));
      QFile f(raw);
      ASSERT_TRUE(f.open(QIODevice::WriteOnly));
      f.write("Punkt;X [mm];Y [mm];Z [mm]\n");
      for (int k = 0; k < 12; ++k) {
        const double ph = 0.5236 * k, th = 0.4 + 0.3 * (k % 2);
        f.write(QStringLiteral("K%1;%2;%3;%4\n")
                    .arg(k + 1)
                    .arg(20.0 * std::sin(th) * std::cos(ph), 0, 'f', 4)
                    .arg(20.0 * std::sin(th) * std::sin(ph), 0, 'f', 4)
                    .arg(20.0 * std::cos(th), 0, 'f', 4)
                    .replace(QLatin1Char('.'), QLatin1Char(','))
                    .toUtf8());
      }
      f.close();
      ImportDialog import(window.document()->project(), window.document()->projectPathForDatasets(), &window);
      import.setFile(raw);
      import.show();
      QTest::qWait(300);
      EXPECT_TRUE(import.needsNominals()) << language.toStdString();
      ClipCheck check;
      check.check(&import);
      for (const std::string& f : check.failures)
        failures.push_back(language.toStdString() + " import dialog (raw points): " + f);
      import.grab().save(QString::fromStdString(
          (test::outDir() / ("clipping-" + language.toStdString() + "-import-raw-points.png")).string()));
    }
    // A setup model from a real OGP report (issue 28 item 3).
    {
      const auto ogp = test::realData("cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt");
      METROFIT_REQUIRE_PATH(ogp);
      const ReportFeatures features = readReportFeatures(ogp.string());
      ReportModelDialog model(features, QStringLiteral("L0_axial_top_module1_1"), nullptr, &window);
      model.show();
      QTest::qWait(200);
      ClipCheck check;
      check.check(&model);
      for (const std::string& f : check.failures)
        failures.push_back(language.toStdString() + " setup model from a report: " + f);
      model.grab().save(QString::fromStdString(
          (test::outDir() / ("clipping-" + language.toStdString() + "-report-model-dialog.png")).string()));
    }
    window.document()->undoStack()->setClean();
    window.setUnsavedChangesDecider([] { return MainWindow::UnsavedChoice::Discard; });
  }
  std::string all;
  for (const std::string& f : failures) all += f + "\n";
  EXPECT_TRUE(failures.empty()) << failures.size() << " cut texts:\n" << all;
}

INSTANTIATE_TEST_SUITE_P(Languages, ClippingTest, ::testing::Values("en", "de", "pl"));

}  // namespace
}  // namespace metrofit
