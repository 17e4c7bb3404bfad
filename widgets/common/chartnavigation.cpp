#include "widgets/common/chartnavigation.h"

#include "widgets/common/cursorlabel.h"

#include <QAbstractAxis>
#include <QAction>
#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QEvent>
#include <QGraphicsEllipseItem>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QLogValueAxis>
#include <QMouseEvent>
#include <QPointer>
#include <QRegularExpression>
#include <QRubberBand>
#include <QScrollBar>
#include <QValueAxis>
#include <QWheelEvent>
#include <QXYSeries>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace metrofit {

namespace {

struct ChartNavigationText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ChartNavigation)
};

const char* const kNavigatorName = "metrofitChartNavigator";
constexpr double kWheelStepFactor = 1.25;  ///< zoom per wheel notch (120 eighths of a degree)
constexpr int kMinBandPx = 5;              ///< a smaller rubber band is a click, not a zoom
constexpr double kMarkerRadiusPx = 5.0;
constexpr int kLabelOffsetPx = 14;

/// "name (unit)" of an axis title split into its name and unit (no unit: the whole title).
std::pair<QString, QString> splitAxisTitle(const QString& title) {
  static const QRegularExpression withUnit(QStringLiteral("^(.*\\S)\\s*\\(([^()]+)\\)\\s*$"));
  const QRegularExpressionMatch m = withUnit.match(title);
  if (m.hasMatch()) return {m.captured(1), m.captured(2)};
  return {title, QString()};
}

/// A value in the UI language: five significant digits, whole numbers from 100 000 on (no exponent
/// for a long log's minutes); a date-time axis in its own format.
QString valueText(const QAbstractAxis* axis, double value) {
  if (const auto* time = qobject_cast<const QDateTimeAxis*>(axis))
    return QLocale().toString(QDateTime::fromMSecsSinceEpoch(static_cast<qint64>(value)), time->format());
  if (std::abs(value) >= 1e5 && std::abs(value) < 1e15) return QLocale().toString(value, 'f', 0);
  return QLocale().toString(value, 'g', 5);
}

/// "x-name: value unit" for one coordinate of a point.
QString coordinateText(const QAbstractAxis* axis, double value, const QString& fallbackName) {
  const auto [name, unit] = splitAxisTitle(axis ? axis->titleText() : QString());
  QString text = (name.isEmpty() ? fallbackName : name) + QStringLiteral(": ") + valueText(axis, value);
  if (!unit.isEmpty()) text += QLatin1Char(' ') + unit;
  return text;
}

struct PointHit {
  QXYSeries* series = nullptr;
  QPointF value;     ///< in the series' units
  QPointF position;  ///< in the chart's coordinates
};

bool hasLogAxis(QXYSeries* series) {
  for (const QAbstractAxis* a : series->attachedAxes())
    if (qobject_cast<const QLogValueAxis*>(a) != nullptr) return true;
  return false;
}

/// The visible data point nearest to `at` (chart coordinates) within `reachPx`. Linear axes map a
/// value to a pixel with two reference points per series (mapToPosition per point is too slow for a
/// long log on every mouse move); a logarithmic axis maps every point.
std::optional<PointHit> nearestPoint(QChart* chart, const QPointF& at, double reachPx) {
  const QRectF plot = chart->plotArea();
  if (!plot.adjusted(-2, -2, 2, 2).contains(at)) return std::nullopt;
  double best = reachPx;
  std::optional<PointHit> hit;
  for (QAbstractSeries* s : chart->series()) {
    auto* xy = qobject_cast<QXYSeries*>(s);
    if (xy == nullptr || !xy->isVisible() || xy->count() == 0 || xy->attachedAxes().isEmpty()) continue;
    const bool log = hasLogAxis(xy);
    const QPointF v0 = chart->mapToValue(plot.topLeft(), xy);
    const QPointF v1 = chart->mapToValue(plot.bottomRight(), xy);
    if (!log && (v1.x() == v0.x() || v1.y() == v0.y())) continue;
    const QList<QPointF> points = xy->points();
    for (const QPointF& p : points) {
      const QPointF pos = log ? chart->mapToPosition(p, xy)
                              : QPointF(plot.left() + (p.x() - v0.x()) / (v1.x() - v0.x()) * plot.width(),
                                        plot.top() + (p.y() - v0.y()) / (v1.y() - v0.y()) * plot.height());
      if (!plot.adjusted(-1, -1, 1, 1).contains(pos)) continue;  // zoomed out of sight
      const double dist = std::hypot(pos.x() - at.x(), pos.y() - at.y());
      if (dist < best) {
        best = dist;
        hit = PointHit{xy, p, pos};
      }
    }
  }
  return hit;
}

