#include "widgets/setup/setupgraphview.h"

#include <QFontMetricsF>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPathStroker>
#include <QRegularExpression>
#include <QSaveFile>
#include <QStyleOptionGraphicsItem>
#include <QSvgGenerator>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "widgets/setup/setupmodeleditor.h"

namespace metrofit {

namespace {

constexpr double kNodeHeight = 19.0;
constexpr double kPitch = 24.0;        ///< node spacing along a column
constexpr double kLevelGap = 150.0;    ///< free space between columns (room for the arcs)
constexpr double kRowGap = 120.0;      ///< distance between rows (Rows orientation)
constexpr double kHeaderSpace = 34.0;  ///< room for the level titles
constexpr int kNodeType = QGraphicsItem::UserType + 41;
constexpr int kArcType = QGraphicsItem::UserType + 42;
constexpr int kUnknownLevel = 5;  ///< the extra column of unknown arc end points

QColor fillColor(int level) {
  static const QColor colors[] = {QColor(0xe4, 0xdc, 0xf0), QColor(0xd6, 0xe4, 0xf5),
                                  QColor(0xfb, 0xe3, 0xc8), QColor(0xdc, 0xef, 0xd9),
                                  QColor(0xf3, 0xe9, 0xc6), QColor(Qt::white)};
  return colors[std::clamp(level, 0, 5)];
}

QColor borderColor(int level) {
  static const QColor colors[] = {QColor(0x5e, 0x4a, 0x86), QColor(0x2f, 0x5d, 0x8a),
                                  QColor(0xa0, 0x5a, 0x14), QColor(0x3c, 0x7a, 0x33),
                                  QColor(0x8a, 0x6d, 0x1c), QColor(0xd6, 0x27, 0x28)};
  return colors[std::clamp(level, 0, 5)];
}

const QColor kProblem(0xd6, 0x27, 0x28);
const QColor kPositive(0x44, 0x5a, 0x74);
const QColor kNegative(0xc0, 0x5a, 0x10);

class NodeItem : public QGraphicsItem {
 public:
  NodeItem(QString id, int level, double width) : id_(std::move(id)), level_(level), width_(width) {
    setFlag(ItemIsSelectable);
    setZValue(2.0);
  }
  int type() const override { return kNodeType; }
  QRectF boundingRect() const override {
    return QRectF(-width_ / 2 - 2, -kNodeHeight / 2 - 2, width_ + 4, kNodeHeight + 4);
  }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override {
    const QRectF r(-width_ / 2, -kNodeHeight / 2, width_, kNodeHeight);
    QPen pen(problem_ ? kProblem : borderColor(level_), problem_ ? 2.5 : 1.2);
    if (level_ == kUnknownLevel) pen.setStyle(Qt::DashLine);
    if (isSelected()) {
      painter->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 4.0));
      painter->setBrush(Qt::NoBrush);
      painter->drawRoundedRect(r.adjusted(-1.5, -1.5, 1.5, 1.5), 5, 5);
    }
    painter->setPen(pen);
    painter->setBrush(fillColor(level_));
    painter->drawRoundedRect(r, 4, 4);
    painter->setPen(level_ == kUnknownLevel ? kProblem : QColor(0x20, 0x20, 0x20));
    painter->setFont(font_);
    painter->drawText(r, Qt::AlignCenter, id_);
  }
  void setProblem(const QString& message) {
    problem_ = true;
    messages_ << message;
    setToolTip(messages_.join(QLatin1Char('\n')));
  }
  void setFont(const QFont& font) { font_ = font; }
  bool problem() const { return problem_; }
  const QString& id() const { return id_; }
  int level() const { return level_; }
  double width() const { return width_; }

 private:
  QString id_;
  int level_;
  double width_;
  QFont font_;
  bool problem_ = false;
  QStringList messages_;
};

