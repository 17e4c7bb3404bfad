#include "widgets/common/chartexport.h"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsView>
#include <QGuiApplication>
#include <QHelpEvent>
#include <QLegend>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QMouseEvent>
#include <QOpenGLWidget>
#include <QPainter>
#include <QPointer>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSvgGenerator>
#include <QToolTip>

#include "widgets/common/chartnavigation.h"

namespace metrofit {

namespace {

struct ChartExportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ChartExport)
};

const char* const kExporterName = "metrofitChartExporter";
const char* const kFolderKey = "ui/chartExportFolder";
constexpr int kStatusTimeoutMs = 5000;
constexpr int kClickSlopPx = 4;
constexpr double kTooltipReachPx = 8.0;

/// Numbers of a chart shown in a view: the user's locale (the report keeps its charts in C), and
/// legend labels shortened to fit get their full text as a tooltip. Once per chart.
void localizeChart(QChart* chart) {
  if (chart == nullptr || chart->property("metrofitLocalized").toBool()) return;
  chart->setProperty("metrofitLocalized", true);
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  chart->legend()->setShowToolTips(true);
}

/// Holds what enableChartExport() attached to a chart; a child QObject, so it dies with it.
class ChartExporter : public QObject {
 public:
  ChartExporter(QWidget* chart, QString baseName, ChartImageProvider image)
      : QObject(chart), chart_(chart), baseName_(std::move(baseName)), image_(std::move(image)) {
    setObjectName(QString::fromLatin1(kExporterName));
  }
  QImage image() const { return image_ ? image_() : chart_->grab().toImage(); }
  const QString& baseName() const { return baseName_; }

  // Right click without drag on an OpenGL child opens the menu (a right drag zooms there). On a Qt
  // Charts viewport a tooltip names the data point under the mouse with its units.
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Paint) {
      if (auto* view = qobject_cast<QChartView*>(chart_); view && watched == view->viewport())
        localizeChart(view->chart());
    } else if (event->type() == QEvent::ToolTip) {
      // A view with navigation shows the point in its cursor label instead.
      if (auto* view = qobject_cast<QChartView*>(chart_);
          view && watched == view->viewport() && !hasChartNavigation(view)) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QString text = chartNearestPointText(view, help->pos(), kTooltipReachPx);
        if (!text.isEmpty()) {
          QToolTip::showText(help->globalPos(), text, view->viewport());
          return true;
        }
      }
    } else if (event->type() == QEvent::MouseButtonPress) {
      auto* e = static_cast<QMouseEvent*>(event);
      if (e->button() == Qt::RightButton) pressPos_ = e->globalPosition().toPoint();
    } else if (event->type() == QEvent::MouseButtonRelease) {
      auto* e = static_cast<QMouseEvent*>(event);
      const QPoint pos = e->globalPosition().toPoint();
      if (e->button() == Qt::RightButton && (pos - pressPos_).manhattanLength() <= kClickSlopPx) {
        const QPointer<QWidget> chart(chart_);
        QMetaObject::invokeMethod(
            this,
            [chart, pos] {
              if (chart) QMenu::exec(chart->actions(), pos, nullptr, chart);
            },
            Qt::QueuedConnection);
      }
    }
    return QObject::eventFilter(watched, event);
  }

 private:
  QWidget* chart_;
  QString baseName_;
  ChartImageProvider image_;
  QPoint pressPos_;
};

ChartExporter* exporterOf(const QWidget* chart) {
  return chart ? dynamic_cast<ChartExporter*>(chart->findChild<QObject*>(QString::fromLatin1(kExporterName),
                                                                         Qt::FindDirectChildrenOnly))
               : nullptr;
}

bool drawsWithOpenGL(const QWidget* widget) {
  return qobject_cast<const QOpenGLWidget*>(widget) != nullptr ||
         !widget->findChildren<QOpenGLWidget*>().isEmpty();
}

void showStatus(QWidget* chart, const QString& message) {
  if (auto* window = qobject_cast<QMainWindow*>(chart->window()))
    window->statusBar()->showMessage(message, kStatusTimeoutMs);
}

QString exportFolder() {
  const QString stored = QSettings().value(QString::fromLatin1(kFolderKey)).toString();
  if (!stored.isEmpty() && QFileInfo(stored).isDir()) return stored;
  const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
  return pictures.isEmpty() ? QDir::homePath() : pictures;
}

void exportWithDialog(QWidget* chart, bool svg) {
  const ChartExporter* exporter = exporterOf(chart);
  const QString base =
      exporter && !exporter->baseName().isEmpty() ? exporter->baseName() : QStringLiteral("chart");
  const QString suffix = svg ? QStringLiteral(".svg") : QStringLiteral(".png");
  QString path = QFileDialog::getSaveFileName(
      chart, svg ? ChartExportText::tr("Export chart as SVG") : ChartExportText::tr("Export chart as PNG"),
      QDir(exportFolder()).filePath(base + suffix),
      svg ? ChartExportText::tr("SVG drawings (*.svg)") : ChartExportText::tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(suffix, Qt::CaseInsensitive)) path += suffix;
  QSettings().setValue(QString::fromLatin1(kFolderKey), QFileInfo(path).absolutePath());
  QString error;
  const bool ok = svg ? exportChartSvg(chart, path, &error) : exportChartPng(chart, path, &error);
  showStatus(chart, ok ? ChartExportText::tr("Chart exported to %1").arg(QDir::toNativeSeparators(path))
                       : ChartExportText::tr("Cannot export the chart: %1").arg(error));
}

}  // namespace

