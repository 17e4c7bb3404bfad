// The controller outputs of the GUI against the CLI and against what the formats themselves say, under
// xvfb-run (the matching page's 3D views render):
//  * matching page, tab "Controller frame": the blocks on the page are the command lines of the file
//    `metrofit-cli match --frame` writes, and "Save frame" writes that file byte for byte; a FANUC
//    frame's G68.2 I J K rebuild the fitted rotation by the Euler Z-X-Z rule written out here; the
//    control is a study setting that undo takes back; no result: disabled with a tooltip;
//  * setup page, "Update HEIDENHAIN table": a preset table and a tool table written here in the TNC's
//    layout (BEGIN line, column names whose position is the column, rows, [END]) come back with only the
//    target cells changed, by the corrections shown; the input is never overwritten;
//  * setup page and kinematics page's SPC tab, "Export Q-DAS DFQ": the file is the CLI's (`setup --dfq`,
//    `spc --dfq`) byte for byte, and its K-fields read back to the measured values (the report / series
//    file read here) and to the page's figures.
#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#define METROFIT_TEST_QT_XVFB
#include "app/gui/kinematicspage.h"
#include "app/gui/matchingpage.h"
#include "app/gui/setuppage.h"
#include "cli/cli_runner.h"
#include "cli/dfq_fields.h"
#include "core/io/csv.h"
#include "core/project/project.h"
#include "core/sim/probe_sim.h"
#include "core/study/kinematic_study.h"
#include "core/study/study_check.h"
#include "qtapp.h"
#include "testsupport.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/matching/pointsetview.h"
#include "widgets/setup/setupmodeleditor.h"
#include "widgets/setup/setupresultsview.h"

namespace metrofit {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string quoted(const QString& s) {
  return "'" + s.toStdString() + "'";
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

// ---- matching page: controller frame ------------------------------------------------------------------

class FramePageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(PointSetView::canRender3D()) << "run under xvfb-run with QT_QPA_PLATFORM=xcb";
    ASSERT_TRUE(dir_.isValid());
    ProbeSimOptions o = ProbeSimOptions::sPieceDefaults();
    o.seed = 11;
    test::writeText(dir_.filePath(QStringLiteral("s.csv")).toStdString(),
                    probePointsToCsv(simulateProbing(o)));
    Project p;
    p.name = "frame test";
    DatasetRef d;
    d.id = "s_piece";
    d.kind = dataset_kind::kProbePoints;
    d.path = "s.csv";
    p.datasets.push_back(d);
    p.studies["matching"] = {{"dataset", "s_piece"}, {"method", "closed-form"}};
    const QString path = dir_.filePath(QStringLiteral("p.metrofit"));
    saveProject(p, path.toStdString());
    document_.load(path);
    page_ = std::make_unique<MatchingPage>(&document_);
    page_->resize(1400, 900);
    page_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(page_.get()));
  }
  /// The points' file as the page reads it (the title of the frame program).
  QString dataFile() const { return document_.datasetPath(*document_.project().dataset("s_piece")); }

  QTemporaryDir dir_;
  ProjectDocument document_;
  std::unique_ptr<MatchingPage> page_;
};

TEST_F(FramePageTest, NoResultNoFrame) {
  EXPECT_FALSE(page_->saveFrameButton()->isEnabled());
  EXPECT_FALSE(page_->saveFrameButton()->toolTip().isEmpty());
  EXPECT_TRUE(page_->frameText().isEmpty());
  QString error;
  EXPECT_FALSE(page_->saveFrame(dir_.filePath(QStringLiteral("x.h")), &error));
  EXPECT_FALSE(error.isEmpty());
  EXPECT_FALSE(QFile::exists(dir_.filePath(QStringLiteral("x.h"))));
}

