#pragma once
// Zoom, pan and a value read-out for the QPainter plots (the kinematics & SPC views: path, polar plot,
// control charts, histogram), as chartnavigation.h gives them to the Qt Charts views. On the widget
// - the mouse wheel magnifies around the cursor (1.25 per notch, up to 50 x; in a page that scrolls,
//   Ctrl + wheel, the plain wheel scrolls the page);
// - a left-button drag pans a magnified plot;
// - a double click, the Home key or "Reset zoom" in the context menu shows the whole plot again;
// - a label follows the cursor with what the plot shows there (the view's read-out: the nearest
//   point with its values and units, numbers in the UI language's format).
// The view paints through plotViewTransform() (QPainter::setTransform) and asks the read-out in its
// own, unmagnified coordinates, so its layout classes stay as they are (and the report, which paints
// the same plots, is not affected).
#include <QPointF>
#include <QString>
#include <QTransform>
#include <functional>

class QWidget;

namespace metrofit {

/// What the plot shows at `plotPos` (the widget's unmagnified coordinates), given the magnification
/// `scale` (a reach in pixels on screen is reach / scale in plot coordinates); empty: nothing there.
using PlotReadout = std::function<QString(const QPointF& plotPos, double scale)>;

/// Adds zoom, pan, reset and the cursor label to a QPainter plot widget. Calling it twice changes
/// nothing (the first read-out stays).
void enablePlotNavigation(QWidget* plot, PlotReadout readout);
/// True when enablePlotNavigation() was called for `plot`.
bool hasPlotNavigation(const QWidget* plot);
/// The magnification and pan to paint with (identity when not zoomed or without navigation).
QTransform plotViewTransform(const QWidget* plot);
/// Shows the whole plot again; false when it was not zoomed.
bool resetPlotZoom(QWidget* plot);
/// True while the plot is magnified.
bool isPlotZoomed(const QWidget* plot);
/// Magnifies by `factor` around widget position `at` (what the wheel does), for tests and keys.
void zoomPlot(QWidget* plot, const QPointF& at, double factor);
/// The text of the cursor label; empty while it is hidden.
QString plotCursorText(const QWidget* plot);
/// The read-out at widget position `pos` (as the cursor label would show it), for tests.
QString plotReadoutAt(const QWidget* plot, const QPointF& pos);

}  // namespace metrofit
