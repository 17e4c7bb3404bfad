// The import dialog (widgets/importer/importdialog.h) and the dataset edits of the document
// (ProjectDocument::addDataset / removeDataset / renameDataset / relinkDataset), offscreen:
//   * a ';'-separated thermal log with decimal commas and German column names, written here from a
//     known formula (not by our writer), imported through the dialog with a column mapping; the saved
//     DatasetRef keeps dialect and mapping; the thermal page reads it and a linear model fitted the
//     way the page's model view does recovers the formula's coefficient;
//   * a circular test exported the German way reads exactly as the original in the kinematics study
//     and the diagnosis;
//   * undo / redo of the import; remove, rename (studies follow, duplicates refused), re-link;
//   * a bad file: a one-line message naming file, line and field, and the Import button disabled;
//   * a file dropped on the main window opens the dialog and is imported (one undo step).
#include <gtest/gtest.h>

#include <QProcess>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeWidgetItemIterator>
#include <QUndoStack>
#include <QUrl>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

#include "app/gui/datasetactions.h"
#include "app/gui/mainwindow.h"
#include "app/gui/matchingpage.h"
#include "app/gui/projectnavigator.h"
#include "app/gui/thermalpage.h"
#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/json_util.h"
#include "core/kinematics/iso230_4.h"
#include "core/kinematics/measured_path.h"
#include "core/project/nominals.h"
#include "core/project/project.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/study/diagnosis_study.h"
#include "core/study/kinematic_study.h"
#include "core/study/setup_study.h"
#include "core/study/thermal_comparison.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "core/thermal/thermal_model.h"
#include "qtapp.h"
#include "table_cells.h"
#include "testsupport.h"
#include "widgets/document/projectdocument.h"
#include "widgets/importer/importdialog.h"
#include "widgets/report/report.h"
#include "widgets/thermal/thermalmodelview.h"

namespace metrofit {
namespace {

// The known formula: the spindle warms up as T(t) = 21 + 9 (1 - exp(-t / 1500 s)) °C and the
// Z displacement follows it linearly, d = kSlope (T - 21) - 0.8 µm.
constexpr double kSlope = 3.25;  // µm/°C
constexpr int kRows = 120;
constexpr int kStepS = 30;

double temperature(int row) {
  const double t = row * kStepS;
  // Rounded to the 4 decimals the file carries, so that the file's displacement is exact.
  return std::round((21.0 + 9.0 * (1.0 - std::exp(-t / 1500.0))) * 1e4) / 1e4;
}

double displacement(int row) {
  return kSlope * (temperature(row) - 21.0) - 0.8;
}

QString decimalComma(double v, int decimals) {
  return QString::number(v, 'f', decimals).replace(QLatin1Char('.'), QLatin1Char(','));
}

/// The log as a German spreadsheet exports it: a comment, ';' between fields, decimal commas.
QByteArray germanLog() {
  QByteArray text = "# Aufwärmversuch Spindel, Maschine 4\n";
  text += "Zeit [s];Temp Spindel;Verlagerung Z\n";
  for (int r = 0; r < kRows; ++r)
    text += QStringLiteral("%1;%2;%3\n")
                .arg(r * kStepS)
                .arg(decimalComma(temperature(r), 4), decimalComma(displacement(r), 6))
                .toUtf8();
  return text;
}

void writeFile(const QString& path, const QByteArray& text) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
  ASSERT_EQ(f.write(text), text.size());
}

QPushButton* importButton(ImportDialog& dialog) {
  auto* box = dialog.findChild<QDialogButtonBox*>();
  return box ? box->button(QDialogButtonBox::Ok) : nullptr;
}

class ImportDialogTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    doc_.saveAs(dir_.filePath(QStringLiteral("shop.metrofit")));
    logPath_ = dir_.filePath(QStringLiteral("data/aufwaermung.csv"));
    ASSERT_TRUE(QDir(dir_.path()).mkpath(QStringLiteral("data")));
    writeFile(logPath_, germanLog());
  }

  /// Imports the German log through the dialog as "spindel" and adds it to the document.
  DatasetRef importGermanLog() {
    ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
    dialog.setFile(logPath_);
    dialog.setKind(QStringLiteral("thermal-log"));
    dialog.setDelimiter(';');
    dialog.setDecimal(',');
    dialog.setRole(QStringLiteral("Zeit [s]"), QStringLiteral("time_s"));
    dialog.setRole(QStringLiteral("Temp Spindel"), QStringLiteral("T1"));
    dialog.setRole(QStringLiteral("Verlagerung Z"), QStringLiteral("disp_z_um"));
    dialog.setDatasetId(QStringLiteral("spindel"));
    EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
    QPushButton* ok = importButton(dialog);
    EXPECT_TRUE(ok && ok->isEnabled());
    if (ok) ok->click();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    doc_.addDataset(dialog.dataset());
    return dialog.dataset();
  }

  QTemporaryDir dir_;
  ProjectDocument doc_;
  QString logPath_;
};

TEST_F(ImportDialogTest, GuessesKindDialectAndTimeColumnOfAGermanLog) {
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(logPath_);
  EXPECT_EQ(dialog.kind(), QStringLiteral("thermal-log"));
  // The time column names its unit: read as time_s without being asked.
  EXPECT_EQ(dialog.role(QStringLiteral("Zeit [s]")), QStringLiteral("time_s"));
  const QString found = dialog.findChild<QLabel*>(QStringLiteral("importDetected"))->text();
  EXPECT_TRUE(found.contains(QStringLiteral("semicolon"))) << found.toStdString();
  EXPECT_TRUE(found.contains(QStringLiteral("line 2"))) << found.toStdString();
  EXPECT_TRUE(found.contains(QStringLiteral("comment lines: 1"))) << found.toStdString();
  EXPECT_TRUE(found.contains(QStringLiteral("data rows: %1").arg(kRows))) << found.toStdString();
  auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
  ASSERT_NE(preview, nullptr);
  EXPECT_EQ(preview->rowCount(), ImportDialog::kPreviewRows);
  EXPECT_EQ(preview->columnCount(), 3);
  EXPECT_EQ(preview->item(1, 1)->text(), decimalComma(temperature(1), 4));
  EXPECT_TRUE(preview->horizontalHeaderItem(0)->text().contains(QStringLiteral("→ time_s")));
  auto* mapping = dialog.findChild<QTableWidget*>(QStringLiteral("importMapping"));
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->rowCount(), 3);
  // Auto-detected dialect, nothing in the mapping but the time column.
  const CsvReadOptions csv = dialog.csvOptions();
  EXPECT_EQ(csv.dialect, CsvDialect{});
  ASSERT_EQ(csv.columnMap.size(), 1u);
  EXPECT_EQ(csv.columnMap[0], (std::pair<std::string, std::string>{"time_s", "Zeit [s]"}));
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().id, "aufwaermung");

  // Other kinds are guessed from the extension or the content.
  EXPECT_EQ(ImportDialog::guessKind(QStringLiteral("m.json"), "{}"), QStringLiteral("setup-model"));
  EXPECT_EQ(ImportDialog::guessKind(QStringLiteral("r.txt"), "FILNAM/'x',4.0\nDMISMN/'x',4.0\n"),
            QStringLiteral("dmis"));
  EXPECT_EQ(ImportDialog::guessKind(QStringLiteral("c.csv"), "x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm\n"),
            QStringLiteral("circular-test"));
  EXPECT_EQ(ImportDialog::guessKind(QStringLiteral("p.csv"), "id,qx,qy,qz,px,py,pz\n"),
            QStringLiteral("probe-points"));
}