// The points table's "Export deviations after matching (CSV)…" writes the bytes `match --per-point`
// writes for the same data and method (issue 28 item 4).
TEST_F(FramePageTest, PerPointDeviationsAreTheCliFile) {
  QString error;
  EXPECT_FALSE(page_->savePerPointDeviations(dir_.filePath(QStringLiteral("pp.csv")), &error));
  EXPECT_FALSE(error.isEmpty());
  EXPECT_FALSE(QFile::exists(dir_.filePath(QStringLiteral("pp.csv"))));
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  ASSERT_EQ(page_->result()->primary, matching::MatchMethod::ClosedForm);
  EXPECT_NE(page_->pointTable()->findChild<QAction*>(QStringLiteral("exportPerPoint")), nullptr);
  const QString saved = dir_.filePath(QStringLiteral("pp.csv"));
  ASSERT_TRUE(page_->savePerPointDeviations(saved, &error)) << error.toStdString();
  test::TempDir tmp;
  const test::CliRun cli =
      test::cli("match --data " + quoted(dataFile()) + " --method closed-form --per-point pp.csv", tmp);
  ASSERT_EQ(cli.code, 0) << cli.err;
  EXPECT_EQ(test::readText(saved.toStdString()), test::readText(tmp.file("pp.csv")));
  // Its d_mm column is the table's "after" column (4 decimals there).
  const CsvTable t = readCsvFile(saved.toStdString());
  ASSERT_EQ(static_cast<int>(t.rowCount()), page_->pointTable()->rowCount());
  for (int row = 0; row < page_->pointTable()->rowCount(); ++row) {
    bool ok = false;
    const double shown = QLocale().toDouble(page_->pointTable()->item(row, 3)->text(), &ok);
    ASSERT_TRUE(ok) << page_->pointTable()->item(row, 3)->text().toStdString();
    EXPECT_NEAR(shown, t.number(static_cast<std::size_t>(row), t.requireColumn("d_mm")), 0.5e-4 + 1e-12)
        << row;
  }
}

TEST_F(FramePageTest, FrameIsTheCliFileForEveryControl) {
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  ASSERT_EQ(page_->result()->primary, matching::MatchMethod::ClosedForm);
  EXPECT_TRUE(page_->saveFrameButton()->isEnabled());
  page_->showView(QStringLiteral("frame"));
  QCoreApplication::processEvents();
  const QDir out(QString::fromStdString((test::outDir() / "controller_outputs").string()));
  QDir().mkpath(out.path());
  page_->grab().save(out.filePath(QStringLiteral("matching_frame.png")));

  test::TempDir tmp;
  const std::pair<machine::FrameFormat, const char*> controls[] = {
      {machine::FrameFormat::Heidenhain, "heidenhain"},
      {machine::FrameFormat::Siemens, "siemens"},
      {machine::FrameFormat::Fanuc, "fanuc"}};
  const char* suffix[] = {".h", ".spf", ".nc"};
  int k = 0;
  for (const auto& [format, name] : controls) {
    SCOPED_TRACE(name);
    page_->setFrameFormat(format);
    page_->frameDecimalsSpin()->setValue(k == 2 ? 3 : 5);
    const std::string file = std::string("POSTURE_") + name + suffix[k];
    const test::CliRun cli =
        test::cli("match --data " + quoted(dataFile()) + " --method closed-form --frame " + name +
                      " --frame-out " + file + " --frame-decimals " + std::to_string(k == 2 ? 3 : 5),
                  tmp);
    ASSERT_EQ(cli.code, 0) << cli.err;
    const std::string cliText = test::readText(tmp.file(file));
    // Saved by the page under the same file name: the same bytes.
    const QString saved = dir_.filePath(QString::fromStdString(file));
    QString error;
    ASSERT_TRUE(page_->saveFrame(saved, &error)) << error.toStdString();
    EXPECT_EQ(test::readText(saved.toStdString()), cliText);
    // The box shows the file's command blocks, in order (HEIDENHAIN: after the block number).
    std::vector<std::string> commands;
    for (std::string l : splitLines(cliText)) {
      if (format == machine::FrameFormat::Heidenhain) l = l.substr(l.find(' ') + 1);
      if (l.rfind("CYCL DEF 7", 0) == 0 || l.rfind("PLANE SPATIAL", 0) == 0 || l.rfind("TRANS", 0) == 0 ||
          l.rfind("AROT", 0) == 0 || l.rfind("G68.2", 0) == 0)
        commands.push_back(l);
    }
    EXPECT_EQ(commands.size(), format == machine::FrameFormat::Heidenhain ? 5u
                               : format == machine::FrameFormat::Siemens  ? 4u
                                                                          : 1u);
    EXPECT_EQ(splitLines(page_->frameText().toStdString()), commands);
    EXPECT_EQ(page_->frameTextBox()->toPlainText(), page_->frameText());
    EXPECT_TRUE(page_->frameTextBox()->isReadOnly());
    ++k;
  }
}