class ArcItem : public QGraphicsPathItem {
 public:
  explicit ArcItem(int index) : index_(index) {
    setFlag(ItemIsSelectable);
    setZValue(1.0);
  }
  int type() const override { return kArcType; }
  int index() const { return index_; }
  QPainterPath shape() const override {
    QPainterPathStroker stroker;
    stroker.setWidth(7.0);
    return stroker.createStroke(path());
  }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override {
    if (isSelected()) {
      painter->setPen(QPen(QColor(0x1f, 0x77, 0xb4, 120), 5.0));
      painter->drawPath(path());
    }
    QStyleOptionGraphicsItem plain(*option);
    plain.state &= ~QStyle::State_Selected;  // no dotted selection box
    QGraphicsPathItem::paint(painter, &plain, widget);
    painter->setPen(Qt::NoPen);
    painter->setBrush(pen().color());
    painter->drawPolygon(head_);
    // The weight as text once it is legible (zoomed in, exports); the line style tells it always.
    if (!label.isEmpty() &&
        QStyleOptionGraphicsItem::levelOfDetailFromTransform(painter->worldTransform()) >= 0.95) {
      painter->setFont(labelFont);
      painter->setPen(pen().color());
      painter->drawText(labelRect, Qt::AlignCenter, label);
    }
  }
  QRectF boundingRect() const override {
    return QGraphicsPathItem::boundingRect().united(head_.boundingRect()).united(labelRect);
  }
  void setHead(const QPolygonF& head) {
    prepareGeometryChange();
    head_ = head;
  }
  void setProblem(const QString& message) {
    problem_ = true;
    messages_ << message;
    QPen p = pen();
    p.setColor(kProblem);
    p.setWidthF(2.5);
    setPen(p);
    setToolTip(messages_.join(QLatin1Char('\n')));
  }
  bool problem() const { return problem_; }
  QString label;
  QFont labelFont;
  QRectF labelRect;

 private:
  int index_;
  QPolygonF head_;
  bool problem_ = false;
  QStringList messages_;
};

int levelIndex(SetupLevel level) {
  return static_cast<int>(level);
}

}  // namespace

SetupGraphView::SetupGraphView(SetupModelEditor* editor, QWidget* parent)
    : QGraphicsView(parent), editor_(editor) {
  setObjectName(QStringLiteral("setupGraphView"));
  setScene(new QGraphicsScene(this));
  setRenderHint(QPainter::Antialiasing);
  setRenderHint(QPainter::TextAntialiasing);
  setDragMode(QGraphicsView::ScrollHandDrag);
  setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
  setResizeAnchor(QGraphicsView::AnchorViewCenter);
  setBackgroundBrush(Qt::white);
  setMinimumSize(320, 240);
  connect(editor_, &SetupModelEditor::modelChanged, this, &SetupGraphView::rebuild);
  connect(scene(), &QGraphicsScene::selectionChanged, this, &SetupGraphView::selectionChanged);
  rebuild();
}

SetupGraphView::~SetupGraphView() = default;

void SetupGraphView::setOrientation(Orientation orientation) {
  if (orientation_ == orientation) return;
  orientation_ = orientation;
  autoFit_ = true;
  rebuild();
}