TEST_F(ImportDialogTest, ImportedLogKeepsDialectAndMappingAndFitsTheKnownFormula) {
  const DatasetRef added = importGermanLog();
  ASSERT_EQ(doc_.project().datasets.size(), 1u);
  const DatasetRef d = doc_.project().datasets[0];  // a copy: saving replaces the list
  EXPECT_EQ(d, added);
  EXPECT_EQ(d.id, "spindel");
  EXPECT_EQ(d.kind, dataset_kind::kThermalLog);
  EXPECT_EQ(d.path, "data/aufwaermung.csv");  // the file itself, relative to the project
  EXPECT_EQ(d.csv.dialect.delimiter, ';');
  EXPECT_EQ(d.csv.dialect.decimal, ',');
  const std::vector<std::pair<std::string, std::string>> mapping{
      {"T1", "Temp Spindel"}, {"disp_z_um", "Verlagerung Z"}, {"time_s", "Zeit [s]"}};  // sorted by role
  EXPECT_EQ(d.csv.columnMap, mapping);
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Import dataset spindel"));

  // Saved and read back: the project keeps the mapping (no converted copy next to it).
  doc_.save();
  const Project saved = loadProject(QFile::encodeName(doc_.fileName()).toStdString());
  ASSERT_EQ(saved.datasets.size(), 1u);
  EXPECT_EQ(saved.datasets[0].csv, d.csv);
  EXPECT_EQ(QDir(dir_.path()).entryList(QDir::Files).size(), 1);  // shop.metrofit only

  // The navigator lists it under the thermal study.
  ProjectNavigator navigator(&doc_);
  bool listed = false;
  for (QTreeWidgetItemIterator it(&navigator); *it; ++it)
    listed = listed || (*it)->data(0, ProjectNavigator::DatasetRole).toString() == QStringLiteral("spindel");
  EXPECT_TRUE(listed);

  // The thermal page reads it with its dialect and mapping and picks the mapped target and input.
  ThermalPage page(&doc_);
  EXPECT_EQ(page.currentDataset(), QStringLiteral("spindel"));
  EXPECT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  const ThermalModelSettings settings = page.modelView()->settings();
  EXPECT_EQ(settings.target, "disp_z_um");
  EXPECT_EQ(settings.inputs, std::vector<std::string>{"T1"});

  // The linear model fitted as the model view fits it (thermal::fitAndEvaluate, the page's train
  // fraction) gives back the formula's slope.
  const ThermalLog log = readThermalLog(doc_.datasetPath(d).toStdString(), 3, d.csv);
  ASSERT_EQ(log.rows(), static_cast<std::size_t>(kRows));
  EXPECT_NEAR(log.timeMin.back(), (kRows - 1) * kStepS / 60.0, 1e-12);
  EXPECT_NEAR(log.channel("T1").values[5], temperature(5), 1e-12);
  EXPECT_NEAR(log.channel("disp_z_um").values[7], displacement(7), 1e-12);
  thermal::ThermalFitOptions options;
  options.model = thermal::ThermalModelKind::Linear;
  const thermal::ThermalEvaluation fit = thermal::fitAndEvaluate(
      thermal::selectThermalSeries(log, settings.target, settings.inputs), settings.trainFraction, options);
  const thermal::LagRegression& regression = fit.training.model.regression;
  ASSERT_EQ(regression.coef.size(), 1u);
  EXPECT_NEAR(regression.coef[0], kSlope, 1e-6);  // µm/°C
  EXPECT_LT(fit.heldout.rmse, 1e-5);              // µm
  ASSERT_EQ(fit.predicted.size(), static_cast<std::size_t>(kRows));
  EXPECT_NEAR(fit.predicted.back(), displacement(kRows - 1), 1e-5);

  // Train on the page declares the thermal study on the log (one undoable step), and the PDF report of
  // the project (what the GUI's Export report writes) then has its thermal section with the imported
  // log, its file in the appendix.
  EXPECT_TRUE(doc_.project().studies.value("thermal", nlohmann::json()).is_null());
  page.modelView()->trainButton()->click();
  EXPECT_EQ(doc_.project().studies.at("thermal").at("dataset"), "spindel");
  EXPECT_EQ(doc_.project().studies.at("thermal").at("target"), "disp_z_um");
  (void)QTest::qWaitFor([&] { return !page.modelView()->isRunning(); }, 60000);
  const QString pdf = QDir(dir_.path()).filePath(QStringLiteral("shop.pdf"));
  ReportOptions ro;
  ro.projectPath = doc_.fileName();
  ro.resolutionDpi = 150;
  const ReportSummary summary = writeReport(doc_.project(), pdf, ro);
  EXPECT_TRUE(summary.sections.contains(QStringLiteral("Thermal")))
      << summary.sections.join(',').toStdString();
  QProcess pdftotext;
  pdftotext.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
  ASSERT_TRUE(pdftotext.waitForFinished(60000));
  const QString text = QString::fromUtf8(pdftotext.readAllStandardOutput());
  EXPECT_TRUE(text.contains(QStringLiteral("data/aufwaermung.csv")));
  EXPECT_TRUE(text.contains(QStringLiteral("spindel")));

  // Undo takes the study back, then removes the dataset (and the page sees it gone); redo brings it
  // back unchanged.
  doc_.undoStack()->undo();
  EXPECT_FALSE(doc_.project().studies.contains("thermal") &&
               doc_.project().studies.at("thermal").contains("dataset"));
  doc_.undoStack()->undo();
  EXPECT_TRUE(doc_.project().datasets.empty());
  EXPECT_TRUE(page.currentDataset().isEmpty());
  doc_.undoStack()->redo();
  ASSERT_EQ(doc_.project().datasets.size(), 1u);
  EXPECT_EQ(doc_.project().datasets[0], added);
  EXPECT_EQ(page.currentDataset(), QStringLiteral("spindel"));
}

TEST_F(ImportDialogTest, BadFileShowsOneLineMessageAndKeepsImportDisabled) {
  const QString bad = dir_.filePath(QStringLiteral("kaputt.csv"));
  writeFile(bad, "Zeit [s];Temp Spindel;Verlagerung Z\n0;21,0;0,1\n30;abc;0,2\n60;21,4;0,3\n");
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(bad);
  EXPECT_FALSE(dialog.canImport());
  const QString problem = dialog.problem();
  EXPECT_FALSE(problem.contains(QLatin1Char('\n'))) << problem.toStdString();
  EXPECT_TRUE(problem.contains(QStringLiteral("kaputt.csv:3:"))) << problem.toStdString();
  EXPECT_TRUE(problem.contains(QStringLiteral("Temp Spindel"))) << problem.toStdString();
  EXPECT_TRUE(problem.contains(QStringLiteral("abc"))) << problem.toStdString();
  EXPECT_EQ(dialog.findChild<QLabel*>(QStringLiteral("importProblem"))->text(), problem);
  QPushButton* ok = importButton(dialog);
  ASSERT_NE(ok, nullptr);
  EXPECT_FALSE(ok->isEnabled());
  ok->click();  // a disabled button does nothing
  EXPECT_NE(dialog.result(), QDialog::Accepted);

  // A good file read as the wrong kind or with the wrong decimal mark is refused the same way.
  dialog.setFile(logPath_);
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  dialog.setKind(QStringLiteral("circular-test"));
  EXPECT_FALSE(dialog.canImport());
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("x_cmd_mm"))) << dialog.problem().toStdString();
  EXPECT_FALSE(importButton(dialog)->isEnabled());
  dialog.setKind(QStringLiteral("thermal-log"));
  dialog.setDecimal('.');
  EXPECT_FALSE(dialog.canImport());
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("aufwaermung.csv:3:")))
      << dialog.problem().toStdString();
  dialog.setDecimal(0);
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  // A mapped column the file does not have (a role given twice) and a duplicate id are refused.
  dialog.setRole(QStringLiteral("Temp Spindel"), QStringLiteral("time_s"));
  EXPECT_FALSE(dialog.canImport());
  dialog.setRole(QStringLiteral("Temp Spindel"), QString());
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  importGermanLog();
  ImportDialog again(doc_.project(), doc_.projectPathForDatasets());
  again.setFile(logPath_);
  again.setDatasetId(QStringLiteral("spindel"));
  EXPECT_FALSE(again.canImport());
  EXPECT_TRUE(again.problem().contains(QStringLiteral("already has a dataset 'spindel'")))
      << again.problem().toStdString();
  again.setDatasetId(QString());
  EXPECT_TRUE(again.canImport());
  EXPECT_EQ(again.dataset().id, "aufwaermung");
  // Unreadable file.
  again.setFile(dir_.filePath(QStringLiteral("missing.csv")));
  EXPECT_FALSE(again.canImport());
  EXPECT_TRUE(again.problem().contains(QStringLiteral("missing.csv"))) << again.problem().toStdString();
}

