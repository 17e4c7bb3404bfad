// From a CMM report to a setup study in the GUI (issue 28 item 3; offscreen): a report imported with the
// import dialog, the setup model created from it with ReportModelDialog (one undo step of the project),
// extended with more of the report's features (one undo step of the graph editor), a dimension mapped to a
// report feature in the graph editor's "Report feature" column (undo / redo), the exact correction run on
// the Setup page and compared with core's setup functions on the same model and report (1e-9), the project
// saved and reopened with the mapping and the stored result. Reports: the REAL OGP step report of
// ../shared/data/real/cmm-ogp-hps-svt (skipped when absent), a PC-DMIS text report written here from the
// format's documentation (the example of tests/core/setup/cmm_text_report_test.cpp), and a DMIS series of
// two files imported as one dataset ("paths"). Screenshots of the dialog and of the editor with the mapping
// go to $METROFIT_TEST_OUT (setup_report_*.png).
#include <gtest/gtest.h>

#include <QPointer>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/gui/setuppage.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/project/project.h"
#include "core/project/report_model.h"
#include "core/setup/model.h"
#include "core/setup/objective.h"
#include "core/setup/report.h"
#include "core/study/setup_study.h"
#include "qtapp.h"
#include "samples/pcdmis_reports.h"
#include "table_cells.h"
#include "testsupport.h"
#include "widgets/data/datasettablemodel.h"
#include "widgets/document/projectdocument.h"
#include "widgets/importer/importdialog.h"
#include "widgets/setup/reportmodeldialog.h"
#include "widgets/setup/setupgrapheditor.h"
#include "widgets/setup/setupmodeleditor.h"
#include "widgets/setup/setupresultsview.h"

namespace metrofit {
namespace {

namespace fs = std::filesystem;

// The shared PC-DMIS sample (tests/samples/pcdmis_reports.h), written from the format's documentation.
const char* const kPcDmis = ::metrofit::test::kPcDmisBracketReport;

/// A DMIS output file of one workpiece (the subset of core/setup/report.h): POS_D1 as nominal and actual
/// plane, D2 by its tolerance definition and actual.
std::string dmisPart(const std::string& serial, double z, double d2) {
  return "DMISMN/'series test',05.0\n"
         "PARTSN/'" +
         serial +
         "'\n"
         "UNITS/MM,ANGDEG\n"
         "F(POS_D1)=FEAT/PLANE,CART,10,20,42.000,0,0,1\n"
         "FA(POS_D1)=FEAT/PLANE,CART,10,20," +
         num::general(z, 17) +
         ",0,0,1\n"
         "T(D2)=TOL/DISTB,NOMINL,18.5,-0.05,0.03,ZAXIS\n"
         "TA(D2)=TOL/DISTB," +
         num::general(d2, 17) + "\nENDFIL\n";
}

nlohmann::json json(const setup::Model& m) {
  return setup::modelToJson(m);
}

int rowOf(const ReportFeatures& r, const std::string& label) {
  for (std::size_t k = 0; k < r.characteristics.size(); ++k)
    if (r.characteristics[k].label == label || (r.byId && r.characteristics[k].feature == label))
      return static_cast<int>(k);
  return -1;
}

/// A dialog made by SetupPage::makeReportDialog has the page as its Qt parent: the page deletes it
/// when the page goes first (makePage() again, the fixture's teardown). This holder deletes it only
/// while it is alive, so neither side deletes it twice (the crash these tests had with unique_ptr).
class DialogHolder {
 public:
  explicit DialogHolder(ReportModelDialog* d = nullptr) : p_(d) {}
  ~DialogHolder() { delete p_.data(); }
  DialogHolder(const DialogHolder&) = delete;
  DialogHolder& operator=(const DialogHolder&) = delete;
  void reset(ReportModelDialog* d) {
    delete p_.data();
    p_ = d;
  }
  ReportModelDialog* get() const { return p_.data(); }
  ReportModelDialog* operator->() const { return p_.data(); }
  ReportModelDialog& operator*() const { return *p_; }
  explicit operator bool() const { return !p_.isNull(); }