TEST_F(FramePageTest, FanucAnglesRebuildTheFittedRotation) {
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  page_->setFrameFormat(machine::FrameFormat::Fanuc);
  page_->frameDecimalsSpin()->setValue(12);
  const std::string block = page_->frameText().toStdString();
  ASSERT_EQ(block.rfind("G68.2 ", 0), 0u) << block;
  // The words X Y Z I J K of the block.
  std::map<char, double> word;
  std::istringstream in(block.substr(6));
  for (std::string w; in >> w;) word[w[0]] = test::cnumber(w.substr(1));
  ASSERT_EQ(word.size(), 6u) << block;
  // FANUC G68.2 Euler angles: turn by I about Z, then by J about the new X, then by K about the new Z:
  // R = Rz(I) Rx(J) Rz(K), written out element by element.
  const double i = word['I'] * kPi / 180, j = word['J'] * kPi / 180, kk = word['K'] * kPi / 180;
  const double ci = std::cos(i), si = std::sin(i), cj = std::cos(j), sj = std::sin(j), ck = std::cos(kk),
               sk = std::sin(kk);
  Eigen::Matrix3d R;
  R << ci * ck - si * cj * sk, -ci * sk - si * cj * ck, si * sj,  //
      si * ck + ci * cj * sk, -si * sk + ci * cj * ck, -ci * sj,  //
      sj * sk, sj * ck, cj;
  const matching::Pose& pose = page_->result()->primaryRun().pose;
  EXPECT_LT((R - pose.rotation).cwiseAbs().maxCoeff(), 1e-9) << block;
  EXPECT_NEAR(word['X'], pose.translation.x(), 1e-9);
  EXPECT_NEAR(word['Y'], pose.translation.y(), 1e-9);
  EXPECT_NEAR(word['Z'], pose.translation.z(), 1e-9);
  EXPECT_GE(word['J'], 0.0);
  EXPECT_LE(word['J'], 180.0);
  // The fit is not a trivial rotation (the test would prove little otherwise).
  EXPECT_GT((pose.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-5);
}

TEST_F(FramePageTest, ControlAndDecimalsAreUndoableStudySettings) {
  const QString study = QStringLiteral("matching");
  EXPECT_EQ(page_->frameFormat(), machine::FrameFormat::Heidenhain);  // the default
  page_->setFrameFormat(machine::FrameFormat::Siemens);
  EXPECT_EQ(document_.studyValue(study, QStringLiteral("/frame")), nlohmann::json("siemens"));
  page_->frameDecimalsSpin()->setValue(3);
  document_.endEditSequence();
  EXPECT_EQ(document_.studyValue(study, QStringLiteral("/frame_decimals")), nlohmann::json(3));
  document_.undoStack()->undo();
  EXPECT_EQ(page_->frameDecimalsSpin()->value(), 4);
  document_.undoStack()->undo();
  EXPECT_EQ(page_->frameFormat(), machine::FrameFormat::Heidenhain);
  EXPECT_TRUE(document_.studyValue(study, QStringLiteral("/frame")).is_null());
  document_.undoStack()->redo();
  EXPECT_EQ(page_->frameFormat(), machine::FrameFormat::Siemens);
  // A page opened on the saved project takes the setting.
  document_.save();
  ProjectDocument again;
  again.load(document_.fileName());
  MatchingPage other(&again);
  EXPECT_EQ(other.frameFormat(), machine::FrameFormat::Siemens);
}

/// The text of a PDF (pdftotext from poppler-utils).
std::string pdfText(const std::string& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {QString::fromStdString(pdf), QStringLiteral("-")});
  if (!p.waitForFinished(30000)) return {};
  return p.readAllStandardOutput().toStdString();
}

