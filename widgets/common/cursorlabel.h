#pragma once
// The read-out label that follows the cursor over a chart (chartnavigation.cpp, the Qt Charts views)
// and a QPainter plot (plotnavigation.cpp): tooltip colours, a box, plain text, transparent for the
// mouse, hidden until there is something to show.
#include <QLabel>
#include <QString>

namespace metrofit {

inline QLabel* makeCursorLabel(QWidget* parent, const QString& objectName) {
  auto* label = new QLabel(parent);
  label->setObjectName(objectName);
  label->setTextFormat(Qt::PlainText);
  label->setAttribute(Qt::WA_TransparentForMouseEvents);
  label->setFrameShape(QFrame::Box);
  label->setMargin(3);
  label->setAutoFillBackground(true);
  label->setBackgroundRole(QPalette::ToolTipBase);
  label->setForegroundRole(QPalette::ToolTipText);
  label->hide();
  return label;
}

}  // namespace metrofit