QString pointText(const PointHit& hit) {
  const QAbstractAxis* xAxis = nullptr;
  const QAbstractAxis* yAxis = nullptr;
  for (const QAbstractAxis* a : hit.series->attachedAxes())
    (a->orientation() == Qt::Horizontal ? xAxis : yAxis) = a;
  QStringList lines;
  if (!hit.series->name().isEmpty()) lines << hit.series->name();
  lines << coordinateText(xAxis, hit.value.x(), QStringLiteral("x"))
        << coordinateText(yAxis, hit.value.y(), QStringLiteral("y"));
  return lines.join(QLatin1Char('\n'));
}

/// Holds what enableChartNavigation() attached to a view; a child QObject, so it dies with it.
class ChartNavigator : public QObject {
 public:
  explicit ChartNavigator(QChartView* view)
      : QObject(view),
        view_(view),
        label_(makeCursorLabel(view->viewport(), QStringLiteral("chartCursorLabel"))),
        band_(new QRubberBand(QRubberBand::Rectangle, view->viewport())) {
    setObjectName(QString::fromLatin1(kNavigatorName));
    band_->hide();
    view->viewport()->setMouseTracking(true);
    view->viewport()->installEventFilter(this);
    view->installEventFilter(this);

    auto* resetAction = new QAction(ChartNavigationText::tr("&Reset zoom (double click, Home)"), this);
    resetAction->setObjectName(QStringLiteral("chartResetZoom"));
    resetAction->setToolTip(ChartNavigationText::tr("Show the whole chart again"));
    connect(resetAction, &QAction::triggered, this, [this] { reset(); });
    // The entry joins the menu the view shows: its own actions, or those of the widget around it
    // that holds the chart's export entries (enableChartExport on a wrapper).
    QWidget* menu = view;
    for (QWidget* w = view; w != nullptr && !w->isWindow(); w = w->parentWidget()) {
      if (w->contextMenuPolicy() == Qt::ActionsContextMenu) {
        menu = w;
        break;
      }
    }
    auto* separator = new QAction(menu);
    separator->setSeparator(true);
    menu->addAction(separator);
    menu->addAction(resetAction);
    menu->setContextMenuPolicy(Qt::ActionsContextMenu);
  }

  bool zoomed() const { return !home_.empty() && homeChart_ == view_->chart(); }
  QString cursorText() const { return label_->isVisible() ? label_->text() : QString(); }