// F2 of the GUI run: choosing a control wrote a key the study validator did not know, so the saved
// project's report failed (metrofit-cli report exit 2) and reopening it showed an error. The control and
// the decimals are matching settings now, and the report lists the study's control with its decimals.
TEST_F(FramePageTest, ChosenControlIsAValidSettingAndTheReportShowsIt) {
  ASSERT_TRUE(page_->runNow()) << page_->errorMessage().toStdString();
  page_->setFrameFormat(machine::FrameFormat::Fanuc);
  page_->frameDecimalsSpin()->setValue(3);
  document_.endEditSequence();
  page_->setFrameFormat(machine::FrameFormat::Heidenhain);  // back and forth: the key stays, and is valid
  page_->setFrameFormat(machine::FrameFormat::Fanuc);
  document_.save();
  EXPECT_TRUE(checkStudies(document_.project()).empty()) << checkStudies(document_.project()).front().field;

  // Reopened: the page shows the control and decimals and no settings error.
  ProjectDocument again;
  again.load(document_.fileName());
  MatchingPage other(&again);
  EXPECT_EQ(other.frameFormat(), machine::FrameFormat::Fanuc);
  EXPECT_EQ(other.frameDecimalsSpin()->value(), 3);
  const QLabel* status = other.findChild<QLabel*>(QStringLiteral("matchingStatus"));
  ASSERT_NE(status, nullptr);
  EXPECT_FALSE(status->text().contains(QStringLiteral("invalid"))) << status->text().toStdString();

  // metrofit-cli report on the saved file: exit 0, the FANUC frame first, with 3 decimals.
  test::TempDir tmp;
  const std::string pdf = tmp.file("r.pdf");
  const test::CliRun r =
      test::cli("report --project '" + document_.fileName().toStdString() + "' --out '" + pdf + "'", tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = pdfText(pdf);
  const std::size_t listing = text.find("controller frame (instead of the axis values; decimals: 3)");
  ASSERT_NE(listing, std::string::npos) << text;
  const std::size_t fanuc = text.find("FANUC (the study's", listing);  // the cell may wrap
  ASSERT_NE(fanuc, std::string::npos) << text.substr(listing, 600);
  EXPECT_LT(fanuc, text.find("HEIDENHAIN", listing)) << "the study's control comes first";
  // The G68.2 block of the page (3 decimals) is the report's.
  const QString g68 = page_->frameText().section(QLatin1Char('\n'), 0, 0);
  ASSERT_TRUE(g68.startsWith(QStringLiteral("G68.2"))) << page_->frameText().toStdString();
  const QString firstWords = g68.section(QLatin1Char(' '), 0, 1);  // "G68.2 X12.345"
  EXPECT_NE(text.find(firstWords.toStdString()), std::string::npos) << g68.toStdString();
}

// A bad setting is refused on the page as in the report: the status names the field and nothing runs
// (issue 27 item 3: the page used to run with the defaults in place of the bad values).
TEST_F(FramePageTest, BadSettingsAreNamedAndRefused) {
  Project p = loadProject(document_.fileName().toStdString());
  p.studies["matching"]["frame"] = "okuma";
  p.studies["matching"]["frame_decimals"] = 13;
  const QString path = dir_.filePath(QStringLiteral("bad.metrofit"));
  saveProject(p, path.toStdString());
  ProjectDocument document;
  document.load(path);
  MatchingPage page(&document);
  const QLabel* status = page.findChild<QLabel*>(QStringLiteral("matchingStatus"));
  ASSERT_NE(status, nullptr);
  EXPECT_TRUE(status->text().contains(QStringLiteral("studies.matching.frame")))
      << status->text().toStdString();
  EXPECT_FALSE(page.runNow()) << "no run with settings the study does not hold";
  EXPECT_FALSE(page.result().has_value());
  EXPECT_TRUE(status->text().contains(QStringLiteral("studies.matching.frame")))
      << status->text().toStdString();
  // Corrected on the page (a valid control and decimals): the run goes ahead.
  document.setStudyValue(QStringLiteral("matching"), QStringLiteral("/frame"), "siemens",
                         QStringLiteral("fix"));
  document.setStudyValue(QStringLiteral("matching"), QStringLiteral("/frame_decimals"), 3,
                         QStringLiteral("fix"));
  EXPECT_FALSE(status->text().contains(QStringLiteral("invalid"))) << status->text().toStdString();
  EXPECT_EQ(page.frameFormat(), machine::FrameFormat::Siemens);
  ASSERT_TRUE(page.runNow()) << page.errorMessage().toStdString();
  EXPECT_FALSE(page.frameText().isEmpty());
}

// ---- setup page: HEIDENHAIN tables and DFQ ------------------------------------------------------------

using test::DfqFields;
using test::readDfq;

/// A TNC table's cells of one row by the header's column positions (a column starts where its name
/// starts and ends where the next begins).
std::map<std::string, std::pair<std::size_t, std::size_t>> columns(const std::string& header) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> c;
  std::vector<std::pair<std::string, std::size_t>> names;
  for (std::size_t i = 0; i < header.size();) {
    if (header[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < header.size() && header[i] != ' ') ++i;
    names.emplace_back(header.substr(start, i - start), start);
  }
  for (std::size_t k = 0; k < names.size(); ++k)
    c[names[k].first] = {names[k].second, k + 1 < names.size() ? names[k + 1].second : std::string::npos};
  return c;
}

std::string cellOf(const std::string& line, std::pair<std::size_t, std::size_t> col) {
  if (col.first >= line.size()) return {};
  std::string s =
      line.substr(col.first, col.second == std::string::npos ? std::string::npos : col.second - col.first);
  s.erase(s.find_last_not_of(' ') + 1);
  s.erase(0, s.find_first_not_of(' '));
  return s;
}

class SetupExportsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = extractDemoProject(dir_.path());
    document_.load(project_);
    page_ = std::make_unique<SetupPage>(&document_);
    page_->resize(1200, 800);
  }
  QString modelPath() const { return dir_.filePath(QStringLiteral("data/paper_example.json")); }
  QString reportPath() const { return dir_.filePath(QStringLiteral("data/paper_example_report.csv")); }
  /// Corrections by setup datum id, from the page's last run.
  std::map<std::string, double> corrections() const {
    std::map<std::string, double> x;
    const auto& model = page_->modelEditor()->model();
    const auto& r = page_->resultsView()->result();
    for (std::size_t i = 0; i < model.setup.size(); ++i) x[model.setup[i].id] = r->x[i];
    return x;
  }

  QTemporaryDir dir_;
  QString project_;
  ProjectDocument document_;
  std::unique_ptr<SetupPage> page_;
};

