// The bad-input catalogue through the GUI (offscreen): with the demo project open,
// bad files of the catalogue (bad_input_cases.h) are opened the way the GUI opens them: project files
// through MainWindow::openProject (File > Open, Recent files), whose message box is read and closed
// without blocking; data files as the pages read them when a dataset is chosen (thermal log, probe
// points / hole table, circular test) or reloaded (setup model). For each, the GUI must show the
// message metrofit-cli prints for the same file (without its "metrofit-cli: " prefix), and the open
// project must be unchanged: file name, name, datasets, studies, results, not modified, undo stack.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <functional>
#include <memory>

#include "app/gui/kinematicspage.h"
#include "app/gui/mainwindow.h"
#include "app/gui/matchingpage.h"
#include "app/gui/setuppage.h"
#include "app/gui/thermalpage.h"
#include "bad_input_cases.h"
#include "qtapp.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {
namespace {

namespace bad = test::bad;

const bad::Case& caseById(const std::string& id) {
  static const std::vector<bad::Case> all = bad::cases();
  for (const auto& c : all) {
    if (c.id == id) return c;
  }
  throw std::runtime_error("no catalogue case " + id);
}

/// The content of the file `name` of a catalogue case.
std::string contentOf(const bad::Case& c, const std::string& name) {
  for (const auto& f : c.files) {
    if (f.name == name) return f.content;
  }
  throw std::runtime_error(c.id + " has no file " + name);
}

std::string quoted(const QString& path) {
  return "'" + path.toStdString() + "'";
}

/// What identifies the open project, for "the project is intact".
struct Snapshot {
  QString fileName;
  std::string name;
  std::vector<std::string> datasets;
  nlohmann::json studies, results;
  bool modified = false;
  int undoCount = 0;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(const ProjectDocument& doc) {
  Snapshot s;
  s.fileName = doc.fileName();
  s.name = doc.project().name;
  for (const auto& d : doc.project().datasets) s.datasets.push_back(d.id + "|" + d.kind + "|" + d.path);
  s.studies = doc.project().studies;
  s.results = doc.project().results;
  s.modified = doc.isModified();
  s.undoCount = doc.undoStack()->count();
  return s;
}

bool labelShows(const QWidget* page, const QString& text) {
  for (const QLabel* label : page->findChildren<QLabel*>()) {
    if (label->text().contains(text)) return true;
  }
  return false;
}

class BadInputGui : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    demo_ = extractDemoProject(dir_.filePath(QStringLiteral("demo")));
    window_ = std::make_unique<MainWindow>();
    QString error;
    ASSERT_TRUE(window_->openProject(demo_, &error)) << error.toStdString();
    window_->show();
    before_ = snapshot(*window_->document());
    ASSERT_FALSE(before_.modified);
  }

  void TearDown() override { window_.reset(); }

  /// metrofit-cli's one-line message for `args`, run in the temporary folder (exit code 2 required).
  std::string cliMessage(const std::string& args) {
    const bad::CliResult r = bad::runCli(args, dir_.path().toStdString(), dir_.path().toStdString());
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    return bad::message(r.err);
  }

  QString datasetPath(const std::string& id) {
    for (const auto& d : window_->document()->project().datasets) {
      if (d.id == id) return window_->document()->datasetPath(d);
    }
    ADD_FAILURE() << "demo has no dataset " << id;
    return {};
  }

  /// Overwrites a data file of the open project with bad content, runs `show` (the page reads it) and
  /// restores the file. Returns the GUI's message.
  QString withBadFile(const QString& path, const std::string& content, const std::function<QString()>& show) {
    QFile original(path);
    EXPECT_TRUE(original.open(QIODevice::ReadOnly));
    const QByteArray good = original.readAll();
    original.close();
    test::writeText(path.toStdString(), content);
    const QString message = show();
    QFile restore(path);
    EXPECT_TRUE(restore.open(QIODevice::WriteOnly | QIODevice::Truncate));
    restore.write(good);
    restore.close();
    return message;
  }

  void expectIntact(const std::string& id) {
    const Snapshot now = snapshot(*window_->document());
    EXPECT_EQ(now.fileName, before_.fileName) << id;
    EXPECT_EQ(now.name, before_.name) << id;
    EXPECT_EQ(now.datasets, before_.datasets) << id;
    EXPECT_EQ(now.studies, before_.studies) << id;
    EXPECT_EQ(now.results, before_.results) << id;
    EXPECT_FALSE(now.modified) << id;
    EXPECT_EQ(now.undoCount, before_.undoCount) << id;
    EXPECT_FALSE(window_->isWindowModified()) << id;
  }

  QTemporaryDir dir_;
  QString demo_;
  std::unique_ptr<MainWindow> window_;
  Snapshot before_;
};