 private:
  QPointer<ReportModelDialog> p_;
};

class SetupReportModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    project_ = dir_.filePath(QStringLiteral("report.metrofit"));
    document_ = std::make_unique<ProjectDocument>();
    document_->saveAs(project_);
  }
  /// Imports `file` as a CMM report through the import dialog (and `more` as one series with it).
  QString importReport(const QString& file, const QStringList& more = {}) {
    ImportDialog dialog(document_->project(), document_->projectPathForDatasets());
    dialog.setFile(file);
    dialog.setKind(QStringLiteral("cmm-report"));
    if (!more.isEmpty()) dialog.setSeriesFiles(more);
    EXPECT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
    document_->addDataset(dialog.dataset());
    return QString::fromStdString(dialog.dataset().id);
  }
  void makePage() {
    page_ = std::make_unique<SetupPage>(document_.get());
    page_->resize(1280, 760);
  }
  /// The exact correction as core computes it for the page's model and the report's files.
  SetupRunOutcome coreExact(const setup::Model& model) {
    const SetupStudyFiles files =
        setupStudyFiles(document_->project(), document_->projectPathForDatasets().toStdString());
    const setup::Measurements m =
        setup::readMeasurements(files.reportPaths, model, files.reportCsv, files.reportDmis);
    const setup::SetupInstance instance(model, m);
    return runSetupMethod(instance, "exact", 0, 0);
  }
  /// Runs exact on the page and checks it against core (1e-9).
  void runAndCompare(const char* what) {
    ASSERT_TRUE(page_->errorMessage().isEmpty()) << what << ": " << page_->errorMessage().toStdString();
    ASSERT_TRUE(page_->runSynchronously(QStringLiteral("exact"), 0, 0)) << what;
    ASSERT_TRUE(page_->resultsView()->result().has_value()) << what;
    const SetupRunOutcome& shown = *page_->resultsView()->result();
    const SetupRunOutcome core = coreExact(page_->modelEditor()->model());
    ASSERT_EQ(shown.x.size(), core.x.size()) << what;
    for (std::size_t i = 0; i < core.x.size(); ++i)
      EXPECT_NEAR(shown.x[i], core.x[i], 1e-9) << what << " x" << i;
    EXPECT_NEAR(shown.score.f1, core.score.f1, 1e-9) << what;
    EXPECT_NEAR(shown.score.f2, core.score.f2, 1e-9) << what;
    EXPECT_NEAR(shown.f1Before, core.f1Before, 1e-9) << what;
  }
  void grab(QWidget* w, const char* name) {
    w->show();
    QCoreApplication::processEvents();
    w->grab().save(QString::fromStdString((test::outDir() / name).string()));
  }

  QTemporaryDir dir_;
  QString project_;
  std::unique_ptr<ProjectDocument> document_;
  std::unique_ptr<SetupPage> page_;
};