  bool reset() {
    if (!zoomed()) {
      dropHome();
      return false;
    }
    applying_ = true;
    for (const AxisRange& r : home_)
      if (r.axis) r.axis->setRange(r.min, r.max);
    applying_ = false;
    dropHome();
    return true;
  }

  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched == view_) {
      if (event->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(event)->key() == Qt::Key_Home &&
          static_cast<QKeyEvent*>(event)->modifiers() == Qt::NoModifier) {
        reset();
        return true;
      }
      return false;
    }
    if (watched != view_->viewport() || view_->chart() == nullptr) return false;
    switch (event->type()) {
      case QEvent::Wheel:
        return wheel(static_cast<QWheelEvent*>(event));
      case QEvent::MouseButtonPress:
        return press(static_cast<QMouseEvent*>(event));
      case QEvent::MouseMove:
        return move(static_cast<QMouseEvent*>(event));
      case QEvent::MouseButtonRelease:
        return release(static_cast<QMouseEvent*>(event));
      case QEvent::MouseButtonDblClick:
        if (static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton) return false;
        reset();
        updateCursor(static_cast<QMouseEvent*>(event)->position().toPoint());
        return true;
      case QEvent::Leave:
        hideCursor();
        return false;
      case QEvent::ToolTip:
        return label_->isVisible();  // the label already shows the point
      default:
        return false;
    }
  }

 private:
  struct AxisRange {
    QPointer<QAbstractAxis> axis;
    QVariant min;
    QVariant max;
  };

  QChart* chart() const { return view_->chart(); }
  QPointF toChart(const QPointF& viewportPos) const {
    return chart()->mapFromScene(view_->mapToScene(viewportPos.toPoint()));
  }

  /// A page that scrolls takes the plain wheel; the chart zooms on Ctrl + wheel there.
  bool inScrollingPage() const {
    for (QWidget* w = view_->parentWidget(); w != nullptr; w = w->parentWidget())
      if (auto* area = qobject_cast<QAbstractScrollArea*>(w))
        if (area->verticalScrollBar()->isVisible() || area->horizontalScrollBar()->isVisible()) return true;
    return false;
  }

  /// Remembers the axis ranges before the first zoom or pan of the chart shown now.
  void keepHome() {
    if (zoomed()) return;
    dropHome();
    homeChart_ = chart();
    for (QAbstractAxis* axis : chart()->axes()) {
      const QVariant min = axis->property("min");
      const QVariant max = axis->property("max");
      if (!min.isValid() || !max.isValid()) continue;
      home_.push_back({axis, min, max});
      // A range set by the program (new data) is the new whole chart: forget the old one.
      const auto changed = [this] {
        if (!applying_) dropHome();
      };
      if (auto* v = qobject_cast<QValueAxis*>(axis))
        watches_ << connect(v, &QValueAxis::rangeChanged, this, changed);
      else if (auto* l = qobject_cast<QLogValueAxis*>(axis))
        watches_ << connect(l, &QLogValueAxis::rangeChanged, this, changed);
      else if (auto* t = qobject_cast<QDateTimeAxis*>(axis))
        watches_ << connect(t, &QDateTimeAxis::rangeChanged, this, changed);
    }
  }

  void dropHome() {
    for (const QMetaObject::Connection& c : std::as_const(watches_)) disconnect(c);
    watches_.clear();
    home_.clear();
    homeChart_ = nullptr;
  }

  template <typename F>
  void navigate(F&& change) {
    keepHome();
    applying_ = true;
    change();
    applying_ = false;
  }

  bool wheel(QWheelEvent* e) {
    const bool ctrl = e->modifiers().testFlag(Qt::ControlModifier);
    if (inScrollingPage() && !ctrl) return false;
    const QPointF at = toChart(e->position());
    const QRectF plot = chart()->plotArea();
    if (!plot.contains(at)) return false;
    const QPoint delta = e->angleDelta();
    const double notches = (delta.y() != 0 ? delta.y() : delta.x()) / 120.0;
    if (notches == 0.0) return true;
    const double factor = std::pow(kWheelStepFactor, notches);  // > 1 zooms in
    const bool xOnly = e->modifiers().testFlag(Qt::ShiftModifier);
    QRectF rect = plot;
    rect.setLeft(at.x() - (at.x() - plot.left()) / factor);
    rect.setWidth(plot.width() / factor);
    if (!xOnly) {
      rect.setTop(at.y() - (at.y() - plot.top()) / factor);
      rect.setHeight(plot.height() / factor);
    }
    navigate([&] { chart()->zoomIn(rect); });
    updateCursor(e->position().toPoint());
    return true;
  }

  bool press(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton || !chart()->plotArea().contains(toChart(e->position()))) return false;
    last_ = e->position().toPoint();
    origin_ = last_;
    if (e->modifiers().testFlag(Qt::ShiftModifier)) {
      drag_ = Drag::Band;
      band_->setGeometry(QRect(origin_, QSize()));
      band_->show();
      return true;
    }
    drag_ = Drag::Pan;
    view_->viewport()->setCursor(Qt::ClosedHandCursor);
    return false;  // the view still sees the press (legend markers, focus)
  }

  bool move(QMouseEvent* e) {
    const QPoint pos = e->position().toPoint();
    if (drag_ == Drag::Pan && e->buttons().testFlag(Qt::LeftButton)) {
      const QPoint d = pos - last_;
      last_ = pos;
      if (!d.isNull()) navigate([&] { chart()->scroll(-d.x(), d.y()); });
      updateCursor(pos);
      return true;
    }
    if (drag_ == Drag::Band && e->buttons().testFlag(Qt::LeftButton)) {
      band_->setGeometry(QRect(origin_, pos).normalized());
      return true;
    }
    updateCursor(pos);
    return false;
  }

  bool release(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton || drag_ == Drag::None) return false;
    const Drag drag = std::exchange(drag_, Drag::None);
    view_->viewport()->unsetCursor();
    if (drag == Drag::Band) {
      band_->hide();
      const QRect band = QRect(origin_, e->position().toPoint()).normalized();
      if (band.width() >= kMinBandPx && band.height() >= kMinBandPx) {
        const QRectF rect = QRectF(toChart(band.topLeft()), toChart(band.bottomRight()))
                                .normalized()
                                .intersected(chart()->plotArea());
        if (rect.isValid()) navigate([&] { chart()->zoomIn(rect); });
      }
      updateCursor(e->position().toPoint());
      return true;
    }
    return false;
  }

  void updateCursor(const QPoint& pos) {
    const std::optional<PointHit> hit =
        nearestPoint(chart(), toChart(pos), std::numeric_limits<double>::infinity());
    if (!hit) {
      hideCursor();
      return;
    }
    label_->setText(pointText(*hit));
    label_->adjustSize();
    const QRect area = view_->viewport()->rect();
    QPoint place = pos + QPoint(kLabelOffsetPx, kLabelOffsetPx);
    if (place.x() + label_->width() > area.right()) place.setX(pos.x() - kLabelOffsetPx - label_->width());
    if (place.y() + label_->height() > area.bottom()) place.setY(pos.y() - kLabelOffsetPx - label_->height());
    label_->move(std::max(area.left(), place.x()), std::max(area.top(), place.y()));
    label_->show();
    label_->raise();
    if (marker_ == nullptr || marker_->scene() != view_->scene()) {
      marker_ = new QGraphicsEllipseItem(-kMarkerRadiusPx, -kMarkerRadiusPx, 2 * kMarkerRadiusPx,
                                         2 * kMarkerRadiusPx);
      marker_->setPen(QPen(view_->palette().color(QPalette::Text), 1.5));
      marker_->setBrush(Qt::NoBrush);
      marker_->setZValue(1e6);
      view_->scene()->addItem(marker_);  // the scene owns it
    }
    marker_->setPos(chart()->mapToScene(hit->position));
    marker_->show();
  }

  void hideCursor() {
    label_->hide();
    if (marker_ != nullptr && marker_->scene() == view_->scene()) marker_->hide();
  }

  enum class Drag { None, Pan, Band };

  QChartView* view_;
  QLabel* label_;
  QRubberBand* band_;
  QGraphicsEllipseItem* marker_ = nullptr;
  Drag drag_ = Drag::None;
  QPoint last_;
  QPoint origin_;
  std::vector<AxisRange> home_;
  QPointer<QChart> homeChart_;
  QList<QMetaObject::Connection> watches_;
  bool applying_ = false;
};