void enableChartExport(QWidget* chart, const QString& baseName, ChartImageProvider image) {
  if (chart == nullptr || exporterOf(chart) != nullptr) return;
  auto* exporter = new ChartExporter(chart, baseName, std::move(image));

  auto* png = new QAction(ChartExportText::tr("Export as &PNG…"), chart);
  png->setObjectName(QStringLiteral("chartExportPng"));
  png->setToolTip(ChartExportText::tr("Save this chart as a PNG image (the size it has on screen)"));
  QObject::connect(png, &QAction::triggered, chart, [chart] { exportWithDialog(chart, false); });
  chart->addAction(png);

  const bool opengl = drawsWithOpenGL(chart);
  if (!opengl) {
    auto* svg = new QAction(ChartExportText::tr("Export as &SVG…"), chart);
    svg->setObjectName(QStringLiteral("chartExportSvg"));
    svg->setToolTip(ChartExportText::tr("Save this chart as an SVG drawing (lines and text stay sharp)"));
    QObject::connect(svg, &QAction::triggered, chart, [chart] { exportWithDialog(chart, true); });
    chart->addAction(svg);
  }

  auto* copy = new QAction(ChartExportText::tr("&Copy image"), chart);
  copy->setObjectName(QStringLiteral("chartCopyImage"));
  QObject::connect(copy, &QAction::triggered, chart, [chart] {
    QGuiApplication::clipboard()->setImage(chartImage(chart));
    showStatus(chart, ChartExportText::tr("Chart copied to the clipboard"));
  });
  chart->addAction(copy);
  chart->setContextMenuPolicy(Qt::ActionsContextMenu);

  if (auto* view = qobject_cast<QChartView*>(chart)) view->viewport()->installEventFilter(exporter);
  if (opengl) {
    for (QOpenGLWidget* gl : chart->findChildren<QOpenGLWidget*>()) {
      gl->setContextMenuPolicy(Qt::PreventContextMenu);
      gl->installEventFilter(exporter);
    }
  }
}

QString chartPointTooltip(QWidget* chartView, const QPoint& pos) {
  return chartNearestPointText(chartView, pos, kTooltipReachPx);
}

bool hasChartExport(const QWidget* chart) {
  return exporterOf(chart) != nullptr;
}

bool chartCanExportSvg(const QWidget* chart) {
  return chart != nullptr && !drawsWithOpenGL(chart);
}

QImage chartImage(QWidget* chart) {
  if (chart == nullptr) return {};
  if (const ChartExporter* exporter = exporterOf(chart)) return exporter->image();
  return chart->grab().toImage();
}

bool exportChartPng(QWidget* chart, const QString& path, QString* error) {
  const QImage image = chartImage(chart);
  if (image.isNull()) {
    if (error) *error = ChartExportText::tr("the chart has no picture to export");
    return false;
  }
  if (!image.save(path, "PNG")) {
    if (error) *error = ChartExportText::tr("cannot write %1").arg(QDir::toNativeSeparators(path));
    return false;
  }
  return true;
}

bool exportChartSvg(QWidget* chart, const QString& path, QString* error) {
  if (!chartCanExportSvg(chart)) {
    if (error) *error = ChartExportText::tr("a 3D view can only be exported as PNG");
    return false;
  }
  auto* view = qobject_cast<QGraphicsView*>(chart);
  const QSize size = view ? view->viewport()->size() : chart->size();
  QSvgGenerator generator;
  generator.setFileName(path);
  generator.setSize(size);
  generator.setViewBox(QRect(QPoint(0, 0), size));
  generator.setTitle(exporterOf(chart) ? exporterOf(chart)->baseName() : QString());
  generator.setDescription(ChartExportText::tr("Exported from Metrofit"));
  QPainter painter;
  if (!painter.begin(&generator)) {
    if (error) *error = ChartExportText::tr("cannot write %1").arg(QDir::toNativeSeparators(path));
    return false;
  }
  painter.fillRect(QRect(QPoint(0, 0), size), chart->palette().color(QPalette::Base));
  if (view) {
    view->render(&painter, QRectF(QPointF(0, 0), QSizeF(size)), view->viewport()->rect());
  } else {
    chart->render(&painter, QPoint(), QRegion(), QWidget::DrawWindowBackground | QWidget::DrawChildren);
  }
  painter.end();
  if (!QFileInfo(path).isFile()) {
    if (error) *error = ChartExportText::tr("cannot write %1").arg(QDir::toNativeSeparators(path));
    return false;
  }
  return true;
}

}  // namespace metrofit
