#include "app/gui/filechangedbar.h"

#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace metrofit {

FileChangedBar::FileChangedBar(QWidget* parent) : QFrame(parent), label_(new QLabel(this)) {
  setObjectName(QStringLiteral("fileChangedBar"));
  setFrameShape(QFrame::StyledPanel);
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, QColor(255, 243, 205));
  p.setColor(QPalette::WindowText, QColor(102, 77, 3));
  setPalette(p);
  label_->setWordWrap(true);
  auto* reload = new QPushButton(tr("&Reload"), this);
  auto* ignore = new QPushButton(tr("&Ignore"), this);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(8, 4, 8, 4);
  layout->addWidget(label_, 1);
  layout->addWidget(reload);
  layout->addWidget(ignore);
  connect(reload, &QPushButton::clicked, this, [this] {
    hide();
    emit reloadRequested();
  });
  connect(ignore, &QPushButton::clicked, this, &QWidget::hide);
  hide();
}

void FileChangedBar::showFor(const QString& fileName, bool modified) {
  QString text =
      QFileInfo::exists(fileName)
          ? tr("The project file %1 was changed by another program.").arg(QDir::toNativeSeparators(fileName))
          : tr("The project file %1 was removed or renamed by another program.")
                .arg(QDir::toNativeSeparators(fileName));
  if (modified) text += QLatin1Char(' ') + tr("Reloading discards your unsaved changes.");
  label_->setText(text);
  show();
}

QString FileChangedBar::message() const {
  return label_->text();
}

}  // namespace metrofit