void SetupGraphView::rebuild() {
  const QString keepNode = selectedNode();
  const int keepArc = selectedArc();
  QGraphicsScene* s = scene();
  s->clear();
  nodes_.clear();
  arcs_.clear();
  const setup::Model& m = editor_->model();

  // ---- nodes per level, with the unknown arc end points ----
  std::vector<std::vector<QString>> levels(6);
  QHash<QString, int> levelOf;
  auto addNode = [&](const std::string& sid, int level) {
    const QString id = QString::fromStdString(sid);
    if (levelOf.contains(id)) return;  // duplicates: drawn once (checkModel reports them)
    levelOf.insert(id, level);
    levels[static_cast<std::size_t>(level)].push_back(id);
  };
  for (const auto& d : m.setup) {
    const int level = d.kind == setup::DatumKind::Machine ? levelIndex(SetupLevel::Machine)
                      : d.kind == setup::DatumKind::Tool  ? levelIndex(SetupLevel::Tool)
                                                          : levelIndex(SetupLevel::Wks);
    addNode(d.id, level);
  }
  for (const auto& f : m.features) addNode(f.id, levelIndex(SetupLevel::Feature));
  for (const auto& d : m.dimensions) addNode(d.id, levelIndex(SetupLevel::Dimension));
  for (const auto& a : m.arcs) {
    for (const std::string* end : {&a.from, &a.to})
      if (!levelOf.contains(QString::fromStdString(*end))) addNode(*end, kUnknownLevel);
  }

  // ---- positions along the level axis: features evenly, the rest at their neighbours' barycentre ----
  QHash<QString, double> pos;  // in slots (multiples of the pitch)
  std::multimap<QString, QString> neighbours;
  for (const auto& a : m.arcs) {
    const QString from = QString::fromStdString(a.from), to = QString::fromStdString(a.to);
    neighbours.emplace(from, to);
    neighbours.emplace(to, from);
  }
  auto place = [&](std::vector<QString>& ids, bool evenly) {
    if (ids.empty()) return;
    std::vector<std::pair<double, QString>> keyed;
    int fallback = 0;
    for (const QString& id : ids) {
      double sum = 0.0;
      int n = 0;
      const auto [b, e] = neighbours.equal_range(id);
      for (auto it = b; it != e; ++it) {
        if (pos.contains(it->second)) {
          sum += pos.value(it->second);
          ++n;
        }
      }
      keyed.emplace_back(n > 0 ? sum / n : std::numeric_limits<double>::max() / 4 + fallback++, id);
    }
    if (!evenly)
      std::stable_sort(keyed.begin(), keyed.end(), [](auto& l, auto& r) { return l.first < r.first; });
    double next = 0.0;
    for (std::size_t i = 0; i < keyed.size(); ++i) {
      double p = evenly ? static_cast<double>(i) : keyed[i].first;
      if (p > 1e12) p = next;  // no placed neighbour: after the others
      p = std::max(p, next);
      pos.insert(keyed[i].second, p);
      next = p + 1.0;
      ids[i] = keyed[i].second;
    }
  };
  const int F = levelIndex(SetupLevel::Feature), D = levelIndex(SetupLevel::Dimension);
  place(levels[static_cast<std::size_t>(F)], true);
  if (levels[static_cast<std::size_t>(F)].empty()) place(levels[static_cast<std::size_t>(D)], true);
  place(levels[static_cast<std::size_t>(D)], false);
  place(levels[static_cast<std::size_t>(levelIndex(SetupLevel::Wks))], false);
  place(levels[static_cast<std::size_t>(levelIndex(SetupLevel::Tool))], false);
  place(levels[static_cast<std::size_t>(levelIndex(SetupLevel::Machine))], false);
  place(levels[kUnknownLevel], false);
  // Keep every level inside the span of the longest one: shift a level up when it runs over.
  double span = 0.0;
  for (const auto& ids : levels)
    for (const QString& id : ids) span = std::max(span, pos.value(id));
  for (auto& ids : levels) {
    if (ids.empty()) continue;
    const double over = pos.value(ids.back()) - span;
    if (over > 0.0)
      for (const QString& id : ids) pos[id] = std::max(0.0, pos.value(id) - over);
  }

  // ---- node items ----
  QFont font = this->font();
  font.setPointSizeF(8.0);
  const QFontMetricsF metrics(font);
  QFont headerFont = font;
  headerFont.setBold(true);
  headerFont.setPointSizeF(9.0);
  std::vector<double> widths(6, 40.0);
  for (std::size_t l = 0; l < levels.size(); ++l)
    for (const QString& id : levels[l]) widths[l] = std::max(widths[l], metrics.horizontalAdvance(id) + 14.0);
  const double slotWidth = *std::max_element(widths.begin(), widths.end()) + 8.0;
  // Level coordinate of each shown level (empty levels take no room).
  std::vector<double> levelCoord(6, 0.0);
  double cursor = 0.0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    if (levels[l].empty()) continue;
    if (orientation_ == Orientation::Columns) {
      levelCoord[l] = cursor + widths[l] / 2;
      cursor += widths[l] + kLevelGap;
    } else {
      levelCoord[l] = cursor;
      cursor += kRowGap;
    }
  }
  auto centreOf = [&](int level, double slot) {
    return orientation_ == Orientation::Columns
               ? QPointF(levelCoord[static_cast<std::size_t>(level)], kHeaderSpace + slot * kPitch)
               : QPointF(slotWidth / 2 + slot * slotWidth,
                         kHeaderSpace + levelCoord[static_cast<std::size_t>(level)]);
  };
  for (std::size_t l = 0; l < levels.size(); ++l) {
    if (levels[l].empty()) continue;
    const QString title = l == static_cast<std::size_t>(kUnknownLevel)
                              ? tr("Unknown nodes")
                              : setupLevelTitle(static_cast<SetupLevel>(l));
    auto* header = s->addSimpleText(title, headerFont);
    header->setBrush(borderColor(static_cast<int>(l)));
    const QRectF hb = header->boundingRect();
    if (orientation_ == Orientation::Columns) {
      header->setPos(levelCoord[l] - hb.width() / 2, 0.0);
    } else {
      header->setPos(-hb.width() - 12.0, kHeaderSpace + levelCoord[l] - hb.height() / 2);
    }
    const double w = orientation_ == Orientation::Columns ? widths[l] : slotWidth - 8.0;
    for (const QString& id : levels[l]) {
      auto* item = new NodeItem(id, static_cast<int>(l), w);
      item->setFont(font);
      item->setPos(centreOf(static_cast<int>(l), pos.value(id)));
      item->setData(0, id);
      if (l == static_cast<std::size_t>(kUnknownLevel)) {
        item->setProblem(tr("'%1' is not a node of the model (an arc names it)").arg(id));
      } else {
        item->setToolTip(setupLevelTitle(static_cast<SetupLevel>(l)) + QStringLiteral(": ") + id);
      }
      s->addItem(item);
      nodes_.insert(id, item);
    }
  }

  // ---- arcs ----
  QFont arcFont = font;
  arcFont.setPointSizeF(6.5);
  for (std::size_t a = 0; a < m.arcs.size(); ++a) {
    const setup::Arc& arc = m.arcs[a];
    auto* item = new ArcItem(static_cast<int>(a));
    const auto* from = static_cast<NodeItem*>(nodes_.value(QString::fromStdString(arc.from)));
    const auto* to = static_cast<NodeItem*>(nodes_.value(QString::fromStdString(arc.to)));
    const bool positive = arc.weight == 1.0;
    const bool negative = arc.weight == -1.0;
    item->label = positive   ? QStringLiteral("+1")
                  : negative ? QStringLiteral("−1")
                             : QString::number(arc.weight);
    QPen pen(negative ? kNegative : kPositive, 1.0);
    if (negative) pen.setStyle(Qt::DashLine);
    item->setPen(pen);
    item->setToolTip(tr("%1 → %2, weight %3")
                         .arg(QString::fromStdString(arc.from), QString::fromStdString(arc.to), item->label));
    if (from != nullptr && to != nullptr) {
      QPointF p0 = from->pos(), p3 = to->pos();
      QPointF c1, c2, dir;
      if (orientation_ == Orientation::Columns) {
        const bool forward = p3.x() >= p0.x();
        p0.rx() += (forward ? 1 : -1) * from->width() / 2;
        p3.rx() -= (forward ? 1 : -1) * to->width() / 2;
        const double dx = (p3.x() - p0.x()) * 0.5;
        c1 = p0 + QPointF(dx, 0);
        c2 = p3 - QPointF(dx, 0);
        dir = QPointF(forward ? 1 : -1, 0);
      } else {
        const bool forward = p3.y() >= p0.y();
        p0.ry() += (forward ? 1 : -1) * kNodeHeight / 2;
        p3.ry() -= (forward ? 1 : -1) * kNodeHeight / 2;
        const double dy = (p3.y() - p0.y()) * 0.5;
        c1 = p0 + QPointF(0, dy);
        c2 = p3 - QPointF(0, dy);
        dir = QPointF(0, forward ? 1 : -1);
      }
      QPainterPath path(p0);
      path.cubicTo(c1, c2, p3 - dir * 5.0);
      item->setPath(path);
      const QPointF normal(-dir.y(), dir.x());
      // The weight near the head, where few arcs overlap.
      const QPointF at = path.pointAtPercent(0.8);
      const QFontMetricsF fm(arcFont);
      const double w = fm.horizontalAdvance(item->label) + 2.0, h = fm.height();
      item->labelFont = arcFont;
      item->labelRect = QRectF(at.x() - w / 2, at.y() - h - 1.0, w, h);
      item->setHead(QPolygonF({p3, p3 - dir * 6.0 + normal * 3.0, p3 - dir * 6.0 - normal * 3.0}));
    }
    s->addItem(item);
    arcs_.append(item);
  }

  // ---- legend of the arc styles, under the graph ----
  {
    const QRectF bounds = s->itemsBoundingRect();
    const double y = bounds.bottom() + 14.0;
    double x = bounds.left();
    QFont legendFont = font;
    legendFont.setPointSizeF(7.5);
    for (const bool negative : {false, true}) {
      QPen pen(negative ? kNegative : kPositive, 1.2);
      if (negative) pen.setStyle(Qt::DashLine);
      s->addLine(x, y, x + 28.0, y, pen);
      auto* text = s->addSimpleText(negative ? tr("weight −1: the target moves against the source")
                                             : tr("weight +1: the target moves with the source"),
                                    legendFont);
      text->setBrush(QColor(0x40, 0x40, 0x40));
      text->setPos(x + 34.0, y - text->boundingRect().height() / 2);
      x += 34.0 + text->boundingRect().width() + 24.0;
    }
    if (!editor_->issues().empty()) {
      auto* text = s->addSimpleText(tr("red outline: a problem of the model (see its tooltip)"), legendFont);
      text->setBrush(kProblem);
      text->setPos(x, y - text->boundingRect().height() / 2);
    }
  }

  // ---- problems ----
  static const QRegularExpression arcField(QStringLiteral("^arcs\\[(\\d+)\\]"));
  for (const setup::ModelIssue& issue : editor_->issues()) {
    const QString message =
        QString::fromStdString(issue.field) + QStringLiteral(": ") + QString::fromStdString(issue.message);
    for (const std::string& node : issue.nodes) {
      if (auto* item = static_cast<NodeItem*>(nodes_.value(QString::fromStdString(node))))
        if (item->level() != kUnknownLevel) item->setProblem(message);
    }
    const auto match = arcField.match(QString::fromStdString(issue.field));
    if (match.hasMatch()) {
      const int index = match.captured(1).toInt();
      if (index >= 0 && index < arcs_.size()) static_cast<ArcItem*>(arcs_[index])->setProblem(message);
    }
  }

  s->setSceneRect(s->itemsBoundingRect().adjusted(-16, -10, 16, 16));
  if (!keepNode.isEmpty()) selectNode(keepNode);
  if (keepArc >= 0 && keepArc < arcs_.size()) selectArc(keepArc);
  if (autoFit_) fitInView(sceneRect(), Qt::KeepAspectRatio);
}