/// Checks `after` is `before` with only `column` of the rows `targets` (register -> increment) changed,
/// by the increment (to the cell's decimals), every other byte identical.
void expectOnlyTargetCells(const std::string& before, const std::string& after, const std::string& key,
                           const std::string& column, const std::map<long, double>& targets) {
  const std::vector<std::string> a = splitLines(before), b = splitLines(after);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(before.find("\r\n") != std::string::npos, after.find("\r\n") != std::string::npos);
  const auto cols = columns(a[1]);
  const auto value = cols.at(column), keyCol = cols.at(key);
  std::size_t changed = 0;
  for (std::size_t l = 0; l < a.size(); ++l) {
    SCOPED_TRACE("line " + std::to_string(l + 1));
    const std::string k = l >= 2 ? cellOf(a[l], keyCol) : std::string();
    const bool target = !k.empty() && k.find_first_not_of("0123456789") == std::string::npos &&
                        targets.count(std::stol(k)) > 0;
    if (!target) {
      EXPECT_EQ(b[l], a[l]);
      continue;
    }
    ++changed;
    // Outside the cell: the same bytes.
    const std::size_t end = value.second == std::string::npos ? a[l].size() : value.second;
    EXPECT_EQ(b[l].substr(0, value.first), a[l].substr(0, value.first));
    EXPECT_EQ(b[l].substr(std::min(end, b[l].size())), a[l].substr(std::min(end, a[l].size())));
    const std::string oldCell = cellOf(a[l], value), newCell = cellOf(b[l], value);
    const std::size_t dp = oldCell.find('.');
    const int decimals = std::max(3, dp == std::string::npos ? 0 : static_cast<int>(oldCell.size() - dp - 1));
    EXPECT_NEAR(test::cnumber(newCell), test::cnumber(oldCell) + targets.at(std::stol(k)),
                0.5 * std::pow(10.0, -decimals) + 1e-12)
        << oldCell << " -> " << newCell;
  }
  EXPECT_EQ(changed, targets.size());
}