TEST_F(ImportDialogTest, RemoveRenameAndRelinkAreUndoable) {
  importGermanLog();
  doc_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/dataset"), "spindel", QStringLiteral("x"));
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal/dataset"), "spindel",
                     QStringLiteral("x"));
  const Project before = doc_.project();
  EXPECT_EQ(doc_.datasetReferences(QStringLiteral("spindel")),
            (QStringList{QStringLiteral("studies.diagnosis.thermal.dataset"),
                         QStringLiteral("studies.thermal.dataset")}));

  // Rename: the studies follow; one undo step back.
  doc_.renameDataset(QStringLiteral("spindel"), QStringLiteral("spindle_warmup"));
  EXPECT_EQ(doc_.project().datasets[0].id, "spindle_warmup");
  EXPECT_EQ(doc_.studyValue(QStringLiteral("thermal"), QStringLiteral("/dataset")), "spindle_warmup");
  EXPECT_EQ(doc_.studyValue(QStringLiteral("diagnosis"), QStringLiteral("/thermal/dataset")),
            "spindle_warmup");
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project(), before);
  doc_.undoStack()->redo();
  EXPECT_EQ(doc_.project().datasets[0].id, "spindle_warmup");
  doc_.undoStack()->undo();

  // A rename to an id the project has, or to nothing, is refused with a message; nothing changes.
  DatasetRef other = doc_.project().datasets[0];
  other.id = "other";
  doc_.addDataset(other);
  const int steps = doc_.undoStack()->count();
  try {
    doc_.renameDataset(QStringLiteral("spindel"), QStringLiteral("other"));
    ADD_FAILURE() << "a duplicate id was accepted";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("already has a dataset 'other'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(doc_.renameDataset(QStringLiteral("spindel"), QStringLiteral("  ")), ValidationError);
  EXPECT_THROW(doc_.renameDataset(QStringLiteral("nope"), QStringLiteral("x")), ValidationError);
  EXPECT_EQ(doc_.undoStack()->count(), steps);
  doc_.undoStack()->undo();  // the second dataset
  EXPECT_EQ(doc_.project(), before);

  // Remove: the dataset and the settings naming it go in one step; undo restores both.
  doc_.removeDataset(QStringLiteral("spindel"));
  EXPECT_TRUE(doc_.project().datasets.empty());
  EXPECT_TRUE(doc_.studyValue(QStringLiteral("thermal"), QStringLiteral("/dataset")).is_null());
  EXPECT_TRUE(doc_.datasetReferences(QStringLiteral("spindel")).isEmpty());
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Remove dataset spindel"));
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project(), before);
  doc_.undoStack()->redo();
  EXPECT_TRUE(doc_.project().datasets.empty());
  doc_.undoStack()->undo();

  // Re-link: the file moved; the dataset points at it again, relative to the project.
  const QString moved = dir_.filePath(QStringLiteral("archive/log.csv"));
  ASSERT_TRUE(QDir(dir_.path()).mkpath(QStringLiteral("archive")));
  ASSERT_TRUE(QFile::rename(logPath_, moved));
  EXPECT_FALSE(QFile::exists(doc_.datasetPath(doc_.project().datasets[0])));
  // A file that cannot be read as a thermal log with this mapping is refused; nothing changes.
  const QString wrong = dir_.filePath(QStringLiteral("archive/other.csv"));
  writeFile(wrong, "a;b\n1;2\n");
  try {
    doc_.relinkDataset(QStringLiteral("spindel"), wrong);
    ADD_FAILURE() << "a file without the mapped columns was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("other.csv"), std::string::npos) << e.what();
  }
  EXPECT_EQ(doc_.project(), before);
  doc_.relinkDataset(QStringLiteral("spindel"), moved);
  EXPECT_EQ(doc_.project().datasets[0].path, "archive/log.csv");
  EXPECT_EQ(doc_.project().datasets[0].csv, before.datasets[0].csv);
  EXPECT_TRUE(QFile::exists(doc_.datasetPath(doc_.project().datasets[0])));
  EXPECT_EQ(doc_.undoStack()->undoText(), QStringLiteral("Re-link dataset spindel"));
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project(), before);
  doc_.undoStack()->redo();
  EXPECT_EQ(doc_.project().datasets[0].path, "archive/log.csv");
}

TEST_F(ImportDialogTest, FilesThatAreNotCsvAreImportedWithoutDialectOrMapping) {
  const QString source = QString::fromStdString(test::sourceDir().string());
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(source + QStringLiteral("/fuzz/corpus/hole_table/excerpt.txt"));
  EXPECT_EQ(dialog.kind(), QStringLiteral("hole-table"));
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_FALSE(dialog.findChild<QComboBox*>(QStringLiteral("importDelimiter"))->isEnabled());
  EXPECT_FALSE(dialog.findChild<QTableWidget*>(QStringLiteral("importMapping"))->isEnabled());
  EXPECT_EQ(dialog.dataset().kind, dataset_kind::kHoleTable);
  EXPECT_EQ(dialog.dataset().csv, CsvReadOptions{});
  // The preview shows the holes as the studies read them (the dataset's Show data table), not the
  // file's lines: the first hole's nominal X 11.650 and measured X 11.610 (the file's first data line).
  auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
  EXPECT_GT(preview->columnCount(), 1);
  QStringList firstRow;
  for (int c = 0; c < preview->columnCount(); ++c) firstRow << preview->item(0, c)->text();
  const QString shown = firstRow.join(QLatin1Char('|'));
  EXPECT_FALSE(shown.contains(QStringLiteral("Plug Plate"))) << shown.toStdString();
  EXPECT_TRUE(shown.contains(QLocale().toString(11.65)) && shown.contains(QLocale().toString(11.61)))
      << shown.toStdString();
  EXPECT_TRUE(dialog.findChild<QGroupBox*>(QStringLiteral("importMappingBox"))->isHidden());

  dialog.setFile(source + QStringLiteral("/fuzz/corpus/dmis/part_17.dmo"));
  EXPECT_EQ(dialog.kind(), QStringLiteral("dmis"));  // by its content: DMISMN
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().kind, dataset_kind::kDmis);
  // The same DMIS file read as a thermal log is refused.
  dialog.setKind(QStringLiteral("thermal-log"));
  EXPECT_FALSE(dialog.canImport());
  EXPECT_FALSE(importButton(dialog)->isEnabled());
}

