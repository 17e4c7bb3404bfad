// Tests of the PDF report: a small project written by the test (thermal log + probe points) goes
// through writeReport, and poppler-utils (pdfinfo, pdftotext, pdftoppm, pdfimages) check the
// result: page count, text, a non-blank chart page, vector graphics only. Errors: an unwritable
// target throws FileError, a missing dataset throws InputError, and neither leaves a PDF behind.
// Rendered pages are saved into $METROFIT_TEST_OUT for a look.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <sstream>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/project/project.h"
#include "metrofit/version.h"
#include "qtapp.h"
#include "samples/box_stl.h"
#include "widgets/report/report.h"

namespace metrofit {
namespace {

QString outputDir() {
  const QString dir = qEnvironmentVariable("METROFIT_TEST_OUT", QDir::tempPath());
  QDir().mkpath(dir);
  return dir;
}

void writeText(const QString& path, const std::string& text) {
  QDir().mkpath(QFileInfo(path).absolutePath());
  std::ofstream(path.toStdString()) << text;
}

/// 240 rows, one a minute: heating to 120 min, then cooling; four temperatures, a displacement.
std::string thermalCsv() {
  std::ostringstream s;
  s << "# synthetic heating / cooling run\ntime_min,T1,T2,T3,T_amb,disp_z_um\n";
  for (int i = 0; i < 240; ++i) {
    const double h =
        i < 120 ? 1.0 - std::exp(-i / 30.0) : (1.0 - std::exp(-4.0)) * std::exp(-(i - 120) / 45.0);
    s << i << ',' << 21.0 + 6.0 * h << ',' << 21.5 + 4.0 * h << ',' << 20.8 + 2.5 * h << ','
      << 20.0 + 0.3 * std::sin(i / 40.0) << ',' << -18.0 * h << '\n';
  }
  return s.str();
}

/// 36 probe points on three faces of a 120 x 80 x 50 mm block, measured p = q + d n with a
/// deviation d that grows along X (so some points are outside +-0.05 mm).
std::string probeCsv() {
  std::ostringstream s;
  s << "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\n";
  int id = 0;
  const auto point = [&](const char* surface, double qx, double qy, double qz, double nx, double ny,
                         double nz) {
    const double d = -0.03 + 0.0009 * qx + 0.01 * std::sin(id * 1.7);
    s << "P" << ++id << ',' << surface << ',' << qx << ',' << qy << ',' << qz << ',' << nx << ',' << ny << ','
      << nz << ',' << qx + d * nx << ',' << qy + d * ny << ',' << qz + d * nz << '\n';
  };
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) {
      point("top", 10 + 33.0 * i, 10 + 30.0 * j, 50, 0, 0, 1);
      point("front", 10 + 33.0 * i, 0, 10 + 15.0 * j, 0, -1, 0);
      point("right", 120, 10 + 20.0 * i, 10 + 15.0 * j, 1, 0, 0);
    }
  }
  return s.str();
}

struct ProcessResult {
  int exitCode = -1;
  QString out;
};

ProcessResult run(const QString& program, const QStringList& args) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(60000)) {
    return {};
  }
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
          QString::fromUtf8(p.readAllStandardOutput())};
}

int pdfPages(const QString& pdf) {
  const ProcessResult r = run(QStringLiteral("pdfinfo"), {pdf});
  const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(r.out);
  return r.exitCode == 0 && m.hasMatch() ? m.captured(1).toInt() : -1;
}

/// Fraction of pixels that are not (near) white.
double inkFraction(const QImage& image) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  long ink = 0;
  for (int y = 0; y < img.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(img.constScanLine(y));
    for (int x = 0; x < img.width(); ++x) {
      if (qRed(line[x]) < 235 || qGreen(line[x]) < 235 || qBlue(line[x]) < 235) {
        ++ink;
      }
    }
  }
  return static_cast<double>(ink) / (static_cast<double>(img.width()) * img.height());
}