QPointF SetupGraphView::nodePosition(const QString& id) const {
  const QGraphicsItem* item = nodes_.value(id);
  if (item == nullptr) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  return item->pos();
}

bool SetupGraphView::isNodeHighlighted(const QString& id) const {
  const auto* item = static_cast<const NodeItem*>(nodes_.value(id));
  return item != nullptr && item->problem();
}

QString SetupGraphView::nodeToolTip(const QString& id) const {
  const QGraphicsItem* item = nodes_.value(id);
  return item != nullptr ? item->toolTip() : QString();
}

bool SetupGraphView::isUnknownNode(const QString& id) const {
  const auto* item = static_cast<const NodeItem*>(nodes_.value(id));
  return item != nullptr && item->level() == kUnknownLevel;
}

bool SetupGraphView::isArcHighlighted(int index) const {
  return index >= 0 && index < arcs_.size() && static_cast<const ArcItem*>(arcs_[index])->problem();
}

QString SetupGraphView::arcToolTip(int index) const {
  return index >= 0 && index < arcs_.size() ? arcs_[index]->toolTip() : QString();
}

QString SetupGraphView::arcLabel(int index) const {
  return index >= 0 && index < arcs_.size() ? static_cast<const ArcItem*>(arcs_[index])->label : QString();
}