// An MTConnect SHDR log (the real OKUMA log of ../shared/data/real/mtconnect-samples, with its Devices.xml
// beside it) is guessed as kind mtconnect, previewed as its resampled table (time_min and one column per
// numeric sample, not the raw lines), resampled to the interval of the spin box (seconds), which the
// dataset keeps (minutes).
TEST_F(ImportDialogTest, AnMtconnectLogIsPreviewedAsItsResampledTable) {
  const QString file = QString::fromStdString(test::realData("mtconnect-samples/okuma.txt").string());
  METROFIT_REQUIRE_PATH(file.toStdString());
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(file);
  EXPECT_EQ(dialog.kind(), QStringLiteral("mtconnect"));
  EXPECT_TRUE(dialog.isMtconnectLog());
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  auto* interval = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("importSampleInterval"));
  ASSERT_NE(interval, nullptr);
  EXPECT_FALSE(interval->isHidden());
  EXPECT_EQ(interval->value(), 1.0);
  EXPECT_FALSE(dialog.findChild<QComboBox*>(QStringLiteral("importDelimiter"))->isEnabled());
  auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
  ASSERT_GT(preview->columnCount(), 3);
  EXPECT_EQ(preview->horizontalHeaderItem(0)->text(), QStringLiteral("time_min"));
  QStringList headers;
  for (int c = 0; c < preview->columnCount(); ++c) headers << preview->horizontalHeaderItem(c)->text();
  for (const char* key : {"S1speed", "X1actm", "Z1actm"})
    EXPECT_TRUE(headers.contains(QLatin1String(key))) << key;
  EXPECT_FALSE(headers.contains(QStringLiteral("system")));
  bool ok = false;
  EXPECT_NEAR(preview->item(1, 0)->text().toDouble(&ok), 1.0 / 60.0,
              1e-12);  // 1 s: the second row at 1/60 min
  EXPECT_TRUE(ok) << preview->item(1, 0)->text().toStdString();
  EXPECT_EQ(dialog.dataset().kind, dataset_kind::kMtconnect);
  EXPECT_EQ(dialog.dataset().csv.sampleIntervalMin, 0.0);  // the default grid is not stored
  // A 30 s grid: the preview's second row at 0.5 min, the dataset keeps it in minutes.
  dialog.setSampleIntervalS(30.0);
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_NEAR(preview->item(1, 0)->text().toDouble(&ok), 0.5, 1e-12);
  EXPECT_TRUE(ok) << preview->item(1, 0)->text().toStdString();
  EXPECT_DOUBLE_EQ(dialog.dataset().csv.sampleIntervalMin, 0.5);
  EXPECT_NE(dialog.findChild<QLabel*>(QStringLiteral("importDetected"))->text().indexOf(QStringLiteral("30")),
            -1);
  // A CSV thermal log: no interval box.
  dialog.setFile(logPath_);
  EXPECT_FALSE(dialog.isMtconnectLog());
  EXPECT_TRUE(interval->isHidden());
}

// CMM text reports are recognised by content and imported without dialect or mapping: a real OGP
// step report wrapped in RTF (../shared/data/real/cmm-ogp-hps-svt, GPL-3.0, read in place) and a
// PC-DMIS text report written here from the PC-DMIS help ("Dimension Command Format").
TEST_F(ImportDialogTest, CmmTextReportsAreImportedWithoutOptions) {
  const std::string pcdmis =
      "DIM LOC1= LOCATION OF CIRCLE CIR1  UNITS=MM ,$\n"
      "GRAPH=OFF  TEXT=OFF  MULT=10.00  OUTPUT=BOTH  HALF ANGLE=NO\n"
      "AX    NOMINAL       +TOL       -TOL       MEAS        DEV     OUTTOL\n"
      "X      10.000      0.050      0.050     10.012      0.012      0.000 ----#----\n"
      "END OF DIMENSION LOC1\n";
  EXPECT_EQ(ImportDialog::guessKind(QStringLiteral("r.txt"), QByteArray::fromStdString(pcdmis)),
            QStringLiteral("cmm-report"));
  const QString real = QString::fromStdString(
      test::realData("cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt").string());
  METROFIT_REQUIRE_PATH(real.toStdString());
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(real);
  EXPECT_EQ(dialog.kind(), QStringLiteral("cmm-report"));
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_FALSE(dialog.findChild<QComboBox*>(QStringLiteral("importDelimiter"))->isEnabled());
  EXPECT_FALSE(dialog.findChild<QTableWidget*>(QStringLiteral("importMapping"))->isEnabled());
  EXPECT_EQ(dialog.dataset().kind, dataset_kind::kCmmReport);
  EXPECT_EQ(dialog.dataset().csv, CsvReadOptions{});
  // The same report as a feature series (one row per run) is accepted too.
  dialog.setKind(QStringLiteral("feature-series"));
  EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().kind, dataset_kind::kFeatureSeries);
}

TEST_F(ImportDialogTest, MappedCircularTestIsReadAlikeByKinematicsAndDiagnosis) {
  // The demo's circular test as a German export: ';', decimal commas, its own column names.
  QFile demo(QString::fromStdString((test::sourceDir() / "resources/demo/data/circular_demo.csv").string()));
  ASSERT_TRUE(demo.open(QIODevice::ReadOnly));
  QByteArray german;
  int rows = 0;
  for (QByteArray line : demo.readAll().split('\n')) {
    if (line.isEmpty() || line.startsWith('#')) {
      german += line + '\n';
    } else if (line.startsWith("x_cmd_mm")) {
      german += "X soll [mm];Y soll [mm];X ist [mm];Y ist [mm]\n";
    } else {
      german += line.replace(',', ';').replace('.', ',') + '\n';
      ++rows;
    }
  }
  const QString file = dir_.filePath(QStringLiteral("kreisform.csv"));
  writeFile(file, german);
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(file);
  dialog.setKind(QStringLiteral("circular-test"));
  EXPECT_FALSE(dialog.canImport());  // the readers' columns are not there yet
  dialog.setRole(QStringLiteral("X soll [mm]"), QStringLiteral("x_cmd_mm"));
  dialog.setRole(QStringLiteral("Y soll [mm]"), QStringLiteral("y_cmd_mm"));
  dialog.setRole(QStringLiteral("X ist [mm]"), QStringLiteral("x_meas_mm"));
  dialog.setRole(QStringLiteral("Y ist [mm]"), QStringLiteral("y_meas_mm"));
  dialog.setDatasetId(QStringLiteral("kreis"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  doc_.addDataset(dialog.dataset());
  ImportDialog original(doc_.project(), doc_.projectPathForDatasets());
  original.setFile(demo.fileName());
  EXPECT_EQ(original.kind(), QStringLiteral("circular-test"));
  ASSERT_TRUE(original.canImport()) << original.problem().toStdString();
  doc_.addDataset(original.dataset());

  // The kinematics study reads both alike: the same identification to the last bit.
  const auto resolve = [this](const DatasetRef& d) {
    return QFile::encodeName(doc_.datasetPath(d)).toStdString();
  };
  const KinematicStudyData mapped = loadKinematicStudy(doc_.project(), resolve, "kreis");
  const KinematicStudyData plain = loadKinematicStudy(doc_.project(), resolve, "circular_demo");
  ASSERT_EQ(mapped.measured.size(), static_cast<std::size_t>(rows));
  EXPECT_EQ(rows, 720);
  EXPECT_EQ(mapped.measured.measured, plain.measured.measured);
  EXPECT_EQ(mapped.identification.errors.originMm, plain.identification.errors.originMm);
  EXPECT_EQ(mapped.identification.errors.xAxisAngleDeg, plain.identification.errors.xAxisAngleDeg);
  // The simulated machine of the demo file's header: origin (0.004, -0.003) mm.
  EXPECT_NEAR(mapped.identification.errors.originMm.x(), 0.004, 2e-4);
  EXPECT_NEAR(mapped.identification.errors.originMm.y(), -0.003, 2e-4);

  // The diagnosis reads the dataset with its dialect and mapping too.
  doc_.setStudyValue(QStringLiteral("diagnosis"), QStringLiteral("/kinematic/dataset"), "kreis",
                     QStringLiteral("x"));
  const DiagnosisSettings s = diagnosisSettings(
      doc_.project(), QFile::encodeName(doc_.fileName()).toStdString(), DiagnosisDomain::Kinematic);
  EXPECT_EQ(s.csv, doc_.project().dataset("kreis")->csv);
  EXPECT_EQ(readMeasuredPath(s.datasetPath, s.csv).measured, plain.measured.measured);
}

/// Runs `handle` on the next modal dialog of type T as soon as it is shown.
template <typename T>
void onNextModal(QObject* owner, std::function<void(T*)> handle) {
  auto* timer = new QTimer(owner);
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, handle] {
    if (auto* dialog = qobject_cast<T*>(QApplication::activeModalWidget())) {
      timer->stop();
      timer->deleteLater();
      handle(dialog);
    }
  });
  timer->start();
}

