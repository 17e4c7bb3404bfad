#include "app/gui/overviewpage.h"

#include "core/study/study_check.h"

#include <QDir>
#include <QEvent>
#include <QFormLayout>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QToolButton>
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
      datasets_(new DatasetTable(this)),
      hint_(new QFrame(this)) {
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

  hint_->setObjectName(QStringLiteral("firstRunHint"));
  hint_->setFrameShape(QFrame::StyledPanel);
  hint_->setAutoFillBackground(true);
  QPalette hintPalette = hint_->palette();
  hintPalette.setColor(QPalette::Window, QColor(0xe8, 0xf1, 0xfb));
  hint_->setPalette(hintPalette);
  auto* hintText = new QLabel(
      tr("<b>New here?</b> Open the demo project: sample data for every study (setup correction, "
         "posture matching, kinematics &amp; SPC, thermal, diagnosis) to try each page. It is also in "
         "<i>Help › Open demo project</i>."),
      hint_);
  hintText->setWordWrap(true);
  auto* hintOpen = new QPushButton(tr("&Open the demo project"), hint_);
  hintOpen->setObjectName(QStringLiteral("firstRunOpenDemo"));
  hintOpen->setToolTip(tr("Copies the bundled demo project into a folder of your own and opens it"));
  auto* hintClose = new QToolButton(hint_);
  hintClose->setObjectName(QStringLiteral("firstRunDismiss"));
  hintClose->setText(QStringLiteral("✕"));
  hintClose->setAutoRaise(true);
  hintClose->setToolTip(tr("Hide this hint (it does not come back)"));
  auto* hintLayout = new QHBoxLayout(hint_);
  hintLayout->addWidget(hintText, 1);
  hintLayout->addWidget(hintOpen);
  hintLayout->addWidget(hintClose, 0, Qt::AlignTop);
  connect(hintOpen, &QPushButton::clicked, this, [this] {
    dismissHint();
    emit openDemoRequested();
  });
  connect(hintClose, &QToolButton::clicked, this, &OverviewPage::dismissHint);

  problems_ = new QLabel(this);
  problems_->setObjectName(QStringLiteral("studySettingProblems"));
  problems_->setWordWrap(true);
  problems_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  problems_->setFrameShape(QFrame::StyledPanel);
  problems_->setAutoFillBackground(true);
  QPalette problemPalette = problems_->palette();
  problemPalette.setColor(QPalette::Window, QColor(0xfd, 0xec, 0xea));
  problemPalette.setColor(QPalette::WindowText, QColor(0x8a, 0x1c, 0x1c));
  problems_->setPalette(problemPalette);
  problems_->hide();

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(problems_);
  layout->addWidget(hint_);
  layout->addWidget(title);
  layout->addLayout(form);
  layout->addSpacing(8);
  auto* importButton = new QPushButton(tr("&Import data…"), this);
  importButton->setObjectName(QStringLiteral("overviewImport"));
  importButton->setToolTip(
      tr("Adds a file to the project as a dataset (File › Import data…, Ctrl+I, or drop "
         "files on the window); right-click a dataset to rename, re-link or remove it"));
  connect(importButton, &QPushButton::clicked, this, &OverviewPage::importRequested);
  auto* datasetsRow = new QHBoxLayout;
  datasetsRow->addWidget(datasetsTitle);
  datasetsRow->addStretch(1);
  datasetsRow->addWidget(importButton);
  layout->addLayout(datasetsRow);
  layout->addWidget(datasets_, 1);
  datasets_->enableEditing(document_);

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

void OverviewPage::dismissHint() {
  QSettings().setValue(QString::fromLatin1(kFirstRunHintKey), true);
  hint_->hide();
}

bool OverviewPage::eventFilter(QObject* watched, QEvent* event) {
  if (watched == description_ && event->type() == QEvent::FocusOut) document_->endEditSequence();
  return QWidget::eventFilter(watched, event);
}

void OverviewPage::refresh() {
  updating_ = true;
  // A project nobody has named carries core's "Untitled": the field stays empty and shows the name in
  // the UI language ("Unbenannt") as its placeholder, so a German window never shows the English word.
  const QString stored = document_->value(ProjectField::name());
  const bool unnamed = stored.trimmed().isEmpty() || stored == QString::fromStdString(Project{}.name);
  const QString name = unnamed && !name_->hasFocus() ? QString() : stored;
  if (name_->text() != name) name_->setText(name);
  name_->setPlaceholderText(unnamed ? document_->displayName() : tr("Project name"));
  const QString description = document_->value(ProjectField::description());
  if (description_->toPlainText() != description) description_->setPlainText(description);
  updating_ = false;
  const QString fileName = document_->fileName();
  file_->setText(fileName.isEmpty() ? tr("not saved yet") : QDir::toNativeSeparators(fileName));
  hint_->setVisible(fileName.isEmpty() && !QSettings().value(QString::fromLatin1(kFirstRunHintKey)).toBool());
  // Study settings are checked when the project is opened and after every change: a bad one is a
  // marked message naming the study and the field, never a quiet default.
  const std::vector<StudyIssue> issues = checkStudies(document_->project());
  if (issues.empty()) {
    problems_->hide();
  } else {
    QStringList lines;
    for (const StudyIssue& i : issues)
      lines << QStringLiteral("⚠ <b>%1</b>: %2")
                   .arg(QString::fromStdString(i.field).toHtmlEscaped(),
                        QString::fromStdString(i.message).toHtmlEscaped());
    problems_->setText(tr("Study settings the methods cannot use; correct them in the project file:") +
                       QStringLiteral("<br>") + lines.join(QStringLiteral("<br>")));
    problems_->show();
  }
  if (shownDatasets_ != document_->project().datasets || shownFile_ != fileName ||
      datasets_->rowCount() == 0) {
    shownDatasets_ = document_->project().datasets;
    shownFile_ = fileName;
    datasets_->setDatasets(*document_, shownDatasets_);
  }
}

}  // namespace metrofit