TEST_F(SetupReportModelTest, OgpReportToModelMappingRunSaveReopen) {
  const fs::path ogp = test::realData("cmm-ogp-hps-svt/survey_data/meas1/L0_axial_top_module1_1.txt");
  METROFIT_REQUIRE_PATH(ogp);
  const QString reportId = importReport(QString::fromStdString(ogp.string()));
  makePage();
  EXPECT_TRUE(page_->errorMessage().contains(QStringLiteral("no setup model yet")))
      << page_->errorMessage().toStdString();
  EXPECT_TRUE(page_->fromReportButton()->isEnabled());

  // (a) Create: the oriball's Z location, 0.05 mm either side (the step report prints no tolerance).
  QString error;
  DialogHolder dialog(page_->makeReportDialog(reportId, &error));
  ASSERT_TRUE(dialog) << error.toStdString();
  EXPECT_TRUE(dialog->creates());
  const ReportFeatures features = readReportFeatures(ogp.string());
  EXPECT_EQ(features.format, "OGP step report");
  const int oriZ = rowOf(features, "oriball:Z Location");
  const int axiD = rowOf(features, "axiball:Diameter");
  const int axiX = rowOf(features, "axiball:X Location");
  ASSERT_GE(oriZ, 0);
  ASSERT_GE(axiD, 0);
  ASSERT_GE(axiX, 0);
  ASSERT_EQ(dialog->table()->rowCount(), static_cast<int>(features.characteristics.size()));
  EXPECT_FALSE(dialog->resultModel()) << "nothing checked";
  ASSERT_TRUE(dialog->setChecked(oriZ, true));
  EXPECT_FALSE(dialog->resultModel(&error)) << "no tolerance printed and none given";
  EXPECT_TRUE(error.contains(QStringLiteral("no tolerance"))) << error.toStdString();
  dialog->setDefaultTolerance(0.05);
  dialog->setModelName(QStringLiteral("module 1"));
  ASSERT_TRUE(dialog->resultModel(&error)) << error.toStdString();
  grab(dialog.get(), "setup_report_dialog_create.png");
  ASSERT_TRUE(page_->applyReportDialog(*dialog, reportId, &error)) << error.toStdString();

  const auto expectCreated = [&](const char* when) {
    const DatasetRef* model = document_->project().firstOfKind(dataset_kind::kSetupModel);
    ASSERT_NE(model, nullptr) << when;
    EXPECT_EQ(document_->studyValue(QStringLiteral("setup"), QStringLiteral("/model")), model->id) << when;
    EXPECT_EQ(document_->studyValue(QStringLiteral("setup"), QStringLiteral("/dataset")),
              reportId.toStdString())
        << when;
    const setup::Model& m = page_->modelEditor()->model();
    ASSERT_EQ(m.dimensions.size(), 1u) << when;
    EXPECT_EQ(m.name, "module 1");
    EXPECT_EQ(m.dimensions[0].label, "oriball:Z Location") << when;
    EXPECT_EQ(m.dimensions[0].lower, -0.05);
    EXPECT_EQ(m.dimensions[0].upper, 0.05);
    EXPECT_EQ(m.setup.size(), 1u);
    EXPECT_EQ(m.arcs.size(), 2u) << "W1 -> oriball -> the dimension";
    EXPECT_TRUE(page_->errorMessage().isEmpty()) << when << ": " << page_->errorMessage().toStdString();
  };
  expectCreated("created");
  EXPECT_EQ(document_->undoStack()->count(), 2) << "import, create: one step each";
  document_->undoStack()->undo();
  EXPECT_EQ(document_->project().firstOfKind(dataset_kind::kSetupModel), nullptr);
  EXPECT_TRUE(page_->modelEditor()->model().dimensions.empty());
  EXPECT_FALSE(page_->errorMessage().isEmpty());
  document_->undoStack()->redo();
  expectCreated("redone");
  runAndCompare("created model");

  // (a) Extend: the axiball's diameter; the oriball's Z location is in the model already.
  dialog.reset(page_->makeReportDialog(reportId, &error));
  ASSERT_TRUE(dialog) << error.toStdString();
  EXPECT_FALSE(dialog->creates());
  EXPECT_FALSE(dialog->setChecked(oriZ, false)) << "read by the model: not checkable";
  ASSERT_TRUE(dialog->setChecked(axiD, true));
  dialog->setDefaultTolerance(0.02);
  dialog->setConnectTo(QStringLiteral("W1"));
  grab(dialog.get(), "setup_report_dialog_add.png");
  const nlohmann::json beforeAdd = json(page_->modelEditor()->model());
  ASSERT_TRUE(page_->applyReportDialog(*dialog, reportId, &error)) << error.toStdString();
  QUndoStack* graphUndo = page_->modelEditor()->undoStack();
  EXPECT_EQ(graphUndo->count(), 1) << "one undo step of the graph editor";
  ASSERT_EQ(page_->modelEditor()->model().dimensions.size(), 2u);
  EXPECT_EQ(page_->modelEditor()->model().dimensions[1].label, "axiball:Diameter");
  const nlohmann::json afterAdd = json(page_->modelEditor()->model());
  graphUndo->undo();
  EXPECT_EQ(json(page_->modelEditor()->model()), beforeAdd);
  graphUndo->redo();
  EXPECT_EQ(json(page_->modelEditor()->model()), afterAdd);
  runAndCompare("extended model, not saved yet");

  // (b) Map: a new dimension D3 under the axiball, mapped in the "Report feature" column.
  SetupModelEditor* editor = page_->modelEditor();
  ASSERT_TRUE(editor->addNode(SetupLevel::Dimension, QStringLiteral("D3")));
  ASSERT_TRUE(editor->addArc(QStringLiteral("axiball"), QStringLiteral("D3"), -1));
  EXPECT_FALSE(page_->errorMessage().isEmpty()) << "D3 (label = its id) is not in the report";
  QTableWidget* table = page_->graphEditor()->dimensionTable();
  ASSERT_EQ(table->rowCount(), 3);
  EXPECT_TRUE(page_->graphEditor()->reportFeatures().contains(QStringLiteral("axiball:X Location")));
  table->item(2, SetupGraphEditor::reportColumn())->setText(QStringLiteral("axiball:X Location"));
  EXPECT_EQ(editor->model().dimensions[2].label, "axiball:X Location");
  EXPECT_EQ(graphUndo->undoText(), QStringLiteral("Map D3 to the report feature axiball:X Location"));
  const nlohmann::json mapped = json(editor->model());
  graphUndo->undo();
  EXPECT_EQ(editor->model().dimensions[2].label, "");
  EXPECT_FALSE(page_->errorMessage().isEmpty());
  EXPECT_EQ(table->item(2, SetupGraphEditor::reportColumn())->text(), QString()) << "the table follows undo";
  graphUndo->redo();
  EXPECT_EQ(json(editor->model()), mapped);
  EXPECT_EQ(table->item(2, SetupGraphEditor::reportColumn())->text(), QStringLiteral("axiball:X Location"));
  page_->tabs()->setCurrentIndex(0);
  grab(page_.get(), "setup_report_editor_mapping.png");

  // (c) Run with the mapped model (before it is saved): the report is read against it.
  runAndCompare("mapped model");
  const std::vector<double> x = page_->resultsView()->result()->x;
  ASSERT_TRUE(page_->saveModel(&error)) << error.toStdString();
  runAndCompare("saved model");  // the stored result is of the saved model
  document_->save();

  // Reopen: the mapping (the model file) and the stored result are there.
  page_.reset();
  document_ = std::make_unique<ProjectDocument>();
  document_->load(project_);
  makePage();
  EXPECT_EQ(json(page_->modelEditor()->model()), mapped);
  EXPECT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  const QString stored = page_->storedResultText();
  EXPECT_TRUE(stored.startsWith(QStringLiteral("From the saved project"))) << stored.toStdString();
  const nlohmann::json entry = document_->project().results["setup"][reportId.toStdString()];
  ASSERT_TRUE(entry.contains("corrections")) << entry.dump();
  ASSERT_EQ(entry["corrections"].size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_NEAR(entry["corrections"][i]["correction_mm"].get<double>(), x[i], 1e-9);
  runAndCompare("reopened");
}

TEST_F(SetupReportModelTest, PcDmisReportToModelRunsLikeCore) {
  const QString file = dir_.filePath(QStringLiteral("bracket.txt"));
  test::writeText(file.toStdString(), kPcDmis);
  const QString reportId = importReport(file);
  makePage();
  QString error;
  DialogHolder dialog(page_->makeReportDialog(reportId, &error));
  ASSERT_TRUE(dialog) << error.toStdString();
  const ReportFeatures features = readReportFeatures(file.toStdString());
  EXPECT_EQ(features.format, "PC-DMIS text report");
  ASSERT_EQ(features.characteristics.size(), 4u);
  EXPECT_EQ(features.characteristics[2].label, "LOC1:D");
  EXPECT_EQ(*features.characteristics[2].lower, -0.05);
  EXPECT_EQ(*features.characteristics[2].upper, 0.03);
  dialog->checkAll(true);
  EXPECT_EQ(dialog->checkedRows().size(), 4u);
  ASSERT_TRUE(page_->applyReportDialog(*dialog, reportId, &error)) << error.toStdString();
  const setup::Model& m = page_->modelEditor()->model();
  ASSERT_EQ(m.dimensions.size(), 4u);
  EXPECT_EQ(m.features.size(), 2u) << "LOC1 and LOC2";
  EXPECT_EQ(*m.dimensions[3].nominal, 42.0);
  runAndCompare("PC-DMIS");
  // LOC2 is 0.015 above its upper limit: the correction brings every dimension into tolerance.
  const SetupRunOutcome& r = *page_->resultsView()->result();
  EXPECT_GT(r.score.f1, r.f1Before);
}

TEST_F(SetupReportModelTest, DmisSeriesIsOneDatasetAndOneSetupSeries) {
  const QString a = dir_.filePath(QStringLiteral("part_1.dmo"));
  const QString b = dir_.filePath(QStringLiteral("part_2.dmo"));
  test::writeText(a.toStdString(), dmisPart("S1", 42.013, -0.021));
  test::writeText(b.toStdString(), dmisPart("S2", 42.007, 0.004));
  const QString reportId = importReport(a, {b});
  const DatasetRef* report = document_->project().dataset(reportId.toStdString());
  ASSERT_NE(report, nullptr);
  EXPECT_EQ(report->paths, (std::vector<std::string>{"part_1.dmo", "part_2.dmo"}));
  makePage();
  QString error;
  DialogHolder dialog(page_->makeReportDialog(reportId, &error));
  ASSERT_TRUE(dialog) << error.toStdString();
  dialog->checkAll(true);
  dialog->setDefaultTolerance(0.02);
  ASSERT_TRUE(page_->applyReportDialog(*dialog, reportId, &error)) << error.toStdString();
  const setup::Model model = page_->modelEditor()->model();
  ASSERT_EQ(model.dimensions.size(), 2u);
  EXPECT_EQ(model.dimensions[0].label, "POS_D1");
  EXPECT_EQ(model.dimensions[1].label, "D2");
  runAndCompare("DMIS series");
  // Both workpieces are read: the deviations are the means of the two files.
  const setup::Measurements m = setup::readMeasurements({a.toStdString(), b.toStdString()}, model);
  EXPECT_EQ(m.parts, (std::vector<std::string>{"S1", "S2"}));
  EXPECT_NEAR(page_->instance()->deviation(0), (0.013 + 0.007) / 2, 1e-9);
  EXPECT_NEAR(page_->instance()->deviation(1), (-0.021 + 0.004) / 2, 1e-9);
  // With the model in the project, the import dialog previews the whole series as the study reads it:
  // the means over the two workpieces, not the first file's values.
  {
    ImportDialog again(document_->project(), document_->projectPathForDatasets());
    again.setFile(a);
    again.setKind(QStringLiteral("cmm-report"));
    again.setSeriesFiles({b});
    auto* detected = again.findChild<QLabel*>(QStringLiteral("importDetected"));
    ASSERT_NE(detected, nullptr);
    EXPECT_TRUE(detected->text().contains(QStringLiteral("DMIS series of 2 files")))
        << detected->text().toStdString();
    auto* preview = again.findChild<QTableWidget*>(QStringLiteral("importPreview"));
    ASSERT_NE(preview, nullptr);
    ASSERT_EQ(preview->rowCount(), 2);
    EXPECT_NEAR(test::cellNumber(preview, 0, 1), (0.013 + 0.007) / 2, 1e-9);
    again.setReadsSeries(false);  // the first file alone
    EXPECT_NEAR(test::cellNumber(preview, 0, 1), 0.013, 1e-9);
  }

  // Saved to another folder and reopened: "paths" follow, and the series is read again.
  QTemporaryDir other;
  ASSERT_TRUE(other.isValid());
  const QString moved = QDir(other.path()).filePath(QStringLiteral("moved.metrofit"));
  document_->saveAs(moved);
  const nlohmann::json saved = nlohmann::json::parse(test::readText(moved.toStdString()));
  const nlohmann::json ds = saved["datasets"][0];
  ASSERT_TRUE(ds.contains("paths")) << ds.dump();
  EXPECT_EQ(ds["path"], ds["paths"][0]);
  page_.reset();
  document_ = std::make_unique<ProjectDocument>();
  document_->load(moved);
  makePage();
  EXPECT_TRUE(page_->errorMessage().isEmpty()) << page_->errorMessage().toStdString();
  EXPECT_TRUE(page_->storedResultText().startsWith(QStringLiteral("From the saved project")))
      << page_->storedResultText().toStdString();
  runAndCompare("DMIS series, reopened");

  // The files moved: re-linked together they stay a series (one undo step); a file that is not DMIS
  // output is refused by name and nothing changes.
  QTemporaryDir movedFiles;
  ASSERT_TRUE(movedFiles.isValid());
  const QString a2 = QDir(movedFiles.path()).filePath(QStringLiteral("w1.dmo"));
  const QString b2 = QDir(movedFiles.path()).filePath(QStringLiteral("w2.dmo"));
  ASSERT_TRUE(QFile::copy(a, a2));
  ASSERT_TRUE(QFile::copy(b, b2));
  const QString notDmis = QDir(movedFiles.path()).filePath(QStringLiteral("notes.txt"));
  test::writeText(notDmis.toStdString(), "part,time_min\n1,0\n");
  const DatasetRef before = *document_->project().dataset(reportId.toStdString());
  try {
    document_->relinkDataset(reportId, QStringList{a2, notDmis});
    ADD_FAILURE() << "a series with a file that is not DMIS output was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(*document_->project().dataset(reportId.toStdString()), before);
  document_->relinkDataset(reportId, QStringList{a2, b2});
  const DatasetRef* relinked = document_->project().dataset(reportId.toStdString());
  ASSERT_EQ(relinked->paths.size(), 2u);
  EXPECT_EQ(relinked->path, relinked->paths[0]);
  EXPECT_NE(relinked->paths[1].find("w2.dmo"), std::string::npos) << relinked->paths[1];
  document_->undoStack()->undo();
  EXPECT_EQ(*document_->project().dataset(reportId.toStdString()), before);
}

// A QIF 3 Results file of six measured parts (the public sample, README facts in
// ../shared/data/real/cmm-qif-samples): the import dialog recognises it, the setup page makes a model of
// its characteristics and runs the exact optimum on the six parts as core does; read as probe points, the
// dialog offers its parts.
TEST_F(SetupReportModelTest, QifResultsToModelRunsLikeCoreAndOffersItsParts) {
  const QString file =
      QString::fromStdString(test::realData("cmm-qif-samples/SheetMetal_QIF_Results_6_samples.QIF").string());
  METROFIT_REQUIRE_PATH(file.toStdString());
  ImportDialog dialog(document_->project(), document_->projectPathForDatasets());
  dialog.setFile(file);
  EXPECT_EQ(dialog.kind(), QStringLiteral("qif"));
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.qifParts().size(), 6);
  EXPECT_EQ(dialog.qifPart(), 0) << "a qif dataset is every part";
  {
    // The preview is the feature table the studies read, not the XML (README fact 5: profile
    // W1RISMRA09V of part 1 is 0.224164, zone 0.5 -> limits ±0.25; fact 2: position W1RXXMRA19P of
    // part 1 is 1.076016, zone 1.25 -> limits 0 and 1.25).
    auto* preview = dialog.findChild<QTableWidget*>(QStringLiteral("importPreview"));
    ASSERT_TRUE(preview);
    QStringList headers;
    for (int c = 0; c < preview->columnCount(); ++c) headers << preview->horizontalHeaderItem(c)->text();
    const int characteristic = headers.indexOf(DatasetTableModel::tr("Feature"));  // the QIF item's name
    const auto column = [&headers](const QString& name) {
      for (int c = 0; c < headers.size(); ++c)
        if (headers[c].startsWith(name)) return c;  // "Actual [mm]"
      return -1;
    };
    const int actual = column(DatasetTableModel::tr("Actual"));
    const int upper = column(DatasetTableModel::tr("Upper tol."));
    ASSERT_GE(characteristic, 0) << headers.join(QLatin1Char('|')).toStdString();
    ASSERT_GE(actual, 0) << headers.join(QLatin1Char('|')).toStdString();
    ASSERT_GE(upper, 0) << headers.join(QLatin1Char('|')).toStdString();
    EXPECT_EQ(preview->rowCount(), ImportDialog::kPreviewRows);
    int found = 0;
    for (int r = 0; r < preview->rowCount(); ++r) {
      if (!preview->item(r, characteristic)->text().contains(QStringLiteral("W1RISMRA09V"))) continue;
      ++found;
      bool ok = false;
      EXPECT_NEAR(QLocale().toDouble(preview->item(r, actual)->text(), &ok), 0.224164, 5e-7);
      EXPECT_TRUE(ok) << preview->item(r, actual)->text().toStdString();
      EXPECT_NEAR(QLocale().toDouble(preview->item(r, upper)->text(), &ok), 0.25, 1e-12);
    }
    for (int r = 0; r < preview->rowCount(); ++r) {
      if (preview->item(r, characteristic)->text() != QStringLiteral("W1RXXMRA19P")) continue;
      ++found;
      EXPECT_NEAR(QLocale().toDouble(preview->item(r, actual)->text()), 1.076016, 5e-7);
      EXPECT_NEAR(QLocale().toDouble(preview->item(r, upper)->text()), 1.25, 1e-12);
    }
    QStringList shown;
    for (int r = 0; r < preview->rowCount(); ++r) {
      QStringList cells;
      for (int c = 0; c < preview->columnCount(); ++c) cells << preview->item(r, c)->text();
      shown << cells.join(QLatin1Char('|'));
    }
    EXPECT_EQ(found, 2) << "the first part's rows come first:\n"
                        << shown.join(QLatin1Char('\n')).toStdString();
    EXPECT_FALSE(preview->item(0, 0)->text().startsWith(QLatin1Char('<'))) << "not the XML lines";
    EXPECT_TRUE(dialog.findChild<QGroupBox*>(QStringLiteral("importMappingBox"))->isHidden())
        << "no columns to map: the preview has the width";
  }
  const DatasetRef qif = dialog.dataset();
  EXPECT_EQ(qif.kind, dataset_kind::kQif);
  // As probe points: one part, chosen in the dialog (1 unless chosen), named by number and serial.
  dialog.setKind(QStringLiteral("probe-points"));
  ASSERT_EQ(dialog.qifParts().size(), 6);
  EXPECT_TRUE(dialog.qifParts()[5].startsWith(QStringLiteral("6 · SN5802806")))
      << dialog.qifParts()[5].toStdString();
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().part, 1);
  dialog.setQifPart(6);
  ASSERT_TRUE(dialog.canImport()) << dialog.problem().toStdString();
  EXPECT_EQ(dialog.dataset().part, 6);
  grab(&dialog, "setup_report_qif_import.png");

  document_->addDataset(qif);
  makePage();
  EXPECT_TRUE(page_->reportDatasets().contains(QString::fromStdString(qif.id)));
  QString error;
  DialogHolder report(page_->makeReportDialog(QString::fromStdString(qif.id), &error));
  ASSERT_TRUE(report) << error.toStdString();
  const ReportFeatures features =
      datasetReportFeatures(document_->projectPathForDatasets().toStdString(), qif);
  EXPECT_EQ(features.format, "QIF results file");
  const int position = rowOf(features, "W1RXXMRA19P:actual");
  ASSERT_GE(position, 0);
  // README: a position zone of diameter 1.25 -> nominal 0, limits 0 and 1.25.
  EXPECT_EQ(*features.characteristics[position].nominal, 0.0);
  EXPECT_EQ(*features.characteristics[position].lower, 0.0);
  EXPECT_EQ(*features.characteristics[position].upper, 1.25);
  report->checkAll(true);
  ASSERT_TRUE(page_->applyReportDialog(*report, QString::fromStdString(qif.id), &error))
      << error.toStdString();
  EXPECT_EQ(page_->modelEditor()->model().dimensions.size(), report->checkedRows().size());
  runAndCompare("QIF");
}

}  // namespace
}  // namespace metrofit
