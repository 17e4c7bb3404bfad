#include "widgets/setup/reportmodeldialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>
#include <exception>

namespace metrofit {

namespace {
enum Column { ColFeature, ColCharacteristic, ColNominal, ColLower, ColUpper, ColState, ColumnCount };

QString number(const std::optional<double>& v) {
  return v ? QLocale().toString(*v, 'f', 4) : QStringLiteral("—");
}
}  // namespace

ReportModelDialog::ReportModelDialog(const ReportFeatures& report, const QString& reportId,
                                     const setup::Model* existing, QWidget* parent)
    : QDialog(parent),
      report_(report),
      base_(existing ? *existing : setup::Model{}),
      creates_(existing == nullptr),
      table_(new QTableWidget(this)),
      connect_(new QComboBox(this)),
      tolerance_(new QDoubleSpinBox(this)),
      summary_(new QLabel(this)) {
  setObjectName(QStringLiteral("reportModelDialog"));
  setWindowTitle(creates_ ? tr("Create setup model from report %1").arg(reportId)
                          : tr("Add report features to setup model"));
  auto* intro = new QLabel(
      creates_
          ? tr("The %1 “%2” measures these characteristics. The checked ones become the dimensions of a "
               "new setup model, each under a feature node; draw the real relation graph in the Graph "
               "tab afterwards.")
                .arg(QString::fromStdString(report.format), reportId)
          : tr("The %1 “%2” measures these characteristics. The checked ones are added to the setup model "
               "“%3” as dimensions; those it reads already are marked.")
                .arg(QString::fromStdString(report.format), reportId, QString::fromStdString(base_.name)),
      this);
  intro->setWordWrap(true);

  table_->setObjectName(QStringLiteral("reportCharacteristics"));
  table_->setColumnCount(ColumnCount);
  table_->setHorizontalHeaderLabels(
      {tr("Feature"), tr("Characteristic"), tr("Nominal"), tr("Lower tol."), tr("Upper tol."), tr("State")});
  table_->verticalHeader()->hide();
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setAlternatingRowColors(true);
  table_->setRowCount(static_cast<int>(report.characteristics.size()));
  for (std::size_t k = 0; k < report.characteristics.size(); ++k) {
    const ReportCharacteristic& c = report.characteristics[k];
    const int row = static_cast<int>(k);
    auto* feature = new QTableWidgetItem(QString::fromStdString(c.feature));
    const bool inModel = !creates_ && modelDimensionFor(base_, report_, c) >= 0;
    const bool checkable = c.usable && !inModel;
    feature->setFlags(checkable ? (Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable)
                                : Qt::ItemFlags(Qt::ItemIsSelectable));
    feature->setCheckState(inModel ? Qt::Checked : Qt::Unchecked);
    feature->setToolTip(c.label.empty() ? QString::fromStdString(c.feature)
                                        : QString::fromStdString(c.label));
    table_->setItem(row, ColFeature, feature);
    table_->setItem(row, ColCharacteristic, new QTableWidgetItem(QString::fromStdString(c.characteristic)));
    const QString unit = c.unit == "deg" ? QStringLiteral(" °") : QString();
    for (const auto& [col, value] :
         {std::pair{ColNominal, c.nominal}, std::pair{ColLower, c.lower}, std::pair{ColUpper, c.upper}}) {
      auto* item = new QTableWidgetItem(number(value) + (value ? unit : QString()));
      item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(row, col, item);
    }
    QString state;
    if (inModel) {
      state = tr("in the model (%1)")
                  .arg(QString::fromStdString(
                      base_.dimensions[static_cast<std::size_t>(modelDimensionFor(base_, report_, c))].id));
    } else if (!c.usable) {
      // core/project/report_model.cpp's two reasons, in the UI language.
      QString why = QString::fromStdString(c.why);
      if (c.why == "the report prints no nominal for it")
        why = tr("the report prints no nominal for it");
      else if (c.why == "an angle (deg), not a length a setup correction moves")
        why = tr("an angle (deg), not a length a setup correction moves");
      state = tr("cannot be used: %1").arg(why);
    } else if (!c.lower) {
      state = tr("no tolerance printed: takes ± the value below");
    }
    table_->setItem(row, ColState, new QTableWidgetItem(state));
  }
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  connect(table_, &QTableWidget::itemChanged, this, [this] { updateSummary(); });

  auto* all = new QPushButton(tr("Check &all"), this);
  auto* none = new QPushButton(tr("Check &none"), this);
  connect(all, &QPushButton::clicked, this, [this] { checkAll(true); });
  connect(none, &QPushButton::clicked, this, [this] { checkAll(false); });

  auto* form = new QFormLayout;
  if (creates_) {
    name_ = new QLineEdit(QFileInfo(QString::fromStdString(report.source)).completeBaseName(), this);
    axis_ = new QComboBox(this);
    axis_->addItems({QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")});
    axis_->setCurrentText(QStringLiteral("Z"));
    axis_->setToolTip(tr("The machine axis the corrections act along"));
    form->addRow(tr("Model &name:"), name_);
    form->addRow(tr("A&xis:"), axis_);
    connect_->addItem(QStringLiteral("W1"), QStringLiteral("W1"));
  } else {
    for (const auto& s : base_.setup)
      connect_->addItem(QString::fromStdString(s.id), QString::fromStdString(s.id));
  }
  // A new model must be valid to be written (every dimension reached from a setup datum); an existing
  // one may be left unconnected while it is edited.
  if (!creates_) connect_->addItem(tr("(none: draw the arcs yourself)"), QString());
  connect_->setToolTip(
      tr("Each new feature gets an arc (+1) from this setup datum, so the model can run at "
         "once; change the arcs in the Graph tab"));
  form->addRow(tr("&Connect new features to:"), connect_);
  tolerance_->setRange(0.0, 10.0);
  tolerance_->setDecimals(3);
  tolerance_->setSingleStep(0.01);
  tolerance_->setValue(0.0);
  tolerance_->setSuffix(tr(" mm"));
  tolerance_->setToolTip(
      tr("± limits for values the report prints no tolerance for (0: such values cannot be added)"));
  form->addRow(tr("&Tolerance where the report gives none: ±"), tolerance_);

  connect(tolerance_, &QDoubleSpinBox::valueChanged, this, [this] { updateSummary(); });
  connect(connect_, &QComboBox::currentIndexChanged, this, [this] { updateSummary(); });
  summary_->setObjectName(QStringLiteral("reportModelSummary"));
  summary_->setWordWrap(true);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(creates_ ? tr("Create model") : tr("Add to model"));
  connect(buttons, &QDialogButtonBox::accepted, this, &ReportModelDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* checks = new QHBoxLayout;
  checks->addWidget(all);
  checks->addWidget(none);
  checks->addStretch(1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addWidget(table_, 1);
  layout->addLayout(checks);
  layout->addLayout(form);
  layout->addWidget(summary_);
  layout->addWidget(buttons);
  resize(960, 620);
  updateSummary();
}

bool ReportModelDialog::isChecked(int row) const {
  const QTableWidgetItem* item = table_->item(row, ColFeature);
  return item && (item->flags() & Qt::ItemIsUserCheckable) && item->checkState() == Qt::Checked;
}

bool ReportModelDialog::setChecked(int row, bool checked) {
  QTableWidgetItem* item = table_->item(row, ColFeature);
  if (!item || !(item->flags() & Qt::ItemIsUserCheckable)) return false;
  item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
  return true;
}

void ReportModelDialog::checkAll(bool checked) {
  const QSignalBlocker blocker(table_);
  for (int r = 0; r < table_->rowCount(); ++r) setChecked(r, checked);
  updateSummary();
}

std::vector<std::size_t> ReportModelDialog::checkedRows() const {
  std::vector<std::size_t> out;
  for (int r = 0; r < table_->rowCount(); ++r)
    if (isChecked(r)) out.push_back(static_cast<std::size_t>(r));
  return out;
}

void ReportModelDialog::setModelName(const QString& name) {
  if (name_) name_->setText(name);
}

void ReportModelDialog::setAxis(const QString& axis) {
  if (axis_) axis_->setCurrentText(axis);
}

void ReportModelDialog::setConnectTo(const QString& datum) {
  const int i = connect_->findData(datum);
  if (i >= 0) connect_->setCurrentIndex(i);
}

void ReportModelDialog::setDefaultTolerance(double mm) {
  tolerance_->setValue(mm);
  updateSummary();
}

std::optional<setup::Model> ReportModelDialog::resultModel(QString* error) const {
  const std::vector<std::size_t> chosen = checkedRows();
  if (chosen.empty()) {
    if (error) *error = tr("Check the characteristics to add.");
    return std::nullopt;
  }
  try {
    setup::Model model =
        creates_ ? newReportModel(name_->text().trimmed().toStdString(), axis_->currentText().toStdString())
                 : base_;
    ReportModelOptions options;
    options.connectTo = connect_->currentData().toString().toStdString();
    options.defaultToleranceMm = tolerance_->value();
    return addReportCharacteristics(std::move(model), report_, chosen, options);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromStdString(e.what());
    return std::nullopt;
  }
}

void ReportModelDialog::updateSummary() {
  QString error;
  const std::optional<setup::Model> model = resultModel(&error);
  if (!model) {
    summary_->setText(error);
    summary_->setStyleSheet(QStringLiteral("color: #b01818;"));
    return;
  }
  summary_->setStyleSheet(QString());
  summary_->setText(tr("%n dimension(s) to add; the model will have %1 features and %2 dimensions.", nullptr,
                       static_cast<int>(model->dimensions.size() - base_.dimensions.size()))
                        .arg(model->features.size())
                        .arg(model->dimensions.size()));
}

void ReportModelDialog::accept() {
  updateSummary();
  if (!resultModel()) return;  // the summary line says why
  QDialog::accept();
}

}  // namespace metrofit