class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    writeText(dir_.filePath(QStringLiteral("data/thermal.csv")), thermalCsv());
    writeText(dir_.filePath(QStringLiteral("data/probes.csv")), probeCsv());
    Project p;
    p.name = "Report test cell";
    p.description = "A synthetic project: one heating / cooling run and one probed block.";
    p.datasets.push_back({"thermal_run",
                          dataset_kind::kThermalLog,
                          "data/thermal.csv",
                          "Spindle warm-up and cool-down (synthetic).",
                          "CC0-1.0",
                          {}});
    p.datasets.push_back(
        {"probe_block", dataset_kind::kProbePoints, "data/probes.csv", "Probed block.", "", {}});
    // The report shows the studies a project declares.
    p.studies["thermal"] = {
        {"dataset", "thermal_run"}, {"target", "disp_z_um"}, {"inputs", {"T1", "T2", "T3"}}};
    p.studies["matching"] = {{"dataset", "probe_block"}, {"tolerance_mm", 0.05}};
    projectPath_ = dir_.filePath(QStringLiteral("cell.metrofit"));
    saveProject(p, projectPath_.toStdString());
    project_ = loadProject(projectPath_.toStdString());
  }

  ReportOptions options() const {
    ReportOptions o;
    o.projectPath = projectPath_;
    return o;
  }

  QTemporaryDir dir_;
  QString projectPath_;
  Project project_;
};