TEST_F(SetupExportsTest, HeidenhainTablesGetOnlyTheTargetCells) {
  SetupResultsView* results = page_->resultsView();
  QString error;
  EXPECT_FALSE(results->updateHeidenhainTable(QStringLiteral("a.PR"), QStringLiteral("b.PR"), &error));
  EXPECT_FALSE(error.isEmpty()) << "no result yet";
  ASSERT_TRUE(page_->runSynchronously(QStringLiteral("exact"), 0, 1)) << page_->errorMessage().toStdString();
  const std::map<std::string, double> x = corrections();
  ASSERT_EQ(x.size(), 10u);
  int nonzero = 0;
  for (const auto& [id, v] : x) nonzero += std::abs(v) > 5e-4;
  EXPECT_GE(nonzero, 3) << "corrections that change cells";

  // The preset table as the TNC saves it (TNC7 user's manual, "Preset table": NR, DOC, X, Y, Z, SPA,
  // SPB, SPC; layout of the TNC's table files): rows 0 and 9 are no setup datum of the model.
  std::string preset =
      "BEGIN PRESET.PR MM\r\nNR      DOC              X              Y              Z              "
      "SPA         SPB         SPC\r\n";
  for (int r = 0; r <= 9; ++r) {
    char row[200];
    std::snprintf(row, sizeof row, "%-8d%-17s%-15s%-15s%-15s%-12s%-12s%s\r\n", r,
                  r == 0 ? "machine" : "fixture", "+12.5", "-3", r == 3 ? "-412.8765" : "-398.25", "+0", "+0",
                  "+0");
    preset += row;
  }
  preset += "[END]\r\n";
  const QString presetIn = dir_.filePath(QStringLiteral("PRESET.PR"));
  test::writeText(presetIn.toStdString(), preset);
  EXPECT_FALSE(results->updateHeidenhainTable(presetIn, presetIn, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("new file"))) << error.toStdString();
  EXPECT_EQ(test::readText(presetIn.toStdString()), preset) << "the control's table is never overwritten";

  const QString presetOut = dir_.filePath(QStringLiteral("out/PRESET.PR"));
  QDir().mkpath(dir_.filePath(QStringLiteral("out")));
  setup::TableUpdate update;
  ASSERT_TRUE(results->updateHeidenhainTable(presetIn, presetOut, &error, &update)) << error.toStdString();
  EXPECT_EQ(update.table, "PRESET.PR");
  EXPECT_EQ(update.notWritten, (std::vector<std::string>{"T5", "T23"}));
  std::map<long, double> presetTargets;
  for (int w = 1; w <= 8; ++w) presetTargets[w] = x.at("W" + std::to_string(w));
  expectOnlyTargetCells(preset, test::readText(presetOut.toStdString()), "NR", "Z", presetTargets);
  // The same as the CLI writes from the same table.
  test::TempDir tmp;
  const test::CliRun cli =
      test::cli("setup --model " + quoted(modelPath()) + " --data " + quoted(reportPath()) +
                    " --export heidenhain-table --export-table " + quoted(presetIn) + " --export-out P.PR",
                tmp);
  ASSERT_EQ(cli.code, 0) << cli.err;
  EXPECT_EQ(test::readText(tmp.file("P.PR")), test::readText(presetOut.toStdString()));

  // The tool table (layout of the TNC's TOOL.T: T, NAME, L, R, DL, ...), wear register DL and then
  // geometry L.
  const std::string tool =
      "BEGIN TOOL.T MM Version: 'Update:110.24'\n"
      "T       NAME                            L           R           R2          DL        DR        DOC\n"
      "0       NULLTOOL                        +0          +0          +0          +0        +0        zero\n"
      "5       END_MILL_D10                    +85.125     +5          +0          +0        -0.01     "
      "rough\n"
      "7       DRILL_D8                        +92         +4          +0          +0.002    +0        "
      "drill\n"
      "23      BALL_D6                         +70.5       +3          +3          -0.005    +0        "
      "finish\n"
      "[END]\n";
  const QString toolIn = dir_.filePath(QStringLiteral("TOOL.T"));
  test::writeText(toolIn.toStdString(), tool);
  const std::map<long, double> toolTargets{{5, x.at("T5")}, {23, x.at("T23")}};
  ASSERT_TRUE(
      results->updateHeidenhainTable(toolIn, dir_.filePath(QStringLiteral("out/TOOL.T")), &error, &update))
      << error.toStdString();
  EXPECT_EQ(update.written, (std::vector<std::string>{"T5", "T23"}));
  expectOnlyTargetCells(tool, test::readText(dir_.filePath(QStringLiteral("out/TOOL.T")).toStdString()), "T",
                        "DL", toolTargets);
  results->setToolOffset(setup::ToolOffset::Geometry);
  ASSERT_TRUE(results->updateHeidenhainTable(toolIn, dir_.filePath(QStringLiteral("out/TOOL_L.T")), &error))
      << error.toStdString();
  expectOnlyTargetCells(tool, test::readText(dir_.filePath(QStringLiteral("out/TOOL_L.T")).toStdString()),
                        "T", "L", toolTargets);

  // A table that is not one: core's message, nothing written.
  const QString bad = dir_.filePath(QStringLiteral("PALLET.P"));
  test::writeText(bad.toStdString(), "BEGIN PALLET.P MM\nNR\n[END]\n");
  EXPECT_FALSE(results->updateHeidenhainTable(bad, dir_.filePath(QStringLiteral("out/x.P")), &error));
  EXPECT_TRUE(error.contains(QStringLiteral("PALLET.P"))) << error.toStdString();
  EXPECT_FALSE(QFile::exists(dir_.filePath(QStringLiteral("out/x.P"))));
}