QString SetupGraphView::selectedNode() const {
  for (QGraphicsItem* item : scene()->selectedItems())
    if (item->type() == kNodeType) return static_cast<NodeItem*>(item)->id();
  return {};
}

int SetupGraphView::selectedArc() const {
  for (QGraphicsItem* item : scene()->selectedItems())
    if (item->type() == kArcType) return static_cast<ArcItem*>(item)->index();
  return -1;
}

void SetupGraphView::selectNode(const QString& id) {
  scene()->clearSelection();
  if (QGraphicsItem* item = nodes_.value(id)) {
    item->setSelected(true);
    ensureVisible(item);
  }
}

void SetupGraphView::selectArc(int index) {
  scene()->clearSelection();
  if (index >= 0 && index < arcs_.size()) arcs_[index]->setSelected(true);
}

double SetupGraphView::zoomFactor() const {
  return transform().m11();
}

void SetupGraphView::scaleBy(double factor) {
  const double next = std::clamp(zoomFactor() * factor, 0.05, 20.0);
  autoFit_ = false;
  scale(next / zoomFactor(), next / zoomFactor());
}

void SetupGraphView::zoomIn() {
  scaleBy(1.25);
}

void SetupGraphView::zoomOut() {
  scaleBy(1.0 / 1.25);
}

