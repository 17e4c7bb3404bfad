#include "app/gui/overviewpage.h"

#include <QDir>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QVBoxLayout>

#include "app/gui/datasettable.h"
#include "widgets/document/projectdocument.h"

namespace metrofit {

OverviewPage::OverviewPage(ProjectDocument* document, QWidget* parent)
    : QWidget(parent),
      document_(document),
      name_(new QLineEdit(this)),
      description_(new QPlainTextEdit(this)),
      file_(new QLabel(this)),
      datasets_(new DatasetTable(this)) {
  auto* title = new QLabel(tr("Project overview"), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);

  name_->setObjectName(QStringLiteral("projectName"));
  name_->setPlaceholderText(tr("Project name"));
  description_->setObjectName(QStringLiteral("projectDescription"));
  description_->setPlaceholderText(tr("What is measured, on which machine, and why"));
  description_->setTabChangesFocus(true);
  description_->setMaximumHeight(140);
  description_->installEventFilter(this);
  file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  file_->setWordWrap(true);

  auto* form = new QFormLayout;
  form->addRow(tr("&Name:"), name_);
  form->addRow(tr("&Description:"), description_);
  form->addRow(tr("File:"), file_);

  auto* datasetsTitle = new QLabel(tr("Datasets"), this);
  QFont sectionFont = datasetsTitle->font();
  sectionFont.setBold(true);
  datasetsTitle->setFont(sectionFont);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title);
  layout->addLayout(form);
  layout->addSpacing(8);
  layout->addWidget(datasetsTitle);
  layout->addWidget(datasets_, 1);

  connect(name_, &QLineEdit::textEdited, this,
          [this](const QString& text) { document_->setValue(ProjectField::name(), text); });
  connect(name_, &QLineEdit::editingFinished, document_, &ProjectDocument::endEditSequence);
  connect(description_, &QPlainTextEdit::textChanged, this, [this] {
    if (!updating_) document_->setValue(ProjectField::description(), description_->toPlainText());
  });
  connect(document_, &ProjectDocument::changed, this, &OverviewPage::refresh);
  connect(document_, &ProjectDocument::fileNameChanged, this, &OverviewPage::refresh);
  refresh();
}

bool OverviewPage::eventFilter(QObject* watched, QEvent* event) {
  if (watched == description_ && event->type() == QEvent::FocusOut) document_->endEditSequence();
  return QWidget::eventFilter(watched, event);
}

void OverviewPage::refresh() {
  updating_ = true;
  const QString name = document_->value(ProjectField::name());
  if (name_->text() != name) name_->setText(name);
  const QString description = document_->value(ProjectField::description());
  if (description_->toPlainText() != description) description_->setPlainText(description);
  updating_ = false;
  const QString fileName = document_->fileName();
  file_->setText(fileName.isEmpty() ? tr("not saved yet") : QDir::toNativeSeparators(fileName));
  if (shownDatasets_ != document_->project().datasets || shownFile_ != fileName ||
      datasets_->rowCount() == 0) {
    shownDatasets_ = document_->project().datasets;
    shownFile_ = fileName;
    datasets_->setDatasets(*document_, shownDatasets_);
  }
}

}  // namespace metrofit
