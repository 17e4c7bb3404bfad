#pragma once
// Export of any chart widget (a QChartView, a QPainter plot, a 3D view) as an image: one call,
// enableChartExport(), adds "Export as PNG…", "Export as SVG…" and "Copy image" to the widget's
// context menu. PNG and "Copy image" take the widget as it is drawn on screen (same size); SVG
// re-draws it through QSvgGenerator, so lines and text stay vectors. Views that draw with OpenGL
// (VTK) have no SVG entry, and their context menu opens on a right click without drag (a right
// drag zooms them). After an export the main window's status bar names the file. On a Qt Charts
// view, the tooltip shows the data point under the mouse: series name and both coordinates with the
// units of the axis titles ("time (h)" -> "time: 1.5 h"), numbers in the user's locale; the chart's
// axis labels use that locale too (QChart::localizeNumbers; the report's charts stay '.'-decimal).
#include <QImage>
#include <QString>
#include <functional>

class QPoint;
class QWidget;

namespace metrofit {

/// Makes the picture of a chart; empty: the widget's own grab().
using ChartImageProvider = std::function<QImage()>;

/// Adds the export entries to `chart`'s context menu (Qt::ActionsContextMenu). `baseName` is the
/// file name suggested in the save dialog (without suffix). Calling it twice changes nothing.
void enableChartExport(QWidget* chart, const QString& baseName, ChartImageProvider image = {});

/// True when enableChartExport() was called for `chart`.
bool hasChartExport(const QWidget* chart);
/// False for views that draw with OpenGL (their picture is a bitmap only).
bool chartCanExportSvg(const QWidget* chart);
/// The picture of the chart at its widget size (the provider given to enableChartExport, else grab()).
QImage chartImage(QWidget* chart);
/// Writes the chart as PNG / SVG. On failure returns false and, when given, a readable *error.
bool exportChartPng(QWidget* chart, const QString& path, QString* error = nullptr);
bool exportChartSvg(QWidget* chart, const QString& path, QString* error = nullptr);
/// The tooltip text for viewport position `pos` of a Qt Charts view (empty: no data point within 8 px).
QString chartPointTooltip(QWidget* chartView, const QPoint& pos);

}  // namespace metrofit
