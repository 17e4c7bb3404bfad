#pragma once
// Zoom, pan and a value read-out for a Qt Charts view: one call, enableChartNavigation(view), used by
// every QChartView of the pages. On the view
// - the mouse wheel zooms around the cursor (Shift + wheel: the x axis only). In a page that scrolls
//   (a QScrollArea with a scroll bar shown) the plain wheel scrolls the page and Ctrl + wheel zooms;
// - a left-button drag pans, a Shift + left-button drag draws a rectangle to zoom into;
// - a double click, the Home key or "Reset zoom" in the context menu shows the whole chart again
//   (the axis ranges the chart had before the first zoom; a range the program sets later, for new
//   data, becomes the new whole chart);
// - a label follows the cursor over the plot area with the data point nearest to it (a ring marks
//   it): the series name and both coordinates, named and with the units of the axis titles
//   ("time (min)" -> "time: 12.5 min"), numbers in the UI language's format (QLocale()).
// The chart may be replaced (QChartView::setChart) at any time: the navigation acts on the view's
// current chart.
#include <QString>
#include <limits>

class QPoint;
class QWidget;

namespace metrofit {

/// Adds zoom, pan, reset and the cursor label to a QChartView (passed as QWidget: Qt Charts stays
/// out of the headers). Anything else is left alone. Calling it twice changes nothing.
void enableChartNavigation(QWidget* chartView);
/// True when enableChartNavigation() was called for `chartView`.
bool hasChartNavigation(const QWidget* chartView);
/// Gives the chart back its axis ranges from before the first zoom or pan; false when not zoomed.
bool resetChartZoom(QWidget* chartView);
/// True after a zoom or pan that no reset (or new range set by the program) has undone.
bool isChartZoomed(const QWidget* chartView);
/// The text of the cursor label; empty while it is hidden.
QString chartCursorText(const QWidget* chartView);

/// The data point of a Qt Charts view nearest to viewport position `pos` (pixel distance), at most
/// `reachPx` away and inside the plot area: "series name\nx-name: x unit\ny-name: y unit" (no series
/// name line when the series has none). Empty when there is none.
QString chartNearestPointText(QWidget* chartView, const QPoint& pos,
                              double reachPx = std::numeric_limits<double>::infinity());

}  // namespace metrofit