TEST_F(ImportDialogTest, BallbarExportIsACircularTestByItsRoles) {
  // A ballbar export from a German spreadsheet (docs/file-formats.md#circular-test, radial-only form):
  // angle, radial deviation in um, direction, with its own column names; 360 points CCW, then 360 CW,
  // an offset circle of 5 um with a 3-lobe form of 2 um: G = 4 um per direction.
  QByteArray text = "Winkel [Grad];Abweichung [um];Richtung\n";
  for (int loop = 0; loop < 2; ++loop) {
    for (int k = 0; k < 360; ++k) {
      const double th = (loop == 0 ? k : 360 - k) * M_PI / 180.0;
      const double dev = 5.0 * std::cos(th) + 2.0 * std::cos(3.0 * th);
      text += QByteArray::number(loop == 0 ? k : 360 - k) + ';' +
              QByteArray::number(dev, 'f', 6).replace('.', ',') + ';' + (loop == 0 ? "GUZ" : "UZ") + '\n';
    }
  }
  text.replace("GUZ", "ccw").replace(";UZ", ";cw");
  const QString file = dir_.filePath(QStringLiteral("ballbar.csv"));
  writeFile(file, text);
  EXPECT_EQ(ImportDialog::guessKind(file, text.left(200)), QStringLiteral("circular-test"));
  EXPECT_TRUE(
      ImportDialog::rolesForKind(QStringLiteral("circular-test")).contains(QStringLiteral("deviation_um")));
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(file);
  EXPECT_EQ(dialog.kind(), QStringLiteral("circular-test"));
  // The German names are mapped to the readers' roles without being asked (core/project/import_guess.h).
  EXPECT_EQ(dialog.role(QStringLiteral("Winkel [Grad]")), QStringLiteral("angle_deg"));
  EXPECT_EQ(dialog.role(QStringLiteral("Abweichung [um]")), QStringLiteral("deviation_um"));
  EXPECT_EQ(dialog.role(QStringLiteral("Richtung")), QStringLiteral("direction"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  doc_.addDataset(dialog.dataset());
  const DatasetRef* ref = doc_.project().dataset("ballbar");
  ASSERT_NE(ref, nullptr);
  const CircularTrace trace =
      readCircularTrace(QFile::encodeName(doc_.datasetPath(*ref)).toStdString(), ref->csv);
  EXPECT_TRUE(trace.radialOnly);
  ASSERT_EQ(trace.size(), 720u);
  const Iso230Result iso = evaluateIso230_4(trace);
  ASSERT_EQ(iso.directions.size(), 2u);
  for (const Iso230Direction& d : iso.directions) EXPECT_NEAR(d.circularDeviationMm, 0.004, 1e-6);
  // The kinematic identification refuses it with the file named.
  try {
    (void)loadKinematicStudy(
        doc_.project(),
        [this](const DatasetRef& d) { return QFile::encodeName(doc_.datasetPath(d)).toStdString(); },
        "ballbar");
    FAIL() << "identified a radial-only test";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ballbar.csv: is a radial-only circular test"), std::string::npos)
        << e.what();
  }
}

TEST_F(ImportDialogTest, ContextMenuRenamesAndRemovesAfterAsking) {
  importGermanLog();
  doc_.setStudyValue(QStringLiteral("thermal"), QStringLiteral("/dataset"), "spindel", QStringLiteral("x"));
  QWidget parent;
  QMenu menu;
  addDatasetActions(&menu, &doc_, QStringLiteral("spindel"), &parent);
  QStringList names;
  for (QAction* a : menu.actions())
    if (!a->isSeparator()) names << a->objectName();
  EXPECT_EQ(names, (QStringList{QStringLiteral("showDatasetData"), QStringLiteral("renameDataset"),
                                QStringLiteral("relinkDataset"), QStringLiteral("removeDataset")}));

  // Rename: the new id typed into the question; the study follows.
  onNextModal<QInputDialog>(&parent, [](QInputDialog* d) {
    d->setTextValue(QStringLiteral("warmup"));
    d->accept();
  });
  EXPECT_TRUE(renameDatasetAsking(&doc_, QStringLiteral("spindel"), &parent));
  EXPECT_EQ(doc_.project().datasets[0].id, "warmup");
  EXPECT_EQ(doc_.studyValue(QStringLiteral("thermal"), QStringLiteral("/dataset")), "warmup");

  // Remove: the question names the setting that goes with it; "No" keeps everything.
  QString question;
  onNextModal<QMessageBox>(&parent, [&question](QMessageBox* box) {
    question = box->text();
    box->button(QMessageBox::No)->click();
  });
  EXPECT_FALSE(removeDatasetAsking(&doc_, QStringLiteral("warmup"), &parent));
  EXPECT_TRUE(question.contains(QStringLiteral("studies.thermal.dataset"))) << question.toStdString();
  EXPECT_EQ(doc_.project().datasets.size(), 1u);
  onNextModal<QMessageBox>(&parent, [](QMessageBox* box) { box->button(QMessageBox::Yes)->click(); });
  EXPECT_TRUE(removeDatasetAsking(&doc_, QStringLiteral("warmup"), &parent));
  EXPECT_TRUE(doc_.project().datasets.empty());
  doc_.undoStack()->undo();
  EXPECT_EQ(doc_.project().datasets[0].id, "warmup");
}

TEST_F(ImportDialogTest, DroppedFileOpensTheDialogAndIsImportedUndoably) {
  MainWindow window;
  window.document()->saveAs(dir_.filePath(QStringLiteral("window.metrofit")));
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  // File › Import data… is there with Ctrl+I.
  auto* action = window.findChild<QAction*>(QStringLiteral("importData"));
  ASSERT_NE(action, nullptr);
  EXPECT_EQ(action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_I));
  EXPECT_TRUE(window.acceptDrops());

  QMimeData mime;
  mime.setUrls({QUrl::fromLocalFile(logPath_)});
  QDragEnterEvent enter(QPoint(20, 20), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&window, &enter);
  EXPECT_TRUE(enter.isAccepted());
  // The dialog opens after the drop; map the columns in it and press Import.
  QString shownFile;
  auto* timer = new QTimer(&window);
  timer->setInterval(20);
  QObject::connect(timer, &QTimer::timeout, [timer, &shownFile] {
    auto* dialog = qobject_cast<ImportDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    timer->stop();
    shownFile = dialog->file();
    dialog->setRole(QStringLiteral("Temp Spindel"), QStringLiteral("T1"));
    dialog->setRole(QStringLiteral("Verlagerung Z"), QStringLiteral("disp_z_um"));
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
  });
  timer->start();
  QDropEvent drop(QPointF(20, 20), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&window, &drop);
  ASSERT_TRUE(QTest::qWaitFor([&] { return !window.document()->project().datasets.empty(); }, 10000));
  EXPECT_EQ(QFileInfo(shownFile), QFileInfo(logPath_));
  const DatasetRef d = window.document()->project().datasets[0];
  EXPECT_EQ(d.id, "aufwaermung");
  EXPECT_EQ(d.path, "data/aufwaermung.csv");
  const std::vector<std::pair<std::string, std::string>> mapping{
      {"T1", "Temp Spindel"}, {"disp_z_um", "Verlagerung Z"}, {"time_s", "Zeit [s]"}};  // sorted by role
  EXPECT_EQ(d.csv.columnMap, mapping);
  EXPECT_EQ(d.csv.dialect, CsvDialect{});          // detected when read, as the CLI's default
  EXPECT_EQ(window.currentPage(), Page::Thermal);  // shown where it is used
  EXPECT_EQ(window.thermalPage()->currentDataset(), QStringLiteral("aufwaermung"));
  EXPECT_TRUE(window.thermalPage()->errorMessage().isEmpty())
      << window.thermalPage()->errorMessage().toStdString();
  window.document()->undoStack()->undo();
  EXPECT_TRUE(window.document()->project().datasets.empty());
  window.document()->undoStack()->setClean();
}

// DMIS output written from the statement syntax of the standard: POS_D1 as nominal and actual point
// (deviation FA - F along z = 0.008 mm), D2 only as a tolerance actual, TA(D2)=TOL/DIAM,18.52 -- the
// actual diameter (nominal 18.5), as the QIF-to-DMIS converter writes it.
constexpr const char* kDmisModel = R"({"name": "small", "step_mm": 0.001, "bounds_mm": [-0.1, 0.1],
  "setup": [{"id": "W1", "kind": "wks"}, {"id": "T5", "kind": "tool"}],
  "features": [{"id": "F1"}, {"id": "F2"}],
  "dimensions": [{"id": "D1", "nominal": 42.0, "lower": -0.02, "upper": 0.02, "label": "POS_D1"},
                 {"id": "D2", "nominal": 18.5, "lower": -0.05, "upper": 0.03}],
  "arcs": [{"from": "W1", "to": "F1", "weight": 1}, {"from": "T5", "to": "F1", "weight": 1},
           {"from": "W1", "to": "F2", "weight": -1}, {"from": "F1", "to": "D1", "weight": 1},
           {"from": "F1", "to": "D2", "weight": 1}, {"from": "F2", "to": "D2", "weight": -1}]})";