ChartNavigator* navigatorOf(const QWidget* view) {
  return view ? dynamic_cast<ChartNavigator*>(view->findChild<QObject*>(QString::fromLatin1(kNavigatorName),
                                                                        Qt::FindDirectChildrenOnly))
              : nullptr;
}

}  // namespace

void enableChartNavigation(QWidget* chartView) {
  auto* view = qobject_cast<QChartView*>(chartView);
  if (view == nullptr || navigatorOf(view) != nullptr) return;
  new ChartNavigator(view);
}

bool hasChartNavigation(const QWidget* chartView) {
  return navigatorOf(chartView) != nullptr;
}

bool resetChartZoom(QWidget* chartView) {
  ChartNavigator* navigator = navigatorOf(chartView);
  return navigator != nullptr && navigator->reset();
}

bool isChartZoomed(const QWidget* chartView) {
  const ChartNavigator* navigator = navigatorOf(chartView);
  return navigator != nullptr && navigator->zoomed();
}

QString chartCursorText(const QWidget* chartView) {
  const ChartNavigator* navigator = navigatorOf(chartView);
  return navigator != nullptr ? navigator->cursorText() : QString();
}

QString chartNearestPointText(QWidget* chartView, const QPoint& pos, double reachPx) {
  auto* view = qobject_cast<QChartView*>(chartView);
  if (view == nullptr || view->chart() == nullptr) return {};
  QChart* chart = view->chart();
  const std::optional<PointHit> hit =
      nearestPoint(chart, chart->mapFromScene(view->mapToScene(pos)), reachPx);
  return hit ? pointText(*hit) : QString();
}

}  // namespace metrofit
