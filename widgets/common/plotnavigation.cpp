#include "widgets/common/plotnavigation.h"

#include "widgets/common/cursorlabel.h"

#include <QAbstractScrollArea>
#include <QAction>
#include <QCoreApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>
#include <QWidget>
#include <algorithm>
#include <cmath>
#include <utility>

namespace metrofit {

namespace {

struct PlotNavigationText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::ChartNavigation)
};

const char* const kNavigatorName = "metrofitPlotNavigator";
constexpr double kWheelStepFactor = 1.25;
constexpr double kMaxScale = 50.0;
constexpr int kLabelOffsetPx = 14;

class PlotNavigator : public QObject {
 public:
  PlotNavigator(QWidget* plot, PlotReadout readout)
      : QObject(plot),
        plot_(plot),
        readout_(std::move(readout)),
        label_(makeCursorLabel(plot, QStringLiteral("plotCursorLabel"))) {
    setObjectName(QString::fromLatin1(kNavigatorName));
    plot->setMouseTracking(true);
    plot->installEventFilter(this);
    if (plot->focusPolicy() == Qt::NoFocus) plot->setFocusPolicy(Qt::ClickFocus);

    // The same menu entry as the Qt Charts views (chartnavigation.cpp), in the widget's own menu (the
    // export entries of chartexport.h are there).
    auto* reset = new QAction(PlotNavigationText::tr("&Reset zoom (double click, Home)"), this);
    reset->setObjectName(QStringLiteral("plotResetZoom"));
    reset->setToolTip(PlotNavigationText::tr("Show the whole chart again"));
    connect(reset, &QAction::triggered, this, [this] { this->reset(); });
    auto* separator = new QAction(plot);
    separator->setSeparator(true);
    plot->addAction(separator);
    plot->addAction(reset);
    plot->setContextMenuPolicy(Qt::ActionsContextMenu);
  }

  const QTransform& transform() const { return view_; }
  bool zoomed() const { return !view_.isIdentity(); }
  QString cursorText() const { return label_->isVisible() ? label_->text() : QString(); }

  bool reset() {
    if (!zoomed()) return false;
    view_.reset();
    plot_->update();
    return true;
  }

  void zoom(const QPointF& at, double factor) {
    const double scale = std::clamp(view_.m11() * factor, 1.0, kMaxScale);
    if (scale == view_.m11()) return;
    if (scale == 1.0) {
      reset();
      return;
    }
    // Keep the plot point under `at` where it is: at = T' * p with p = T^-1 * at.
    const QPointF p = view_.inverted().map(at);
    view_ = QTransform(scale, 0, 0, scale, at.x() - scale * p.x(), at.y() - scale * p.y());
    clampPan();
    plot_->update();
  }