/// The report's rows read here: dimension -> measured values in file order.
std::map<std::string, std::vector<double>> reportValues(const std::string& path) {
  std::map<std::string, std::vector<double>> v;
  std::ifstream in(path);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      EXPECT_EQ(line, "part,time_min,dimension,nominal_mm,measured_mm,lower_tol_mm,upper_tol_mm");
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    v[cells.at(2)].push_back(test::cnumber(cells.at(4)));
  }
  return v;
}

TEST_F(SetupExportsTest, SetupDfqIsTheCliFileAndReadsBackToTheReport) {
  SetupResultsView* results = page_->resultsView();
  ASSERT_TRUE(results->hasMeasurements());
  const QString file = dir_.filePath(QStringLiteral("setup.dfq"));
  QString error;
  ASSERT_TRUE(results->exportDfq(file, &error)) << error.toStdString();
  const std::string text = test::readText(file.toStdString());
  test::TempDir tmp;
  const test::CliRun cli = test::cli(
      "setup --model " + quoted(modelPath()) + " --data " + quoted(reportPath()) + " --dfq s.dfq", tmp);
  ASSERT_EQ(cli.code, 0) << cli.err;
  EXPECT_EQ(test::readText(tmp.file("s.dfq")), text);

  const DfqFields d = readDfq(text);
  const auto report = reportValues(reportPath().toStdString());
  const auto& model = page_->modelEditor()->model();
  ASSERT_EQ(d.fields.at("K0100"), std::to_string(report.size()));
  EXPECT_EQ(d.fields.at("K1001/1"), "paper_example");
  const setup::SetupInstance* inst = page_->instance();
  ASSERT_NE(inst, nullptr);
  for (int i = 1; i <= static_cast<int>(report.size()); ++i) {
    const std::string id = d.fields.at("K2001/" + std::to_string(i));
    SCOPED_TRACE(id);
    ASSERT_TRUE(report.count(id));
    const std::vector<double>& measured = report.at(id);
    ASSERT_EQ(d.values.at(i).size(), measured.size());
    for (std::size_t k = 0; k < measured.size(); ++k) EXPECT_NEAR(d.values.at(i)[k], measured[k], 1e-12);
    const auto dim = std::find_if(model.dimensions.begin(), model.dimensions.end(),
                                  [&](const setup::Dimension& m) { return m.id == id; });
    ASSERT_NE(dim, model.dimensions.end());
    EXPECT_DOUBLE_EQ(test::cnumber(d.fields.at("K2101/" + std::to_string(i))), *dim->nominal);
    EXPECT_NEAR(test::cnumber(d.fields.at("K2110/" + std::to_string(i))), *dim->nominal + dim->lower, 1e-12);
    EXPECT_NEAR(test::cnumber(d.fields.at("K2111/" + std::to_string(i))), *dim->nominal + dim->upper, 1e-12);
    // The page's deviation of the dimension (the margins' "before") is the mean of the values - nominal.
    const auto& ids = inst->dimensionIds();
    const auto q = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
    ASSERT_LT(q, ids.size());
    double mean = 0.0;
    for (double v : d.values.at(i)) mean += v - *dim->nominal;
    EXPECT_NEAR(mean / static_cast<double>(measured.size()), inst->deviation(q), 1e-9);
  }
}

