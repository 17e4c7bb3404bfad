// `metrofit --screenshots DIR` (docs/file-formats.md#screenshots), run as a user would: under xvfb-run it
// writes one non-blank PNG per main view and exits 0; without an X server it exits 2 with one clear line.
#include <gtest/gtest.h>

#include <QColor>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QHash>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <algorithm>
#include <memory>

#include "core/project/project.h"
#include "testsupport.h"

namespace {

constexpr const char* kNeedX =
    "metrofit: --screenshots needs an X server for the 3D views; run under xvfb-run -a";

/// QProcess wants a QCoreApplication; this test has no GUI of its own.
class CoreApplicationEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { app_ = std::make_unique<QCoreApplication>(argc_, argv_); }
  void TearDown() override { app_.reset(); }

 private:
  int argc_ = 1;
  char name_[17] = "screenshots_test";
  char* argv_[2] = {name_, nullptr};
  std::unique_ptr<QCoreApplication> app_;
};
::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new CoreApplicationEnvironment);

struct ProcessResult {
  int exitCode = -1;
  bool crashed = false;
  QString stdErr;
};

/// The metrofit executable: $METROFIT_BIN_DIR/metrofit, else the one this test was built with.
QString metrofitBinary() {
  const QString bin = qEnvironmentVariable("METROFIT_BIN_DIR");
  return bin.isEmpty() ? QStringLiteral(METROFIT_GUI_EXECUTABLE)
                       : QDir(bin).filePath(QStringLiteral("metrofit"));
}

ProcessResult run(const QString& program, const QStringList& arguments, QProcessEnvironment env) {
  // Qt warns on stderr without a private runtime folder; the checks below read stderr.
  static const QTemporaryDir runtime;  // mode 0700
  if (env.value(QStringLiteral("XDG_RUNTIME_DIR")).isEmpty())
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), runtime.path());
  QProcess process;
  process.setProcessEnvironment(env);
  process.start(program, arguments);
  ProcessResult r;
  if (!process.waitForStarted(10000)) {
    r.stdErr = QStringLiteral("cannot start ") + program;
    return r;
  }
  if (!process.waitForFinished(90000)) {
    process.kill();
    process.waitForFinished(5000);
    r.stdErr = QStringLiteral("timed out: ") + QString::fromLocal8Bit(process.readAllStandardError());
    return r;
  }
  r.crashed = process.exitStatus() != QProcess::NormalExit;
  r.exitCode = process.exitCode();
  r.stdErr = QString::fromLocal8Bit(process.readAllStandardError());
  return r;
}

ProcessResult runUnderXvfb(const QStringList& metrofitArguments) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
  // The same wrapper as the XVFB tests' executor (display search of its own, one retry when
  // xvfb-run itself fails).
  return run(QStringLiteral(METROFIT_XVFB_RUN), QStringList{metrofitBinary()} + metrofitArguments, env);
}

/// A fresh folder for a run's output: below $METROFIT_TEST_OUT (kept for people to look at), else
/// below a temporary folder of this process.
QString outputDir(const QString& name) {
  static const QTemporaryDir fallback;
  const QString base = qEnvironmentVariable("METROFIT_TEST_OUT", fallback.path());
  QDir dir(QDir(base).filePath(name));
  dir.removeRecursively();
  return dir.path();
}

/// The views every screenshot run must show: the list of docs/file-formats.md#screenshots in a fixed order,
/// then one trend view per further thermal log of the bundled demo project (in project order), then the
/// import dialog.
QStringList expectedShots() {
  QStringList names = {
      QStringLiteral("overview"),           QStringLiteral("setup-graph"),
      QStringLiteral("setup-convergence"),  QStringLiteral("matching-3d"),
      QStringLiteral("matching-frame"),     QStringLiteral("kinematics-path"),
      QStringLiteral("kinematics-spc"),     QStringLiteral("thermal-trend"),
      QStringLiteral("thermal-hysteresis"), QStringLiteral("thermal-models"),
      QStringLiteral("diagnosis"),          QStringLiteral("diagnosis-residual"),
  };
  const metrofit::Project demo =
      metrofit::loadProject((metrofit::test::sourceDir() / "resources/demo/demo.metrofit").string());
  const std::string firstLog = demo.studies.value("thermal", nlohmann::json::object()).value("dataset", "");
  for (const metrofit::DatasetRef& d : demo.datasets)
    if (d.kind == metrofit::dataset_kind::kThermalLog && d.id != firstLog)
      names << QStringLiteral("thermal-trend-") + QString::fromStdString(d.id);
  names << QStringLiteral("import-dialog");  // File › Import data… on a ';' / decimal-comma log
  QStringList files;
  for (int i = 0; i < names.size(); ++i)
    files << QStringLiteral("%1-%2.png").arg(i + 1, 2, 10, QLatin1Char('0')).arg(names[i]);
  return files;
}

