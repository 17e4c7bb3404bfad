#include "app/gui/studypage.h"

#include <QLabel>
#include <QVBoxLayout>

#include "app/gui/datasettable.h"
#include "app/gui/notesedit.h"
#include "widgets/document/projectdocument.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

StudyPage::StudyPage(ProjectDocument* document, const QString& study, QWidget* parent)
    : QWidget(parent),
      document_(document),
      study_(study),
      noData_(new QLabel(this)),
      datasets_(new DatasetTable(this)),
      filler_(new QWidget(this)) {
  auto* title = new QLabel(studyTitle(study), this);
  QFont titleFont = title->font();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
  titleFont.setBold(true);
  title->setFont(titleFont);

  auto* summary = new QLabel(studySummary(study), this);
  summary->setWordWrap(true);
  summary->setTextInteractionFlags(Qt::TextSelectableByMouse);

  auto* status = new QLabel(
      tr("The views of this study are not part of this version of the workbench yet. Nothing has been "
         "computed: the datasets it will work on are listed below."),
      this);
  status->setObjectName(QStringLiteral("studyStatus"));
  status->setWordWrap(true);
  status->setFrameShape(QFrame::StyledPanel);
  status->setMargin(8);

  auto sectionLabel = [this](const QString& text) {
    auto* label = new QLabel(text, this);
    QFont f = label->font();
    f.setBold(true);
    label->setFont(f);
    return label;
  };
  noData_->setWordWrap(true);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title);
  layout->addWidget(sectionLabel(tr("What this study does")));
  layout->addWidget(summary);
  layout->addSpacing(6);
  layout->addWidget(status);
  layout->addSpacing(6);
  layout->addWidget(sectionLabel(tr("Datasets")));
  layout->addWidget(noData_);
  layout->addWidget(datasets_, 1);
  // Takes the table's room when there is nothing to list, so the page keeps its shape.
  filler_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
  layout->addWidget(filler_, 1);
  layout->addWidget(sectionLabel(tr("Notes")));
  auto* notes = new NotesEdit(document_, study_, this);
  notes->setMaximumHeight(110);
  layout->addWidget(notes);

  connect(document_, &ProjectDocument::changed, this, &StudyPage::refresh);
  refresh();
}

std::vector<DatasetRef> StudyPage::studyDatasets() const {
  const QStringList kinds = studyDatasetKinds(study_);
  std::vector<DatasetRef> out;
  for (const DatasetRef& d : document_->project().datasets) {
    if (kinds.contains(QString::fromStdString(d.kind))) out.push_back(d);
  }
  return out;
}

void StudyPage::refresh() {
  std::vector<DatasetRef> datasets = studyDatasets();
  if (datasets == shown_ && !noData_->text().isEmpty()) return;
  shown_ = std::move(datasets);
  datasets_->setDatasets(*document_, shown_);
  QStringList kinds;
  for (const QString& kind : studyDatasetKinds(study_)) kinds << datasetKindTitle(kind);
  noData_->setText(shown_.empty() ? tr("This project has no datasets for this study yet (it uses: %1).")
                                        .arg(kinds.join(QStringLiteral(", ")))
                                  : tr("Data this study uses: %1.").arg(kinds.join(QStringLiteral(", "))));
  datasets_->setVisible(!shown_.empty());
  filler_->setVisible(shown_.empty());
}

}  // namespace metrofit