TEST(KinematicsSpcDfq, IsTheCliFileAndReadsBackToThePageSeries) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  ProjectDocument document;
  document.load(extractDemoProject(dir.path()));
  KinematicsPage page(&document);
  page.showView(QStringLiteral("spc"));
  ASSERT_NE(page.study(), nullptr) << page.errorMessage().toStdString();
  ASSERT_TRUE(page.study()->spc.has_value()) << page.study()->spcError;
  EXPECT_TRUE(page.spcDfqButton()->isEnabled());
  const QString file = dir.filePath(QStringLiteral("bores.dfq"));
  QString error;
  ASSERT_TRUE(page.exportSpcDfq(file, &error)) << error.toStdString();
  const std::string text = test::readText(file.toStdString());

  // The study's series (studies.kinematics.spc of the demo: bores_demo, diameter_mm, n = 5, limits
  // 99.98 / 100.02, nominal 100) through the CLI.
  const QString data = dir.filePath(QStringLiteral("data/bores_demo.csv"));
  test::TempDir tmp;
  const test::CliRun cli = test::cli("spc --data " + quoted(data) +
                                         " --column diameter_mm --subgroup 5 --lsl 99.98 --usl 100.02 "
                                         "--nominal 100 --dfq b.dfq",
                                     tmp);
  ASSERT_EQ(cli.code, 0) << cli.err;
  EXPECT_EQ(test::readText(tmp.file("b.dfq")), text);

  const DfqFields d = readDfq(text);
  EXPECT_EQ(d.fields.at("K0100"), "1");
  EXPECT_EQ(d.fields.at("K2001/1"), "diameter_mm");
  EXPECT_EQ(d.fields.at("K2142/1"), "mm");
  EXPECT_EQ(test::cnumber(d.fields.at("K2110/1")), 99.98);
  EXPECT_EQ(test::cnumber(d.fields.at("K2111/1")), 100.02);
  EXPECT_EQ(test::cnumber(d.fields.at("K2101/1")), 100.0);
  EXPECT_EQ(d.values.at(1), page.study()->spc->values);  // the series the SPC tab charts
  // ... and the file's column read here.
  std::ifstream in(data.toStdString());
  std::string line;
  std::vector<double> column;
  int index = -1;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (index < 0) {
      index = static_cast<int>(std::find(cells.begin(), cells.end(), "diameter_mm") - cells.begin());
      ASSERT_LT(index, static_cast<int>(cells.size()));
      continue;
    }
    column.push_back(test::cnumber(cells.at(static_cast<std::size_t>(index))));
  }
  EXPECT_EQ(d.values.at(1), column);
  EXPECT_EQ(column.size(), 25u);
}

}  // namespace
}  // namespace metrofit