void SetupGraphView::fitToView() {
  autoFit_ = true;
  fitInView(sceneRect(), Qt::KeepAspectRatio);
}

void SetupGraphView::wheelEvent(QWheelEvent* event) {
  if (event->modifiers() & Qt::ControlModifier) {
    scaleBy(std::pow(1.0015, event->angleDelta().y()));
    event->accept();
    return;
  }
  QGraphicsView::wheelEvent(event);
}

void SetupGraphView::mouseDoubleClickEvent(QMouseEvent* event) {
  for (QGraphicsItem* item : items(event->position().toPoint())) {
    if (item->type() == kNodeType) {
      emit nodeActivated(static_cast<NodeItem*>(item)->id());
      return;
    }
    if (item->type() == kArcType) {
      emit arcActivated(static_cast<ArcItem*>(item)->index());
      return;
    }
  }
  QGraphicsView::mouseDoubleClickEvent(event);
}

void SetupGraphView::resizeEvent(QResizeEvent* event) {
  QGraphicsView::resizeEvent(event);
  if (autoFit_) fitInView(sceneRect(), Qt::KeepAspectRatio);
}

bool SetupGraphView::exportSvg(const QString& path, QString* error) const {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  const QRectF source = scene()->sceneRect();
  {
    QSvgGenerator svg;
    svg.setOutputDevice(&file);
    svg.setSize(source.size().toSize());
    svg.setViewBox(QRectF(QPointF(0, 0), source.size()));
    svg.setTitle(tr("Relation graph of %1").arg(QString::fromStdString(editor_->model().name)));
    svg.setDescription(tr("Setup model: machine points, work offsets, tools, features, dimensions"));
    QPainter painter;
    if (!painter.begin(&svg)) {
      if (error) *error = tr("Cannot write %1: the SVG generator did not start").arg(path);
      file.cancelWriting();
      return false;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    scene()->render(&painter, QRectF(QPointF(0, 0), source.size()), source);
    painter.end();
  }
  if (!file.commit()) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

bool SetupGraphView::exportPng(const QString& path, QString* error, double scale) const {
  const QRectF source = scene()->sceneRect();
  QImage image((source.size() * scale).toSize(), QImage::Format_ARGB32);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    scene()->render(&painter, QRectF(QPointF(0, 0), image.size()), source);
  }
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit()) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace metrofit