  QString readoutAt(const QPointF& pos) const {
    if (!readout_) return {};
    return readout_(view_.inverted().map(pos), view_.m11());
  }

  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched != plot_) return false;
    switch (event->type()) {
      case QEvent::Wheel: {
        auto* w = static_cast<QWheelEvent*>(event);
        if (inScrollingPage() && !(w->modifiers() & Qt::ControlModifier)) return false;
        const double notches = w->angleDelta().y() / 120.0;
        if (notches == 0.0) return false;
        zoom(w->position(), std::pow(kWheelStepFactor, notches));
        updateCursor(w->position());
        return true;
      }
      case QEvent::MouseButtonPress: {
        auto* m = static_cast<QMouseEvent*>(event);
        if (m->button() != Qt::LeftButton || !zoomed()) return false;
        dragFrom_ = m->position();
        dragging_ = true;
        plot_->setCursor(Qt::ClosedHandCursor);
        return true;
      }
      case QEvent::MouseMove: {
        auto* m = static_cast<QMouseEvent*>(event);
        if (dragging_) {
          const QPointF d = m->position() - dragFrom_;
          dragFrom_ = m->position();
          view_ = QTransform(view_.m11(), 0, 0, view_.m22(), view_.dx() + d.x(), view_.dy() + d.y());
          clampPan();
          plot_->update();
        }
        updateCursor(m->position());
        return false;
      }
      case QEvent::MouseButtonRelease:
        if (!dragging_) return false;
        dragging_ = false;
        plot_->unsetCursor();
        return true;
      case QEvent::MouseButtonDblClick:
        if (static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton) return false;
        reset();
        return true;
      case QEvent::KeyPress:
        if (static_cast<QKeyEvent*>(event)->key() == Qt::Key_Home &&
            static_cast<QKeyEvent*>(event)->modifiers() == Qt::NoModifier) {
          reset();
          return true;
        }
        return false;
      case QEvent::Leave:
        label_->hide();
        return false;
      case QEvent::ToolTip:
        return label_->isVisible();  // the label already says what is there
      default:
        return false;
    }
  }

 private:
  /// A page that scrolls takes the plain wheel; the plot zooms on Ctrl + wheel there.
  bool inScrollingPage() const {
    for (QWidget* w = plot_->parentWidget(); w != nullptr; w = w->parentWidget())
      if (auto* area = qobject_cast<QAbstractScrollArea*>(w))
        if (area->verticalScrollBar()->isVisible() || area->horizontalScrollBar()->isVisible()) return true;
    return false;
  }

  /// The magnified plot always covers the widget (no pan beyond its edges).
  void clampPan() {
    const double s = view_.m11();
    const double w = plot_->width(), h = plot_->height();
    const double dx = std::clamp(view_.dx(), w - s * w, 0.0);
    const double dy = std::clamp(view_.dy(), h - s * h, 0.0);
    view_ = QTransform(s, 0, 0, s, dx, dy);
  }

  void updateCursor(const QPointF& pos) {
    const QString text = readoutAt(pos);
    if (text.isEmpty()) {
      label_->hide();
      return;
    }
    label_->setText(text);
    label_->adjustSize();
    // Beside the cursor, inside the widget (left of it near the right edge, above it near the bottom).
    QPoint at = pos.toPoint() + QPoint(kLabelOffsetPx, kLabelOffsetPx);
    if (at.x() + label_->width() > plot_->width())
      at.setX(pos.toPoint().x() - kLabelOffsetPx - label_->width());
    if (at.y() + label_->height() > plot_->height())
      at.setY(pos.toPoint().y() - kLabelOffsetPx - label_->height());
    label_->move(std::max(0, at.x()), std::max(0, at.y()));
    label_->show();
    label_->raise();
  }

  QWidget* plot_;
  PlotReadout readout_;
  QLabel* label_;
  QTransform view_;
  QPointF dragFrom_;
  bool dragging_ = false;
};

PlotNavigator* navigatorOf(const QWidget* plot) {
  return plot ? plot->findChild<PlotNavigator*>(QString::fromLatin1(kNavigatorName),
                                                Qt::FindDirectChildrenOnly)
              : nullptr;
}

}  // namespace

void enablePlotNavigation(QWidget* plot, PlotReadout readout) {
  if (!plot || navigatorOf(plot)) return;
  new PlotNavigator(plot, std::move(readout));
}

bool hasPlotNavigation(const QWidget* plot) {
  return navigatorOf(plot) != nullptr;
}

QTransform plotViewTransform(const QWidget* plot) {
  const PlotNavigator* n = navigatorOf(plot);
  return n ? n->transform() : QTransform();
}

bool resetPlotZoom(QWidget* plot) {
  PlotNavigator* n = navigatorOf(plot);
  return n && n->reset();
}

bool isPlotZoomed(const QWidget* plot) {
  const PlotNavigator* n = navigatorOf(plot);
  return n && n->zoomed();
}

void zoomPlot(QWidget* plot, const QPointF& at, double factor) {
  if (PlotNavigator* n = navigatorOf(plot)) n->zoom(at, factor);
}

QString plotCursorText(const QWidget* plot) {
  const PlotNavigator* n = navigatorOf(plot);
  return n ? n->cursorText() : QString();
}

QString plotReadoutAt(const QWidget* plot, const QPointF& pos) {
  const PlotNavigator* n = navigatorOf(plot);
  return n ? n->readoutAt(pos) : QString();
}

}  // namespace metrofit