constexpr const char* kDmisPart =
    "DMISMN/'part 7',05.3\n"
    "UNITS/MM,ANGDEG\n"
    "F(POS_D1)=FEAT/POINT,CART,10,20,42,0,0,1\n"
    "FA(POS_D1)=FEAT/POINT,CART,10,20,42.008,0,0,1\n"
    "TA(D2)=TOL/DIAM,18.52,INTOL\n"
    "ENDFIL\n";

TEST_F(ImportDialogTest, DmisTaMeaningIsChosenInTheDialogAndUsedByTheSetupStudy) {
  writeFile(dir_.filePath(QStringLiteral("m.json")), kDmisModel);
  writeFile(dir_.filePath(QStringLiteral("part7.dmi")), kDmisPart);
  {
    ImportDialog model(doc_.project(), doc_.projectPathForDatasets());
    model.setFile(dir_.filePath(QStringLiteral("m.json")));
    ASSERT_TRUE(model.canImport()) << model.problem().toStdString();
    doc_.addDataset(model.dataset());
  }
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  // A CSV file has no TA controls.
  dialog.setFile(logPath_);
  EXPECT_FALSE(dialog.isDmisFile());
  EXPECT_FALSE(dialog.findChild<QWidget*>(QStringLiteral("importDmis"))->isVisibleTo(&dialog));
  dialog.setFile(dir_.filePath(QStringLiteral("part7.dmi")));
  EXPECT_EQ(dialog.kind(), QStringLiteral("dmis"));
  EXPECT_TRUE(dialog.isDmisFile());
  EXPECT_TRUE(dialog.findChild<QWidget*>(QStringLiteral("importDmis"))->isVisibleTo(&dialog));
  auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
  auto* found = dialog.findChild<QLabel*>(QStringLiteral("importDetected"));
  // Read as a deviation, 18.52 mm is far outside D2's band: the preview says so, naming TA(D2).
  dialog.setTaMeaning(QStringLiteral("deviation"));
  EXPECT_TRUE(found->text().contains(QStringLiteral("TA(D2)"))) << found->text().toStdString();
  // Read as the actual value: D2's deviation is 18.52 - 18.5.
  dialog.setTaMeaning(QStringLiteral("actual"));
  ASSERT_EQ(preview->rowCount(), 2) << found->text().toStdString();
  EXPECT_EQ(preview->item(1, 0)->text(), QStringLiteral("D2"));
  EXPECT_NEAR(test::cellNumber(preview, 1, 1), 0.02, 1e-9);
  EXPECT_NEAR(test::cellNumber(preview, 0, 1), 0.008, 1e-9);
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().dmis.taMeaning, setup::DmisTaMeaning::Actual);
  EXPECT_FALSE(dialog.dataset().dmis.signFollowsNominal);
  importButton(dialog)->click();
  ASSERT_EQ(dialog.result(), QDialog::Accepted);
  doc_.addDataset(dialog.dataset());
  doc_.save();
  // The saved project says how the file is read, and the setup study reads it that way.
  const nlohmann::json saved = readJsonFile(doc_.fileName().toStdString());
  EXPECT_EQ(saved["datasets"][1]["dmis"], (nlohmann::json{{"ta_meaning", "actual"}}));
  const Project reopened = loadProject(doc_.fileName().toStdString());
  const SetupStudyFiles files = setupStudyFiles(reopened, doc_.fileName().toStdString());
  EXPECT_EQ(files.reportId, "part7");
  const setup::Model model = setup::readModel(files.modelPath);
  const setup::Measurements m =
      setup::readMeasurements({files.reportPath}, model, files.reportCsv, files.reportDmis);
  EXPECT_NEAR(m.deviationMm[0], 0.008, 1e-12);
  EXPECT_NEAR(m.deviationMm[1], 18.52 - 18.5, 1e-12);
}

// A log with an instrument preamble (two lines, then a '%' comment) and two unreadable rows: line 6
// ('n/a' in T1) and line 8 (a field missing).
constexpr const char* kPreambleLog =
    "Thermal test rig 3\n"
    "Operator: K.\n"
    "% sensors calibrated\n"
    "time_min,T1,disp_z_um\n"
    "0,20.0,0.0\n"
    "10,n/a,1.5\n"
    "20,21.0,2.5\n"
    "30,21.5\n"
    "40,22.0,4.0\n";

TEST_F(ImportDialogTest, HeaderOverrideAndEveryUnreadableRowIsListed) {
  const QString path = dir_.filePath(QStringLiteral("rig.csv"));
  writeFile(path, kPreambleLog);
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(path);
  EXPECT_FALSE(dialog.canImport());  // detected: the preamble is taken for the header
  dialog.setKind(QStringLiteral("thermal-log"));
  dialog.setHeaderLines(2);
  dialog.setCommentPrefix(QStringLiteral("%"));
  // Both bad rows are listed, with line, row, column and why; strict, the first is the problem.
  EXPECT_EQ(dialog.rowProblems(),
            (QStringList{QStringLiteral("line 6 (row 2), column 'T1': 'n/a' is not a number"),
                         QStringLiteral("line 8 (row 4): row has 2 fields, the header (line 4) has 3")}));
  EXPECT_FALSE(dialog.canImport());
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("rig.csv:6:2: field 'T1'")))
      << dialog.problem().toStdString();
  EXPECT_FALSE(importButton(dialog)->isEnabled());
  // The preview shows the readable rows.
  auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
  EXPECT_EQ(preview->rowCount(), 3);
  EXPECT_EQ(preview->item(2, 0)->text(), QStringLiteral("40"));
  // A picture of the dialog in this state, to look at (the list under the preview, the problem line).
  dialog.show();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);  // replaced mapping widgets
  QApplication::processEvents();
  dialog.grab().save(QString::fromStdString((test::outDir() / "import_dialog_unreadable_rows.png").string()));
  dialog.setSkipBadRows(true);
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_TRUE(
      dialog.findChild<QLabel*>(QStringLiteral("importProblem"))->text().contains(QStringLiteral("2")));
  const CsvReadOptions o = dialog.dataset().csv;
  EXPECT_EQ(o.headerLines, 2);
  EXPECT_EQ(o.commentPrefix, "%");
  EXPECT_TRUE(o.skipBadRows);
  importButton(dialog)->click();
  ASSERT_EQ(dialog.result(), QDialog::Accepted);
  doc_.addDataset(dialog.dataset());
  // The thermal log read the way the project says: three rows, time 0, 20, 40 min.
  const ThermalLog log = readThermalLog(resolveDatasetPath(doc_.fileName().toStdString(), dialog.dataset()),
                                        3, dialog.dataset().csv);
  EXPECT_EQ(log.rows(), 3u);
}