TEST(ScreenshotsTest, WritesOneNonBlankPngPerView) {
  const QString dir = outputDir(QStringLiteral("screenshots"));
  const ProcessResult r = runUnderXvfb({QStringLiteral("--screenshots"), dir});
  ASSERT_FALSE(r.crashed) << r.stdErr.toStdString();
  ASSERT_EQ(r.exitCode, 0) << r.stdErr.toStdString();
  EXPECT_TRUE(r.stdErr.contains(QStringLiteral("screenshots written to"))) << r.stdErr.toStdString();

  const QStringList written = QDir(dir).entryList({QStringLiteral("*.png")}, QDir::Files, QDir::Name);
  const QStringList expected = expectedShots();
  EXPECT_EQ(written, expected);
  EXPECT_TRUE(expected.contains(QStringLiteral("13-thermal-trend-thermal_caiviac.png")));
  for (const QString& name : expected) {
    SCOPED_TRACE(name.toStdString());
    const QImage image(QDir(dir).filePath(name));
    ASSERT_FALSE(image.isNull());
    EXPECT_GE(image.width(), 800);
    EXPECT_GE(image.height(), 600);
    QHash<QRgb, qint64> histogram;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
      const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
      for (int x = 0; x < rgb.width(); ++x) ++histogram[line[x]];
    }
    qint64 largest = 0;
    for (const qint64 count : histogram) largest = std::max(largest, count);
    const double share = static_cast<double>(largest) / (static_cast<double>(rgb.width()) * rgb.height());
    EXPECT_GT(histogram.size(), 64) << "distinct colours";
    EXPECT_LT(share, 0.98) << "one colour covers " << share * 100 << " % of the image";
  }

  // The matching view shows the VTK scene, not the fallback text: the measured points are coloured
  // by deviation with a diverging map, so there are saturated red and blue pixels.
  const QImage matching =
      QImage(QDir(dir).filePath(QStringLiteral("04-matching-3d.png"))).convertToFormat(QImage::Format_RGB32);
  ASSERT_FALSE(matching.isNull());
  int reddish = 0;
  int bluish = 0;
  for (int y = 0; y < matching.height(); ++y) {
    for (int x = 0; x < matching.width(); ++x) {
      const QColor c = QColor::fromRgb(matching.pixel(x, y));
      if (c.red() > 150 && c.green() < 120 && c.blue() < 120) ++reddish;
      if (c.blue() > 150 && c.red() < 140 && c.green() < 170) ++bluish;
    }
  }
  EXPECT_GT(reddish, 50) << "red deviation markers in the 3D view";
  EXPECT_GT(bluish, 50) << "blue deviation markers in the 3D view";
}

TEST(ScreenshotsTest, WithoutAnXServerExitsTwoWithOneLine) {
  const QString dir = outputDir(QStringLiteral("screenshots-nox"));
  for (const bool offscreen : {true, false}) {
    SCOPED_TRACE(offscreen ? "QT_QPA_PLATFORM=offscreen" : "no QT_QPA_PLATFORM");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    if (offscreen) env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    const ProcessResult r = run(metrofitBinary(), {QStringLiteral("--screenshots"), dir}, env);
    EXPECT_FALSE(r.crashed);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.stdErr, QString::fromLatin1(kNeedX) + QLatin1Char('\n'));
    EXPECT_TRUE(QDir(dir).entryList({QStringLiteral("*.png")}, QDir::Files).isEmpty());
  }
}

TEST(ScreenshotsTest, UnwritableFolderExitsOne) {
  QTemporaryDir tmp;
  ASSERT_TRUE(tmp.isValid());
  QFile blocker(tmp.filePath(QStringLiteral("blocker")));
  ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
  blocker.close();
  const ProcessResult r =
      runUnderXvfb({QStringLiteral("--screenshots"), tmp.filePath(QStringLiteral("blocker/shots"))});
  EXPECT_FALSE(r.crashed);
  EXPECT_EQ(r.exitCode, 1) << r.stdErr.toStdString();
  const QStringList lines = r.stdErr.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
  ASSERT_FALSE(lines.isEmpty());
  EXPECT_TRUE(lines.last().startsWith(QStringLiteral("metrofit: "))) << r.stdErr.toStdString();
  EXPECT_TRUE(r.stdErr.contains(QStringLiteral("blocker/shots"))) << r.stdErr.toStdString();
}

}  // namespace