TEST_F(ReportTest, WritesCoverThermalAndProbeSections) {
  const QString pdf = dir_.filePath(QStringLiteral("report.pdf"));
  const ReportSummary summary = writeReport(project_, pdf, options());
  ASSERT_TRUE(QFileInfo::exists(pdf));
  const QString copy = QDir(outputDir()).filePath(QStringLiteral("report.pdf"));
  QFile::remove(copy);
  QFile::copy(pdf, copy);
  EXPECT_EQ(summary.sections,
            (QStringList{QStringLiteral("Thermal"), QStringLiteral("Posture matching — probe points"),
                         QStringLiteral("Posture matching — before and after")}));

  const int pages = pdfPages(pdf);
  EXPECT_GE(pages, 3);
  EXPECT_EQ(pages, summary.pages);

  const ProcessResult text =
      run(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
  ASSERT_EQ(text.exitCode, 0);
  for (const QString& needle :
       {QStringLiteral("Metrofit report"), QStringLiteral("Report test cell"), QStringLiteral("Thermal"),
        QStringLiteral("thermal_run"), QStringLiteral("probe_block"), QStringLiteral("CC0-1.0"),
        QStringLiteral("temperature (°C)"), QStringLiteral("displacement (µm)"),
        QStringLiteral("Top view (XY)"), QString::fromUtf8(kVersion),
        QStringLiteral("page 2 of %1").arg(pages)}) {
    EXPECT_TRUE(text.out.contains(needle)) << "missing: " << needle.toStdString();
  }
  // 36 points, computed outside-tolerance count appears in the facts table.
  EXPECT_TRUE(text.out.contains(QRegularExpression(QStringLiteral("points\\s+36"))))
      << text.out.toStdString();

  // Charts and projections are vector graphics: no raster image in the PDF.
  const ProcessResult images = run(QStringLiteral("pdfimages"), {QStringLiteral("-list"), pdf});
  ASSERT_EQ(images.exitCode, 0);
  EXPECT_LE(images.out.trimmed().split('\n').size(), 2) << images.out.toStdString();  // header lines only

  // Every page rendered for a look; the chart page and the probe page carry ink.
  const QString prefix = QDir(outputDir()).filePath(QStringLiteral("report_page"));
  ASSERT_EQ(run(QStringLiteral("pdftoppm"),
                {QStringLiteral("-r"), QStringLiteral("50"), QStringLiteral("-png"), pdf, prefix})
                .exitCode,
            0);
  const QString page2 = pages >= 10 ? prefix + QStringLiteral("-02.png") : prefix + QStringLiteral("-2.png");
  const QString page3 = pages >= 10 ? prefix + QStringLiteral("-03.png") : prefix + QStringLiteral("-3.png");
  const QImage image2(page2);
  ASSERT_FALSE(image2.isNull()) << page2.toStdString();
  EXPECT_GT(inkFraction(image2), 0.08);
  const QImage image3(page3);
  ASSERT_FALSE(image3.isNull()) << page3.toStdString();
  EXPECT_GT(inkFraction(image3), 0.03);
  // A sharper copy of the chart page for people.
  run(QStringLiteral("pdftoppm"),
      {QStringLiteral("-r"), QStringLiteral("110"), QStringLiteral("-png"), QStringLiteral("-f"),
       QStringLiteral("2"), QStringLiteral("-l"), QStringLiteral("3"), pdf,
       QDir(outputDir()).filePath(QStringLiteral("report_hires"))});
}

TEST_F(ReportTest, TitleOptionOverridesTheProjectName) {
  const QString pdf = dir_.filePath(QStringLiteral("titled.pdf"));
  ReportOptions o = options();
  o.title = QStringLiteral("Acceptance run 42");
  writeReport(project_, pdf, o);
  const ProcessResult text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  EXPECT_TRUE(text.out.contains(QStringLiteral("Acceptance run 42")));
  EXPECT_TRUE(text.out.contains(QStringLiteral("Report test cell")));  // still named on the cover
}

TEST_F(ReportTest, ProbeToleranceComesFromTheMatchingStudy) {
  Project p = project_;
  p.studies["matching"] = {{"tolerance_mm", 0.2}};
  const QString pdf = dir_.filePath(QStringLiteral("tol.pdf"));
  writeReport(p, pdf, options());
  const ProcessResult text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  EXPECT_TRUE(text.out.contains(QStringLiteral("outside ±0.200 mm"))) << text.out.toStdString();
  EXPECT_FALSE(text.out.contains(QStringLiteral("outside ±0.050 mm")));
  p.studies["matching"] = {{"tolerance_mm", -1}};
  try {
    writeReport(p, dir_.filePath(QStringLiteral("bad.pdf")), options());
    FAIL() << "negative tolerance accepted";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("studies.matching.tolerance_mm"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(QFileInfo::exists(dir_.filePath(QStringLiteral("bad.pdf"))));
}

TEST_F(ReportTest, UnwritableTargetThrowsFileErrorAndLeavesNothing) {
  const QString pdf = dir_.filePath(QStringLiteral("no/such/folder/report.pdf"));
  EXPECT_THROW(writeReport(project_, pdf, options()), FileError);
  EXPECT_FALSE(QFileInfo::exists(pdf));
  EXPECT_FALSE(QFileInfo::exists(dir_.filePath(QStringLiteral("no"))));
}

TEST_F(ReportTest, MissingDatasetThrowsInputErrorAndLeavesNoPdf) {
  Project broken = project_;
  broken.datasets.push_back({"gone", dataset_kind::kThermalLog, "data/missing.csv", "", "", {}});
  const QString pdf = dir_.filePath(QStringLiteral("broken.pdf"));
  try {
    writeReport(broken, pdf, options());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(QFileInfo::exists(pdf));
  // An older report at the target survives a failed run untouched, and no temporary file is left.
  writeText(pdf, "old report");
  EXPECT_THROW(writeReport(broken, pdf, options()), InputError);
  QFile old(pdf);
  ASSERT_TRUE(old.open(QIODevice::ReadOnly));
  EXPECT_EQ(old.readAll(), QByteArray("old report"));
  EXPECT_EQ(QDir(dir_.path()).entryList(QDir::Files).size(), 2);  // cell.metrofit, broken.pdf
}

TEST_F(ReportTest, InvalidProbeDataPropagatesTheCoreError) {
  writeText(dir_.filePath(QStringLiteral("data/probes.csv")),
            "id,surface,qx,qy,qz,nx,ny,nz,px,py,pz\nA,s,0,0,0,0,0,2,0,0,0\nB,s,1,0,0,0,0,1,1,0,0\n"
            "C,s,0,1,0,0,0,1,0,1,0\n");
  const QString pdf = dir_.filePath(QStringLiteral("bad.pdf"));
  EXPECT_THROW(writeReport(project_, pdf, options()), InputError);
  EXPECT_FALSE(QFileInfo::exists(pdf));
}

TEST_F(ReportTest, ProjectWithoutDatasetsIsACoverPage) {
  Project empty;
  empty.name = "Empty cell";
  const QString pdf = dir_.filePath(QStringLiteral("empty.pdf"));
  const ReportSummary summary = writeReport(empty, pdf, options());
  EXPECT_EQ(summary.pages, 1);
  EXPECT_TRUE(summary.sections.isEmpty());
  EXPECT_EQ(pdfPages(pdf), 1);
}

TEST_F(ReportTest, ResolutionOutOfRangeIsAnOptionsError) {
  ReportOptions o = options();
  o.resolutionDpi = 10;
  const QString pdf = dir_.filePath(QStringLiteral("lowres.pdf"));
  EXPECT_THROW(writeReport(project_, pdf, o), OptionsError);
  EXPECT_FALSE(QFileInfo::exists(pdf));
}

// The real CAIVIAC spindle log (11 115 rows x 22 channels) once the demo bundles it: the report
// stays small (decimated vector chart) and lists all 22 channels.
TEST(ReportReal, CaiviacSpindleLog) {
  const QString csv = QDir(qEnvironmentVariable("METROFIT_SOURCE_DIR"))
                          .filePath(QStringLiteral("resources/demo/data/thermal_caiviac.csv"));
  ASSERT_TRUE(QFileInfo::exists(csv)) << "the demo bundles the real log: " << csv.toStdString();
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  Project p;
  p.name = "CAIVIAC spindle";
  p.datasets.push_back({"caiviac",
                        dataset_kind::kThermalLog,
                        QFileInfo(csv).absoluteFilePath().toStdString(),
                        "Spindle thermal drift, 16 temperatures, 5 displacements.",
                        "MIT (CAIVIAC)",
                        {}});
  p.studies["thermal"] = {{"dataset", "caiviac"}};
  const QString projectPath = dir.filePath(QStringLiteral("caiviac.metrofit"));
  saveProject(p, projectPath.toStdString());
  ReportOptions o;
  o.projectPath = projectPath;
  const QString pdf = dir.filePath(QStringLiteral("caiviac.pdf"));
  const ReportSummary summary = writeReport(p, pdf, o);
  EXPECT_EQ(summary.sections, QStringList{QStringLiteral("Thermal")});
  EXPECT_EQ(pdfPages(pdf), summary.pages);
  EXPECT_LT(QFileInfo(pdf).size(), 3 * 1024 * 1024);
  const ProcessResult text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  for (const char* needle : {"t16_degC", "ch5_um", "spindle_rpm", "speed (rpm)", "6 heating, 6 cooling"}) {
    EXPECT_TRUE(text.out.contains(QString::fromUtf8(needle))) << "missing: " << needle;
  }
  const QString prefix = QDir(outputDir()).filePath(QStringLiteral("report_caiviac"));
  ASSERT_EQ(run(QStringLiteral("pdftoppm"),
                {QStringLiteral("-r"), QStringLiteral("110"), QStringLiteral("-png"), QStringLiteral("-f"),
                 QStringLiteral("2"), QStringLiteral("-l"), QStringLiteral("2"), pdf, prefix})
                .exitCode,
            0);
}

// One model's failure marks that model only: on a noise-free log whose target is exactly linear in its
// one input (3.25 um/K, written with every decimal), GMC(1,N)'s least squares is rank deficient. The
// thermal section still has the models' table: GMC(1,N)'s row says "not fitted" with the reason, the
// linear model's held-out row its RMSE of 0 (an exact fit), and the conclusion names a fitted model.
TEST_F(ReportTest, AModelThatCannotBeFittedIsMarkedAndTheOthersAreReported) {
  std::ostringstream csv;
  csv << "time_s,T1,disp_z_um\n";
  for (int r = 0; r < 120; ++r) {
    const double t = 30.0 * r;
    const double temperature = std::round((21.0 + 9.0 * (1.0 - std::exp(-t / 1500.0))) * 1e4) / 1e4;
    char line[96];
    metrofit::c_snprintf(line, sizeof line, "%d,%.4f,%.6f\n", static_cast<int>(t), temperature,
                         3.25 * (temperature - 21.0) - 0.8);
    csv << line;
  }
  writeText(dir_.filePath(QStringLiteral("data/linear.csv")), csv.str());
  Project p;
  p.name = "Linear log";
  p.datasets.push_back({"spindel", dataset_kind::kThermalLog, "data/linear.csv", "", "", {}});
  p.studies["thermal"] = {{"dataset", "spindel"}, {"target", "disp_z_um"}, {"inputs", {"T1"}}};
  const QString projectPath = dir_.filePath(QStringLiteral("linear.metrofit"));
  saveProject(p, projectPath.toStdString());
  ReportOptions o;
  o.projectPath = projectPath;
  const QString pdf = dir_.filePath(QStringLiteral("linear.pdf"));
  writeReport(loadProject(projectPath.toStdString()), pdf, o);
  QString text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).out;
  text.replace(QRegularExpression(QStringLiteral("\\s+")), QStringLiteral(" "));
  EXPECT_FALSE(text.contains(QStringLiteral("could not be fitted:"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("Performance indices"))) << text.toStdString();
  EXPECT_TRUE(
      text.contains(QStringLiteral("not fitted: the GMC(1,N) least-squares system is rank deficient")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("GMC(1,N) could not be fitted (the GMC(1,N) least-squares")))
      << text.toStdString();
  // The linear model's rows (pdftotext -layout keeps a table row on one line): fitted and held out on
  // 60 rows each, R = E = 1 and an RMSE and band of 0.00 um (an exact fit; the target reaches 26 um).
  const QString layout =
      run(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")}).out;
  const QRegularExpression linearRows(
      QStringLiteral("\\n\\s*linear\\s+fit, 60\\s+1\\.0000\\s+0\\.00\\s+1\\.0000\\s+±0\\.00\\s*\\n"
                     "\\s*held out, 60\\s+1\\.0000\\s+0\\.00\\s+1\\.0000\\s+±0\\.00\\s+usable"));
  EXPECT_TRUE(linearRows.match(layout).hasMatch()) << layout.toStdString();
  EXPECT_FALSE(text.contains(
      QRegularExpression(QStringLiteral("\\bnan\\b"), QRegularExpression::CaseInsensitiveOption)));
  const QString prefix = QDir(outputDir()).filePath(QStringLiteral("report_one_model_not_fitted"));
  run(QStringLiteral("pdftoppm"),
      {QStringLiteral("-r"), QStringLiteral("80"), QStringLiteral("-png"), QStringLiteral("-f"),
       QStringLiteral("2"), QStringLiteral("-l"), QStringLiteral("3"), pdf, prefix});
}

// The modular case as the project declares it: studies.thermal.modules names a new C test for the C
// module (the Modular tab's "Identify again…"). A two-drive plant written out here: Z and C drive
// nodes are first-order lags (tau 20 and 15 min), the ram grows -5 um/K dTz + kc dTc plus 0.1 um
// noise; the Z and C tests have kc = -3, the combined test and the new C test kc = -4. With the key the
// report's modules predict the combined test within 0.15 um (the noise and the estimation error) and
// say where C was identified; without it, C of the old machine leaves more than 1 um.
TEST_F(ReportTest, TheModularSectionUsesTheModuleTestsOfTheThermalStudy) {
  const auto plant = [](double z, double c, double kc, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.1);
    std::string csv = "time_min,Tz,Tc,disp_z_um\n";
    double tz = 20.0, tc = 20.0;
    for (int k = 0; k <= 240; ++k) {
      char line[128];
      metrofit::c_snprintf(line, sizeof line, "%d,%.6f,%.6f,%.6f\n", k, tz, tc,
                           -5.0 * (tz - 20.0) + kc * (tc - 20.0) + noise(rng));
      csv += line;
      const double uz = k < 120 ? 8.0 * z : 0.0, uc = k < 120 ? 6.0 * c : 0.0;
      tz = 20.0 + uz + (tz - 20.0 - uz) * std::exp(-1.0 / 20.0);
      tc = 20.0 + uc + (tc - 20.0 - uc) * std::exp(-1.0 / 15.0);
    }
    return csv;
  };
  writeText(dir_.filePath(QStringLiteral("data/z.csv")), plant(1, 0, -3.0, 1));
  writeText(dir_.filePath(QStringLiteral("data/c.csv")), plant(0, 1, -3.0, 2));
  writeText(dir_.filePath(QStringLiteral("data/combined.csv")), plant(0.5, 0.5, -4.0, 5));
  writeText(dir_.filePath(QStringLiteral("data/c_new.csv")), plant(0, 1, -4.0, 4));
  Project p;
  p.name = "Two drives";
  p.datasets.push_back({"thermal_modular_z", dataset_kind::kThermalLog, "data/z.csv", "", "", {}});
  p.datasets.push_back({"thermal_modular_c", dataset_kind::kThermalLog, "data/c.csv", "", "", {}});
  p.datasets.push_back(
      {"thermal_modular_combined", dataset_kind::kThermalLog, "data/combined.csv", "", "", {}});
  p.datasets.push_back({"c_after_bearings", dataset_kind::kThermalLog, "data/c_new.csv", "", "", {}});
  p.studies["thermal"] = {{"dataset", "thermal_modular_combined"}};
  // The modules' row of the modular table (text with whitespace runs as one space): its RMSE.
  const auto modulesRmse = [](const QString& text) {
    const QRegularExpressionMatch m =
        QRegularExpression(
            QStringLiteral("modules, summed \\(distributed lag\\)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+) %\\s+(\\S+)"))
            .match(text);
    bool ok = false;
    const double rmse = m.hasMatch() ? m.captured(4).toDouble(&ok) : -1.0;
    return ok ? rmse : -1.0;  // -1: not found or not a number; the callers expect a positive rmse
  };
  for (const bool declared : {false, true}) {
    if (declared)
      p.studies["thermal"]["modules"] = {{"thermal_modular_c", {{"dataset", "c_after_bearings"}}}};
    const QString projectPath = dir_.filePath(QStringLiteral("modules.metrofit"));
    saveProject(p, projectPath.toStdString());
    ReportOptions o;
    o.projectPath = projectPath;
    const QString pdf = dir_.filePath(declared ? QStringLiteral("declared.pdf") : QStringLiteral("own.pdf"));
    writeReport(loadProject(projectPath.toStdString()), pdf, o);
    QString text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).out;
    text.replace(QRegularExpression(QStringLiteral("\\s+")), QStringLiteral(" "));
    const double rmse = modulesRmse(text);
    if (declared) {
      EXPECT_TRUE(text.contains(QStringLiteral("(identified again on c_after_bearings)")))
          << text.toStdString();
      EXPECT_GE(rmse, 0.0) << text.toStdString();
      EXPECT_LT(rmse, 0.15) << text.toStdString();
    } else {
      EXPECT_FALSE(text.contains(QStringLiteral("identified again on"))) << text.toStdString();
      EXPECT_GT(rmse, 1.0) << text.toStdString();
    }
  }
}

/// The text of one page (1-based) of a PDF.
QString pageText(const QString& pdf, int page) {
  return run(QStringLiteral("pdftotext"), {QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"),
                                           QString::number(page), pdf, QStringLiteral("-")})
      .out;
}

// Page 1 is the summary; every section ends with its conclusion; references and the
// data-provenance appendix close the report; a thermal model is judged usable or not.
TEST_F(ReportTest, PageOneSummarisesAndSectionsConclude) {
  const QString pdf = dir_.filePath(QStringLiteral("summary.pdf"));
  const ReportSummary summary = writeReport(project_, pdf, options());
  const QString page1 = pageText(pdf, 1);
  for (const char* needle :
       {"What each study found", "What to change on the machine", "Error before and after",
        "What was measured", "thermal_run", "CC0-1.0", "Contents:"}) {
    EXPECT_TRUE(page1.contains(QString::fromUtf8(needle))) << "page 1 lacks: " << needle << "\n"
                                                           << page1.toStdString();
  }
  // The thermal finding names the best usable model (or says none is usable) with its unit.
  EXPECT_TRUE(page1.contains(QRegularExpression(QStringLiteral("Best usable model of disp_z_um: \\S+"))) ||
              page1.contains(QStringLiteral("No model of disp_z_um passes the held-out test")))
      << page1.toStdString();
  // The matching finding: what to change, with units.
  EXPECT_TRUE(page1.contains(
      QRegularExpression(QStringLiteral("SX -?\\d+\\.\\d+,\\s+SY -?\\d+\\.\\d+,\\s+SZ -?\\d+\\.\\d+\\s+mm"))))
      << page1.toStdString();

  const QString all = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).out;
  // The posture also as a controller frame for the three controls, in their own words.
  for (const char* block : {"PLANE SPATIAL SPA", "CYCL DEF 7.1 X", "AROT Z=", "TRANS X=", "G68.2 X"})
    EXPECT_TRUE(all.contains(QString::fromUtf8(block))) << "the report lacks the frame block " << block;
  EXPECT_EQ(all.count(QStringLiteral("Conclusion")), 2);  // thermal, matching (probe points has none)
  EXPECT_GE(all.count(QStringLiteral("Recommendation: ")), 2);
  EXPECT_TRUE(all.contains(QStringLiteral("References")));
  EXPECT_TRUE(all.contains(QStringLiteral("Abdulshahed")));
  EXPECT_TRUE(all.contains(QStringLiteral("Table 4 of [4]")));
  EXPECT_TRUE(all.contains(QStringLiteral("Appendix: data provenance")));
  EXPECT_TRUE(all.contains(QStringLiteral("Spindle warm-up and cool-down (synthetic).")));
  EXPECT_TRUE(all.contains(QStringLiteral("verdict")));
  EXPECT_TRUE(all.contains(QStringLiteral("usable")));
  // No internal words where the user reads.
  for (const char* word : {"seed 00", "core/", ".cpp", "issue ", " um ", "+-", "->"})
    EXPECT_FALSE(all.contains(QString::fromUtf8(word))) << "the report says: " << word;
  EXPECT_EQ(summary.pages, pdfPages(pdf));
}

// Nothing is elided or cut: long ids, file names and the title wrap instead.
TEST_F(ReportTest, NoElidedOrClippedText) {
  Project p = project_;
  p.name =
      "A very long project name that would not fit into the running header of a page at the small size "
      "it is printed in, repeated: a very long project name";
  p.datasets[0].id = "thermal_run_of_the_spindle_with_a_particularly_long_identifier";
  p.datasets[0].licence =
      "Creative Commons Zero v1.0 Universal, see LICENSE-CC0-1.0-for-the-thermal-data.txt";
  p.studies["thermal"]["dataset"] = p.datasets[0].id;
  const QString pdf = dir_.filePath(QStringLiteral("long.pdf"));
  writeReport(p, pdf, options());
  const QString text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).out;
  ASSERT_FALSE(text.isEmpty());
  EXPECT_FALSE(text.contains(QChar(0x2026))) << "elided text in the report";
  EXPECT_FALSE(text.contains(QStringLiteral("...")));
  // Wrapped, but every character is there (pdftotext joins the wrapped lines with a newline).
  QString joined = text;
  joined.remove(QLatin1Char('\n'));
  EXPECT_TRUE(
      joined.contains(QStringLiteral("thermal_run_of_the_spindle_with_a_particularly_long_identifier")));
  EXPECT_TRUE(joined.contains(QStringLiteral("LICENSE-CC0-1.0-for-the-thermal-data.txt")));
}

// A bad study setting is an error naming the study and the field, before any PDF.
TEST_F(ReportTest, BadStudySettingsAreErrorsNotDefaults) {
  struct Case {
    std::function<void(Project&)> spoil;
    std::string field;
  };
  const std::vector<Case> cases = {
      {[](Project& p) { p.studies["thermal"]["target"] = "disp_x_um"; }, "studies.thermal.target"},
      {[](Project& p) {
         p.studies["thermal"]["inputs"] = {"T1", "T7"};
       },
       "studies.thermal.inputs"},
      {[](Project& p) { p.studies["thermal"]["train_fraction"] = 2; }, "studies.thermal.train_fraction"},
      {[](Project& p) { p.studies["thermal"]["colour"] = "red"; }, "studies.thermal.colour"},
      {[](Project& p) { p.studies["thermal"]["dataset"] = "probe_block"; }, "studies.thermal.dataset"},
      {[](Project& p) { p.studies["termal"] = nlohmann::json::object(); }, "studies.termal"},
      {[](Project& p) { p.datasets[1].kind = "probe-points"; }, "datasets[1].kind"},
  };
  for (const Case& c : cases) {
    Project p = project_;
    c.spoil(p);
    const QString pdf = dir_.filePath(QStringLiteral("bad.pdf"));
    try {
      writeReport(p, pdf, options());
      ADD_FAILURE() << "accepted: " << c.field;
    } catch (const ValidationError& e) {
      EXPECT_EQ(e.context().field, c.field) << e.what();
      EXPECT_NE(std::string(e.what()).find("cell.metrofit"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(QFileInfo::exists(pdf)) << c.field;
  }
}

// Sections report only the studies the project declares.
TEST_F(ReportTest, OnlyDeclaredStudiesHaveSections) {
  Project p = project_;
  p.datasets.push_back({"second_run", dataset_kind::kThermalLog, "data/thermal.csv", "", "", {}});
  p.studies.erase("matching");
  const QString pdf = dir_.filePath(QStringLiteral("declared.pdf"));
  const ReportSummary summary = writeReport(p, pdf, options());
  EXPECT_EQ(summary.sections, QStringList{QStringLiteral("Thermal")});
  const QString text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")}).out;
  EXPECT_TRUE(text.contains(QStringLiteral("Thermal log “thermal_run”")));
  EXPECT_FALSE(text.contains(QStringLiteral("Thermal log “second_run”")));
  EXPECT_TRUE(text.contains(QStringLiteral("second_run")));  // in the appendix
}

// A shop charting a part series on the kinematics study without any circular test: the report has the
// section with the SPC charts and the indices (the walk's project had none: issue 28). The series is
// written here: 50 diameters, subgroups of 5, every subgroup mean 20.000 + 0.001 * (k mod 3) mm.
TEST_F(ReportTest, APartSeriesWithoutACircularTestHasItsSpcPages) {
  std::ostringstream csv;
  csv << "part,diameter_mm\n";
  const double within[5] = {-0.002, -0.001, 0.0, 0.001, 0.002};
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 5; ++j) csv << k * 5 + j + 1 << ',' << 20.0 + 0.001 * (k % 3) + within[j] << '\n';
  writeText(dir_.filePath(QStringLiteral("data/diameters.csv")), csv.str());
  Project p = project_;
  p.studies.erase("thermal");
  p.studies.erase("matching");
  p.datasets.push_back({"diameters", dataset_kind::kFeatureSeries, "data/diameters.csv", "", "", {}});
  p.studies["kinematics"] = {{"spc",
                              {{"dataset", "diameters"},
                               {"column", "diameter_mm"},
                               {"subgroup", 5},
                               {"lsl", 19.99},
                               {"usl", 20.01}}}};
  const QString pdf = dir_.filePath(QStringLiteral("spc_only.pdf"));
  const ReportSummary summary = writeReport(p, pdf, options());
  ASSERT_EQ(summary.sections.size(), 1) << summary.sections.join(QLatin1Char('|')).toStdString();
  const QString text =
      run(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")}).out;
  EXPECT_TRUE(text.contains(QStringLiteral("Statistical process control of “diameter_mm” (diameters)")));
  EXPECT_TRUE(text.contains(QStringLiteral("The project has no circular test")));
  // X-bar CL: the grand mean 20 + 0.001 * (4 * 0 + 3 * 1 + 3 * 2) / 10 = 20.0009 mm.
  EXPECT_TRUE(text.contains(QStringLiteral("20.0009"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("SPC of diameter_mm: in control.")));
  EXPECT_FALSE(text.contains(QStringLiteral("Cannot analyse the circular test")));
}

// A probe-point dataset whose nominals are a CAD part (a box written as STL): the report's matching
// section runs the study on the part, says so, and draws the part coloured under the points; the page
// with the views has the part's light grey and coloured faces (rendered with pdftoppm, kept for a look).
TEST_F(ReportTest, ACadNominalIsMatchedAndTheColouredPartIsDrawn) {
  writeText(dir_.filePath(QStringLiteral("data/box.stl")), test::boxStl(100, 60, 40));
  QString csv = QStringLiteral("id,x,y,z\n");
  int k = 0;
  // The bottom, front and left faces probed, 20 um high on the bottom; top, back and right not probed.
  for (double x : {20.0, 50.0, 80.0})
    for (double y : {15.0, 45.0})
      csv += QStringLiteral("B%1,%2,%3,0.02\n").arg(++k).arg(x + 0.1).arg(y - 0.05);
  for (double x : {20.0, 60.0, 90.0})
    csv += QStringLiteral("F%1,%2,-0.05,%3\n").arg(++k).arg(x + 0.1).arg(20.0);
  for (double y : {10.0, 30.0, 50.0})
    csv += QStringLiteral("L%1,0.1,%2,%3\n").arg(++k).arg(y - 0.05).arg(15.0 + y / 5);
  writeText(dir_.filePath(QStringLiteral("data/box_points.csv")), csv.toStdString());
  Project p = project_;
  p.datasets.push_back({"box", dataset_kind::kCadModel, "data/box.stl", "The part.", "", {}});
  DatasetRef points{"box_points", dataset_kind::kProbePoints, "data/box_points.csv", "", "", {}};
  points.nominals.from = "cad";
  points.nominals.cad = "box";
  p.datasets.push_back(points);
  p.studies["matching"] = {{"dataset", "box_points"}, {"tolerance_mm", 0.05}, {"method", "closed-form"}};
  const QString pdf = dir_.filePath(QStringLiteral("cad.pdf"));
  writeReport(p, pdf, options());
  const ProcessResult text = run(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
  ASSERT_EQ(text.exitCode, 0);
  const QString t = text.out.simplified();
  EXPECT_TRUE(t.contains(QStringLiteral("The nominal is the CAD part “box” (12 triangles)")))
      << t.toStdString();
  // Find the page with the views and look at it.
  const QString prefix = QDir(outputDir()).filePath(QStringLiteral("report_cad"));
  ASSERT_EQ(run(QStringLiteral("pdftoppm"),
                {QStringLiteral("-r"), QStringLiteral("60"), QStringLiteral("-png"), pdf, prefix})
                .exitCode,
            0);
  int bestGrey = 0;
  for (const QFileInfo& f : QDir(outputDir()).entryInfoList({QStringLiteral("report_cad*.png")})) {
    const QImage img = QImage(f.filePath()).convertToFormat(QImage::Format_RGB32);
    int grey = 0;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x) {
        const QColor c = img.pixelColor(x, y);
        // The unprobed faces: light grey (0xdc at 55 % on white: about 0xe8), not text black or white.
        if (std::abs(c.red() - c.green()) < 4 && std::abs(c.green() - c.blue()) < 4 && c.red() > 225 &&
            c.red() < 240)
          ++grey;
      }
    bestGrey = std::max(bestGrey, grey);
  }
  EXPECT_GT(bestGrey, 500) << "no page shows the part's unprobed faces";
}

}  // namespace
}  // namespace metrofit
