#include "app/gui/screenshots.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMetaObject>
#include <QPixmap>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>
#include <QWindow>
#include <cmath>
#include <exception>
#include <functional>
#include <vector>

#include "app/gui/mainwindow.h"
#include "app/gui/matchingpage.h"
#include "app/gui/thermalpage.h"
#include "core/project/datasets.h"
#include "core/project/project.h"
#include "widgets/document/demoproject.h"
#include "widgets/document/projectdocument.h"
#include "widgets/importer/importdialog.h"

namespace metrofit {

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 800;
/// Time for a view to lay out and render (the first VTK frame takes about 0.4 s).
constexpr int kSettleMs = 700;

void settle(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

bool waitExposed(QWidget& window, int timeoutMs) {
  QElapsedTimer timer;
  timer.start();
  while (!(window.windowHandle() && window.windowHandle()->isExposed())) {
    if (timer.elapsed() > timeoutMs) return false;
    settle(20);
  }
  return true;
}

struct View {
  QString name;
  std::function<void(MainWindow&)> show;
};

}  // namespace

bool environmentHasXServer() {
  const QString platform = qEnvironmentVariable("QT_QPA_PLATFORM");
  const bool xcb =
      platform.isEmpty() || platform == QLatin1String("xcb") || platform.startsWith(QLatin1String("xcb:"));
  return xcb && !qEnvironmentVariableIsEmpty("DISPLAY");
}

int runScreenshots(const QString& outDir, QTextStream& err) {
  const QString dir = QDir(outDir).absolutePath();
  if (!QDir().mkpath(dir)) {
    err << "metrofit: cannot create the screenshot folder " << QDir::toNativeSeparators(dir) << Qt::endl;
    return 1;
  }
  QTemporaryDir work;
  if (!work.isValid()) {
    err << "metrofit: cannot create a temporary folder for the demo project: " << work.errorString()
        << Qt::endl;
    return 1;
  }
  QString projectPath;
  try {
    projectPath = extractDemoProject(work.path());
  } catch (const std::exception& e) {
    err << "metrofit: " << e.what() << Qt::endl;
    return 1;
  }

  MainWindow window;
  QString error;
  if (!window.openProject(projectPath, &error)) {
    err << "metrofit: cannot open the demo project: " << error << Qt::endl;
    return 1;
  }
  window.resize(kWidth, kHeight);
  window.show();
  if (!waitExposed(window, 10000)) {
    err << "metrofit: the window was not shown by the X server" << Qt::endl;
    return 1;
  }

  // The views of docs/file-formats.md#screenshots in a fixed order. Each shows a page and then asks the page
  // for one of its views through `Q_INVOKABLE void showView(const QString&)` when the page has it (pages
  // without sub-views just show themselves), so adding a view to a page needs no change here.
  const auto pageView = [](Page page, const QString& view) {
    return [page, view](MainWindow& w) {
      w.showPage(page);
      QWidget* widget = w.page(page);
      if (widget->metaObject()->indexOfMethod("showView(QString)") >= 0)
        QMetaObject::invokeMethod(widget, "showView", Qt::DirectConnection, Q_ARG(QString, view));
    };
  };
  std::vector<View> views = {
      {QStringLiteral("overview"), pageView(Page::Overview, {})},
      {QStringLiteral("setup-graph"), pageView(Page::Setup, QStringLiteral("graph"))},
      {QStringLiteral("setup-convergence"), pageView(Page::Setup, QStringLiteral("convergence"))},
      {QStringLiteral("matching-3d"), pageView(Page::Matching, QStringLiteral("3d"))},
      {QStringLiteral("matching-frame"), pageView(Page::Matching, QStringLiteral("frame"))},
      {QStringLiteral("kinematics-path"), pageView(Page::Kinematics, QStringLiteral("path"))},
      {QStringLiteral("kinematics-spc"), pageView(Page::Kinematics, QStringLiteral("spc"))},
      {QStringLiteral("thermal-trend"), pageView(Page::Thermal, QStringLiteral("trend"))},
      {QStringLiteral("thermal-hysteresis"), pageView(Page::Thermal, QStringLiteral("hysteresis"))},
      {QStringLiteral("thermal-models"), pageView(Page::Thermal, QStringLiteral("models"))},
      {QStringLiteral("diagnosis"), pageView(Page::Diagnosis, QStringLiteral("diagnosis"))},
      {QStringLiteral("diagnosis-residual"), pageView(Page::Diagnosis, QStringLiteral("residual"))},
  };
  // Every further thermal log of the project (the demo has a real one besides the simulated one).
  const ThermalPage* thermal = window.thermalPage();
  const QString firstLog = thermal->currentDataset();
  for (const DatasetRef& d : window.document()->project().datasets) {
    const QString id = QString::fromStdString(d.id);
    if (!datasetKindServes(dataset_kind::kThermalLog, d.kind) || id == firstLog) continue;
    views.push_back({QStringLiteral("thermal-trend-") + id, [id, pageView](MainWindow& w) {
                       pageView(Page::Thermal, QStringLiteral("trend"))(w);
                       w.thermalPage()->selectDataset(id);
                     }});
  }

  int number = 1;
  for (const View& view : views) {
    view.show(window);
    settle(kSettleMs);
    const QImage image = window.grab().toImage();
    const QString file =
        dir + QStringLiteral("/%1-%2.png").arg(number++, 2, 10, QLatin1Char('0')).arg(view.name);
    if (image.isNull() || !image.save(file, "PNG")) {
      err << "metrofit: cannot write the screenshot " << QDir::toNativeSeparators(file) << Qt::endl;
      return 1;
    }
  }
  window.thermalPage()->selectDataset(firstLog);

  // The import dialog (File › Import data…) on a thermal log as a German spreadsheet exports it:
  // ';' between fields, decimal commas, its own column names, the displacement mapped to disp_z_um.
  {
    const QString log = work.filePath(QStringLiteral("Aufwaermung Spindel.csv"));
    QFile f(log);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
      err << "metrofit: cannot write " << QDir::toNativeSeparators(log) << Qt::endl;
      return 1;
    }
    QByteArray text =
        "# Aufwärmversuch Spindel 8000 1/min, Maschine 4\n"
        "Zeit [s];Temp Spindel;Temp Bett;Verlagerung Z [µm]\n";
    for (int row = 0; row < 240; ++row) {
      const double t = 30.0 * row;
      const double spindle = 21.0 + 9.0 * (1.0 - std::exp(-t / 1500.0));
      const double bed = 20.5 + 1.5 * (1.0 - std::exp(-t / 4000.0));
      text += QStringLiteral("%1;%2;%3;%4\n")
                  .arg(t, 0, 'f', 0)
                  .arg(spindle, 0, 'f', 3)
                  .arg(bed, 0, 'f', 3)
                  .arg(3.25 * (spindle - 21.0) + 1.1 * (bed - 20.5), 0, 'f', 2)
                  .replace(QLatin1Char('.'), QLatin1Char(','))
                  .toUtf8();
    }
    f.write(text);
    f.close();
    ImportDialog dialog(window.document()->project(), window.document()->projectPathForDatasets(), &window);
    dialog.setFile(log);
    dialog.setRole(QStringLiteral("Temp Spindel"), QStringLiteral("T1"));
    dialog.setRole(QStringLiteral("Temp Bett"), QStringLiteral("T2"));
    dialog.setRole(QStringLiteral("Verlagerung Z [µm]"), QStringLiteral("disp_z_um"));
    dialog.show();
    if (!waitExposed(dialog, 10000)) {
      err << "metrofit: the import dialog was not shown by the X server" << Qt::endl;
      return 1;
    }
    settle(kSettleMs);
    const QImage image = dialog.grab().toImage();
    const QString file = dir + QStringLiteral("/%1-import-dialog.png").arg(number++, 2, 10, QLatin1Char('0'));
    if (image.isNull() || !image.save(file, "PNG")) {
      err << "metrofit: cannot write the screenshot " << QDir::toNativeSeparators(file) << Qt::endl;
      return 1;
    }
  }
  err << "metrofit: " << views.size() + 1 << " screenshots written to " << QDir::toNativeSeparators(dir)
      << Qt::endl;
  return 0;
}

}  // namespace metrofit