TEST_F(BadInputGui, OpenProjectShowsTheCliMessageAndKeepsTheProject) {
  int checked = 0;
  for (const char* id : {"PJ01", "PJ02", "PJ03", "PJ04", "PJ05", "PJ06", "PJ07", "PJ08", "PJ09"}) {
    SCOPED_TRACE(id);
    const bad::Case& c = caseById(id);
    const QString path = dir_.filePath(QStringLiteral("%1.metrofit").arg(QString::fromLatin1(id)));
    test::writeText(path.toStdString(), contentOf(c, "p.metrofit"));
    const std::string cli = cliMessage("report --project " + quoted(path) + " --out " +
                                       quoted(dir_.filePath(QStringLiteral("r.pdf"))));
    EXPECT_NE(cli.find(path.toStdString()), std::string::npos) << cli;

    // File > Open: the error arrives in a message box, read and closed by a timer (no blocking).
    QString shown, title;
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, [&shown, &title, timer] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
        timer->stop();
        timer->deleteLater();
        shown = box->text();
        title = box->windowTitle();
        box->accept();
      }
    });
    timer->start();
    EXPECT_FALSE(window_->openProject(path));
    EXPECT_EQ(shown.toStdString(), cli);
    EXPECT_FALSE(title.isEmpty());

    // The same through the error-returning form (what tests and Recent files use).
    QString error;
    EXPECT_FALSE(window_->openProject(path, &error));
    EXPECT_EQ(error.toStdString(), cli);
    expectIntact(id);
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}

TEST_F(BadInputGui, ThermalLogShowsTheCliMessageAndKeepsTheProject) {
  auto* page = window_->thermalPage();
  ASSERT_NE(page, nullptr);
  window_->showPage(Page::Thermal);
  const QString path = datasetPath("thermal_sim");
  for (const char* id : {"TL05", "TL06", "TL08", "TL09", "TL10", "TL12", "TL13", "TL16"}) {
    SCOPED_TRACE(id);
    const std::string content = contentOf(caseById(id), "log.csv");
    const QString shown = withBadFile(path, content, [&] {
      const std::string cli =
          cliMessage("thermal fit --data " + quoted(path) + " --target disp_z_um --inputs T1,T2");
      page->selectDataset(QStringLiteral("thermal_modular_z"));
      page->selectDataset(QStringLiteral("thermal_sim"));
      EXPECT_EQ(page->errorMessage().toStdString(), cli);
      return page->errorMessage();
    });
    EXPECT_TRUE(labelShows(page, shown)) << shown.toStdString();
    expectIntact(id);
  }
  // The restored log reads again.
  page->selectDataset(QStringLiteral("thermal_modular_z"));
  page->selectDataset(QStringLiteral("thermal_sim"));
  EXPECT_TRUE(page->errorMessage().isEmpty()) << page->errorMessage().toStdString();
}

TEST_F(BadInputGui, ProbePointsShowTheCliMessageAndKeepTheProject) {
  auto* page = window_->matchingPage();
  ASSERT_NE(page, nullptr);
  window_->showPage(Page::Matching);
  const QString path = datasetPath("probe_block");
  struct Item {
    const char* id;
    const char* file;
  };
  for (const Item& item : {Item{"PP01", "pts.csv"}, Item{"PP03", "pts.csv"}, Item{"PP06", "pts.csv"},
                           Item{"PP12", "pts.csv"}, Item{"HT02", "holes.txt"}, Item{"HT04", "holes.txt"}}) {
    SCOPED_TRACE(item.id);
    const std::string content = contentOf(caseById(item.id), item.file);
    const QString shown = withBadFile(path, content, [&] {
      const std::string cli = cliMessage("match --data " + quoted(path));
      page->selectDataset(QStringLiteral("probe_s_piece"));
      page->selectDataset(QStringLiteral("probe_block"));
      EXPECT_EQ(page->errorMessage().toStdString(), cli);
      return page->errorMessage();
    });
    EXPECT_TRUE(labelShows(page, shown)) << shown.toStdString();
    expectIntact(item.id);
  }
}

TEST_F(BadInputGui, CircularTestShowsTheCliMessageAndKeepsTheProject) {
  auto* page = qobject_cast<KinematicsPage*>(window_->page(Page::Kinematics));
  ASSERT_NE(page, nullptr);
  window_->showPage(Page::Kinematics);
  const QString path = datasetPath("circular_demo");
  for (const char* id : {"CT01", "CT02", "CT03", "CT04"}) {
    SCOPED_TRACE(id);
    const std::string content = contentOf(caseById(id), "c.csv");
    const QString shown = withBadFile(path, content, [&] {
      const std::string cli = cliMessage("kinematic identify --data " + quoted(path));
      page->selectDataset(QStringLiteral("diagnose_circular"));
      page->selectDataset(QStringLiteral("circular_demo"));
      EXPECT_FALSE(page->identify());
      EXPECT_EQ(page->errorMessage().toStdString(), cli);
      return page->errorMessage();
    });
    EXPECT_TRUE(labelShows(page, shown)) << shown.toStdString();
    expectIntact(id);
  }
}

TEST_F(BadInputGui, SetupModelShowsTheCliMessageAndKeepsTheProject) {
  auto* page = qobject_cast<SetupPage*>(window_->page(Page::Setup));
  ASSERT_NE(page, nullptr);
  window_->showPage(Page::Setup);
  const QString model = datasetPath("setup_model");
  const QString report = datasetPath("setup_report");
  for (const char* id : {"SM01", "SM02", "SM05", "SM06", "SM07", "SM08"}) {
    SCOPED_TRACE(id);
    const std::string content = contentOf(caseById(id), "m.json");
    withBadFile(model, content, [&] {
      const std::string cli = cliMessage("setup --model " + quoted(model) + " --data " + quoted(report));
      page->reload();
      EXPECT_EQ(page->errorMessage().toStdString(), cli);
      return page->errorMessage();
    });
    expectIntact(id);
  }
  page->reload();
  EXPECT_TRUE(page->errorMessage().isEmpty()) << page->errorMessage().toStdString();
}

}  // namespace
}  // namespace metrofit