TEST_F(ImportDialogTest, EmbedCopiesIntoTheDataFolderAndRefusesToOverwrite) {
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  const QString outside = dir_.filePath(QStringLiteral("elsewhere/Messung.CSV"));
  ASSERT_TRUE(QDir(dir_.path()).mkpath(QStringLiteral("elsewhere")));
  writeFile(outside, germanLog());
  dialog.setFile(outside);
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().path, "elsewhere/Messung.CSV");  // the default links
  // data/aufwaermung.csv exists: an embedded copy with that id is refused, nothing is written.
  dialog.setDatasetId(QStringLiteral("aufwaermung"));
  dialog.setEmbed(true);
  EXPECT_FALSE(dialog.canImport());
  EXPECT_TRUE(dialog.problem().contains(QStringLiteral("already exists"))) << dialog.problem().toStdString();
  dialog.setDatasetId(QStringLiteral("messung"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  importButton(dialog)->click();
  ASSERT_EQ(dialog.result(), QDialog::Accepted);
  EXPECT_EQ(dialog.dataset().path, "data/messung.csv");
  QFile copy(dir_.filePath(QStringLiteral("data/messung.csv")));
  ASSERT_TRUE(copy.open(QIODevice::ReadOnly));
  EXPECT_EQ(copy.readAll(), germanLog());
  doc_.addDataset(dialog.dataset());
  EXPECT_EQ(test::readText(resolveDatasetPath(doc_.fileName().toStdString(), doc_.project().datasets.back())),
            germanLog().toStdString());
  // A copy that appears between the check and the click is not overwritten either: the dialog stays open.
  ImportDialog late(doc_.project(), doc_.projectPathForDatasets());
  late.setFile(outside);
  late.setDatasetId(QStringLiteral("late"));
  late.setEmbed(true);
  ASSERT_TRUE(late.canImport()) << late.problem().toStdString();
  writeFile(dir_.filePath(QStringLiteral("data/late.csv")), "x\n");
  importButton(late)->click();
  EXPECT_NE(late.result(), QDialog::Accepted);
  EXPECT_TRUE(late.problem().contains(QStringLiteral("already exists"))) << late.problem().toStdString();
  QFile lateFile(dir_.filePath(QStringLiteral("data/late.csv")));
  ASSERT_TRUE(lateFile.open(QIODevice::ReadOnly));
  EXPECT_EQ(lateFile.readAll(), QByteArray("x\n"));
  // An untitled project cannot embed (no folder yet).
  ProjectDocument untitled;
  ImportDialog unsaved(untitled.project(), untitled.projectPathForDatasets());
  EXPECT_FALSE(unsaved.findChild<QWidget*>(QStringLiteral("importEmbed"))->isEnabled());
}

// Issue 28 item 1: files as German and Polish shops write them, written here from those conventions.
constexpr const char* kTitledGermanLog =
    "Spindel-W\xC3\xA4rmegang DMU 50, Messung vom 01.05.2024\n"
    "Zeit [min];Temperatur T1 [\xC2\xB0"
    "C];Verlagerung K3 [\xC2\xB5m];Drehzahl [1/min]\n"
    "0;20,5;0,0;0\n"
    "0,25;20,7;1,25;1250\n"
    "0,5;21,0;2,5;1250\n"
    "0,75;21,2;3,0;1250\n";

TEST_F(ImportDialogTest, ATitleLineAboveAGermanHeaderIsFoundAndTheRolesAreMapped) {
  const QString path = dir_.filePath(QStringLiteral("Spindel_Waermegang.csv"));
  writeFile(path, kTitledGermanLog);
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(path);
  EXPECT_EQ(dialog.kind(), QStringLiteral("thermal-log"));
  EXPECT_EQ(dialog.role(QStringLiteral("Zeit [min]")), QStringLiteral("time_min"));
  EXPECT_EQ(dialog.role(QStringLiteral("Drehzahl [1/min]")), QStringLiteral("spindle_rpm"));
  EXPECT_EQ(dialog.role(QStringLiteral("Verlagerung K3 [\xC2\xB5m]")), QString());
  EXPECT_TRUE(dialog.rowProblems().isEmpty()) << dialog.rowProblems().join(QLatin1Char('\n')).toStdString();
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  const QString found = dialog.findChild<QLabel*>(QStringLiteral("importDetected"))->text();
  EXPECT_TRUE(found.contains(QStringLiteral("line 2"))) << found.toStdString();
  // A picture to look at: the title line skipped, the roles mapped, the preview in the file's units.
  dialog.show();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  QApplication::processEvents();
  dialog.grab().save(QString::fromStdString((test::outDir() / "import_dialog_german_title.png").string()));

  // Forcing the title to be the header makes it another kind; back to the right line, the kind and the
  // roles are guessed again.
  dialog.setHeaderLines(0);
  EXPECT_EQ(dialog.kind(), QStringLiteral("feature-series"));
  dialog.setHeaderLines(1);
  EXPECT_EQ(dialog.kind(), QStringLiteral("thermal-log"));
  EXPECT_EQ(dialog.role(QStringLiteral("Zeit [min]")), QStringLiteral("time_min"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  // A kind the user chose stays.
  dialog.setKind(QStringLiteral("feature-series"));
  dialog.setHeaderLines(-1);
  EXPECT_EQ(dialog.kind(), QStringLiteral("feature-series"));

  // Imported: the log reads with its units, the speed is the spindle speed.
  dialog.setKind(QStringLiteral("thermal-log"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  importButton(dialog)->click();
  ASSERT_EQ(dialog.result(), QDialog::Accepted);
  doc_.addDataset(dialog.dataset());
  const ThermalLog log = readThermalLog(resolveDatasetPath(doc_.fileName().toStdString(), dialog.dataset()),
                                        3, dialog.dataset().csv);
  EXPECT_EQ(log.rows(), 4u);
  EXPECT_DOUBLE_EQ(log.timeMin[3], 0.75);
  ASSERT_GE(log.indexOf("spindle_rpm"), 0);
  EXPECT_EQ(channelKind(log.channel("spindle_rpm")), ChannelKind::Speed);
  EXPECT_EQ(log.channel("Verlagerung K3 [\xC2\xB5m]").unit, "um");
  EXPECT_EQ(log.channel("Temperatur T1 [\xC2\xB0"
                        "C]")
                .unit,
            "degC");
}

TEST_F(ImportDialogTest, TheRealWenzelPointsWithoutExtensionAreProbePointsWithTheirIdsMapped) {
  const auto real = test::realData("cmm-wenzel-lens-points/SPH1_1");
  METROFIT_REQUIRE_PATH(real);
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(QString::fromStdString(real.string()));
  EXPECT_EQ(dialog.kind(), QStringLiteral("probe-points"));
  EXPECT_EQ(dialog.role(QStringLiteral("ID")), QStringLiteral("id"));
  EXPECT_EQ(dialog.role(QStringLiteral("x")), QStringLiteral("px"));
  EXPECT_EQ(dialog.role(QStringLiteral("z")), QStringLiteral("pz"));
}

// Found in the de_DE walk (2026-11-30): a role combo box was left in the top-left cell over the first
// column's name ("ID" hidden under "as in ..."). Every combo box of the mapping table is the role editor of
// one row, shown in the role column, and nothing covers the file's column names.
TEST_F(ImportDialogTest, MappingTableShowsEveryColumnNameAndOneRoleEditorPerRow) {
  const auto real = test::realData("cmm-wenzel-lens-points/SPH1_1");
  METROFIT_REQUIRE_PATH(real);
  int visibleCombos = -1;
  // As the main window opens it: from an event handler of the running loop, the dialog's exec() a loop
  // inside it (a widget deleted later is gone only when the outer loop runs again).
  QEventLoop outer;
  QTimer::singleShot(0, &outer, [&] {
    ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
    dialog.setFile(QString::fromStdString(real.string()));
    QTimer::singleShot(300, &dialog, [&] {
      auto* mapping = dialog.findChild<QTableWidget*>(QStringLiteral("importMapping"));
      ASSERT_NE(mapping, nullptr);
      EXPECT_EQ(mapping->rowCount(), 6);
      visibleCombos = 0;
      for (QComboBox* combo : mapping->findChildren<QComboBox*>()) {
        if (!combo->isVisible()) continue;
        ++visibleCombos;
        const QPoint centre = mapping->viewport()->mapFromGlobal(combo->mapToGlobal(combo->rect().center()));
        const QModelIndex at = mapping->indexAt(centre);
        EXPECT_EQ(at.column(), 2) << "a combo box '" << combo->objectName().toStdString()
                                  << "' lies over row " << at.row() << ", column " << at.column();
        if (at.isValid()) EXPECT_EQ(mapping->cellWidget(at.row(), at.column()), combo);
      }
      dialog.reject();
    });
    dialog.exec();
    outer.quit();
  });
  outer.exec();
  EXPECT_EQ(visibleCombos, 6);
}

/// The Wenzel file's `Residues` column (the CMM's residuals of its own sphere fit), read by the test.
std::map<QString, double> wenzelResidues(const std::filesystem::path& file) {
  QFile f(QString::fromStdString(file.string()));
  EXPECT_TRUE(f.open(QIODevice::ReadOnly));
  std::map<QString, double> out;
  const QList<QByteArray> lines = f.readAll().split('\n');
  for (int i = 1; i < lines.size(); ++i) {
    const QList<QByteArray> cells = lines[i].split('\t');
    if (cells.size() < 5) continue;
    bool ok = false;
    const double residue = cells[4].trimmed().toDouble(&ok);
    EXPECT_TRUE(ok) << "line " << i + 1 << ": '" << cells[4].toStdString() << "' is not a number";
    if (ok) out[QString::fromUtf8(cells[0])] = residue;
  }
  return out;
}

// Issue 28 item 4, the journey: raw CMM points without nominals (the Wenzel lens sphere) are imported,
// their nominals come from a sphere fitted to them, the Matching page runs on them and its per-point
// deviations are the CMM's own residuals; a second measurement of the lens takes the first as nominal.
TEST_F(ImportDialogTest, RawPointsTakeTheirNominalsFromAFittedSphereOrTheFirstMeasurement) {
  const auto first = test::realData("cmm-wenzel-lens-points/SPH1_1");
  const auto second = test::realData("cmm-wenzel-lens-points/SPH1_2");
  METROFIT_REQUIRE_PATH(first);
  METROFIT_REQUIRE_PATH(second);
  {
    ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
    dialog.setFile(QString::fromStdString(first.string()));
    ASSERT_EQ(dialog.kind(), QStringLiteral("probe-points"));
    ASSERT_TRUE(dialog.needsNominals());
    auto* box = dialog.findChild<QWidget*>(QStringLiteral("importNominals"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->isHidden());
    // Without another probe-point dataset, a second measurement cannot be chosen.
    auto* from = dialog.findChild<QComboBox*>(QStringLiteral("importNominalFrom"));
    ASSERT_NE(from, nullptr);
    EXPECT_FALSE(from->model()->flags(from->model()->index(1, 0)).testFlag(Qt::ItemIsEnabled));
    NominalSource n;
    n.from = "element";
    n.element = "sphere";
    dialog.setNominals(n);
    dialog.setDatasetId(QStringLiteral("lens1"));
    ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
    EXPECT_TRUE(dialog.nominalsSummary().contains(QStringLiteral("sphere fitted to 18 point(s)")))
        << dialog.nominalsSummary().toStdString();
    EXPECT_TRUE(dialog.findChild<QLabel*>(QStringLiteral("importProblem"))
                    ->text()
                    .contains(QStringLiteral("sphere fitted to 18 point(s)")));
    importButton(dialog)->click();
    ASSERT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.dataset().nominals, n);
    doc_.addDataset(dialog.dataset());
  }
  MatchingPage page(&doc_);
  page.selectDataset(QStringLiteral("lens1"));
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  // A sphere's normals all pass through its centre: no rotation about it is determined, and the page
  // says so (the minimax method checks it) instead of returning an arbitrary rotation.
  EXPECT_FALSE(page.runNow());
  EXPECT_TRUE(page.statusText().contains(QStringLiteral("undetermined"))) << page.statusText().toStdString();
  for (int dof = 0; dof < 3; ++dof) page.setLocked(dof, true);  // rx, ry, rz, as the message says
  ASSERT_TRUE(page.runNow()) << page.statusText().toStdString();
  ASSERT_TRUE(page.result().has_value());
  const QString csv = dir_.filePath(QStringLiteral("lens1_deviations.csv"));
  QString error;
  ASSERT_TRUE(page.savePerPointDeviations(csv, &error)) << error.toStdString();
  const CsvTable table = readCsvFile(csv.toStdString());
  const std::map<QString, double> cmm = wenzelResidues(first);
  ASSERT_EQ(table.rowCount(), cmm.size());
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    const QString id = QString::fromStdString(table.cell(r, table.requireColumn("id")));
    ASSERT_TRUE(cmm.count(id)) << id.toStdString();
    EXPECT_NEAR(table.number(r, table.requireColumn("d_mm")), cmm.at(id), 1.0e-3 + 1e-9) << id.toStdString();
  }

  // The second measurement of the lens, its nominals the first's points with the sphere's normals.
  ImportDialog dialog(doc_.project(), doc_.projectPathForDatasets());
  dialog.setFile(QString::fromStdString(second.string()));
  ASSERT_TRUE(dialog.needsNominals());
  NominalSource n;
  n.from = "reference";
  n.reference = "lens1";
  n.element = "sphere";
  dialog.setNominals(n);
  dialog.setDatasetId(QStringLiteral("lens2"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.nominals(), n);
  EXPECT_TRUE(dialog.nominalsSummary().contains(QStringLiteral("the 18 point(s) of “lens1”")))
      << dialog.nominalsSummary().toStdString();
  importButton(dialog)->click();
  doc_.addDataset(dialog.dataset());
  page.selectDataset(QStringLiteral("lens2"));
  ASSERT_TRUE(page.errorMessage().isEmpty()) << page.errorMessage().toStdString();
  EXPECT_TRUE(page.infoText().contains(QStringLiteral("with normals"))) << page.infoText().toStdString();
  ASSERT_TRUE(page.runNow());
  // The project file keeps the recipes: saved, reopened, the same points.
  doc_.save();
  const Project reopened = loadProject(doc_.fileName().toStdString());
  ASSERT_NE(reopened.dataset("lens2"), nullptr);
  EXPECT_EQ(reopened.dataset("lens2")->nominals, n);
  const ProbePointSet again =
      readProjectProbePoints(reopened, doc_.fileName().toStdString(), *reopened.dataset("lens2"));
  EXPECT_EQ(again.points.size(), 18u);
  EXPECT_TRUE(again.hasNormals);
}

}  // namespace
}  // namespace metrofit
