#include "widgets/importer/importdialog.h"

#include <QBrush>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <exception>
#include <string_view>
#include <utility>

#include "core/common/error.h"
#include "core/geometry/point_table.h"
#include "core/io/cmm_text_report.h"
#include "core/io/file_io.h"
#include "core/io/mtconnect.h"
#include "core/io/qif.h"
#include "core/matching/hole_table.h"
#include "core/project/dataset_content.h"
#include "core/project/datasets.h"
#include "core/project/import_guess.h"
#include "core/project/nominals.h"
#include "core/setup/model.h"
#include "core/setup/report.h"
#include "core/study/setup_study.h"
#include "core/thermal/thermal_log.h"
#include "widgets/data/datasettablemodel.h"
#include "widgets/document/studyinfo.h"

namespace metrofit {

namespace {

/// Files larger than this are not imported (the readers' limit, core/project/datasets.cpp).
constexpr qint64 kMaxFileBytes = qint64{256} << 20;
/// Lines shown for a file that is not read as CSV.
constexpr int kRawPreviewLines = 40;

enum MappingColumn { MapFileColumn, MapFirstValue, MapRole, MapColumnCount };

QString projectKind(const QString& cliKind) {
  QString k = cliKind;
  return k.replace(QLatin1Char('-'), QLatin1Char('_'));
}

QString delimiterText(char c) {
  switch (c) {
    case ',':
      return ImportDialog::tr("comma ( , )");
    case ';':
      return ImportDialog::tr("semicolon ( ; )");
    case '\t':
      return ImportDialog::tr("tab");
    default:
      return ImportDialog::tr("detect");
  }
}

QString decimalText(char c) {
  switch (c) {
    case '.':
      return ImportDialog::tr("point ( . )");
    case ',':
      return ImportDialog::tr("comma ( , )");
    default:
      return ImportDialog::tr("detect");
  }
}

/// What a role means to the readers (the combo box items' tooltips).
QString roleDescription(const QString& role) {
  static const QMap<QString, const char*> text{
      {QStringLiteral("time_s"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "time in s, strictly increasing")},
      {QStringLiteral("time_min"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "time in min")},
      {QStringLiteral("time_h"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "time in h")},
      {QStringLiteral("disp_x_um"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "displacement in X in µm (a target)")},
      {QStringLiteral("disp_y_um"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "displacement in Y in µm (a target)")},
      {QStringLiteral("disp_z_um"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "displacement in Z in µm (a target)")},
      {QStringLiteral("T_amb"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "ambient temperature in °C")},
      {QStringLiteral("spindle_rpm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "spindle speed in 1/min")},
      {QStringLiteral("id"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "point id")},
      {QStringLiteral("surface"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "surface name")},
      {QStringLiteral("qx"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal point in mm")},
      {QStringLiteral("qy"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal point in mm")},
      {QStringLiteral("qz"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal point in mm")},
      {QStringLiteral("nx"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal unit normal")},
      {QStringLiteral("ny"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal unit normal")},
      {QStringLiteral("nz"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal unit normal")},
      {QStringLiteral("px"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured point in mm")},
      {QStringLiteral("py"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured point in mm")},
      {QStringLiteral("pz"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured point in mm")},
      {QStringLiteral("x_cmd_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "commanded coordinate in mm")},
      {QStringLiteral("y_cmd_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "commanded coordinate in mm")},
      {QStringLiteral("x_meas_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured coordinate in mm")},
      {QStringLiteral("y_meas_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured coordinate in mm")},
      {QStringLiteral("angle_deg"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "angle of a radial-only circular test in deg")},
      {QStringLiteral("deviation_um"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "radial deviation in µm (radial-only circular test)")},
      {QStringLiteral("deviation_mm"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "radial deviation in mm (radial-only circular test)")},
      {QStringLiteral("direction"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "direction of travel: ccw or cw")},
      {QStringLiteral("run"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "run number")},
      {QStringLiteral("radius_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal radius in mm")},
      {QStringLiteral("part"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "part number")},
      {QStringLiteral("dimension"),
       QT_TRANSLATE_NOOP("metrofit::ImportDialog", "dimension id of the setup model")},
      {QStringLiteral("nominal_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "nominal value in mm")},
      {QStringLiteral("measured_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "measured value in mm")},
      {QStringLiteral("lower_tol_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "lower tolerance in mm")},
      {QStringLiteral("upper_tol_mm"), QT_TRANSLATE_NOOP("metrofit::ImportDialog", "upper tolerance in mm")},
  };
  if (role.size() == 2 && role.startsWith(QLatin1Char('T')) && role[1].isDigit())
    return ImportDialog::tr("temperature in °C (an input)");
  const auto it = text.find(role);
  return it == text.end() ? QString() : ImportDialog::tr(it.value());
}

QString elementTitle(const QString& element) {
  if (element == QLatin1String("plane")) return ImportDialog::tr("plane");
  if (element == QLatin1String("line")) return ImportDialog::tr("line");
  if (element == QLatin1String("circle")) return ImportDialog::tr("circle");
  if (element == QLatin1String("sphere")) return ImportDialog::tr("sphere");
  if (element == QLatin1String("cylinder")) return ImportDialog::tr("cylinder");
  if (element == QLatin1String("cone")) return ImportDialog::tr("cone");
  return element;
}

/// "sphere fitted to 18 points: radius 487.310 mm, form 0.0040 mm, rmse 0.0010 mm." (+ the condition
/// when the fit is not well conditioned), after the reference's name for a second measurement.
QString nominalsText(const NominalsOutcome& out, const NominalSource& n) {
  const QLocale l;
  QString text;
  if (n.from == "reference")
    text = ImportDialog::tr("Nominals: the %n point(s) of “%1”.", nullptr,
                            static_cast<int>(out.set.points.size()))
               .arg(QString::fromStdString(n.reference));
  if (out.fit) {
    const geometry::ElementFitResult& f = *out.fit;
    QString size;
    if (f.element.radiusMm > 0.0)
      size = ImportDialog::tr("radius %1 mm, ").arg(l.toString(f.element.radiusMm, 'f', 3));
    const int fitted = static_cast<int>(f.residualsMm.size() - f.excluded.size());
    text += (text.isEmpty() ? QString() : QStringLiteral(" ")) +
            ImportDialog::tr("%1 fitted to %n point(s): %2form %3 mm, rmse %4 mm.", nullptr, fitted)
                .arg(elementTitle(QString::fromStdString(n.element)), size, l.toString(f.formMm, 'f', 4),
                     l.toString(f.rmseMm, 'f', 4));
    if (!f.excluded.empty())
      text += QLatin1Char(' ') + ImportDialog::tr("%n stray point(s) left out of the fit.", nullptr,
                                                  static_cast<int>(f.excluded.size()));
    // The condition in the UI language (core's text, element_fit.h, is English): how much the point noise
    // is amplified in the element's parameters, and how much of the element the points cover.
    QString coverage;
    if (f.element.kind == geometry::ElementKind::Sphere)
      coverage = ImportDialog::tr(" The points cover a cap of half angle %1°.")
                     .arg(l.toString(f.coverageDeg, 'f', 1));
    else if (f.element.kind != geometry::ElementKind::Plane && f.element.kind != geometry::ElementKind::Line)
      coverage = ImportDialog::tr(" The points cover an arc of %1°.").arg(l.toString(f.coverageDeg, 'f', 1));
    if (f.noiseAmplification > geometry::kBadConditionAmplification)
      text +=
          QLatin1Char(' ') +
          ImportDialog::tr("Badly conditioned: the noise of the points is amplified %1 times in the element.")
              .arg(l.toString(f.noiseAmplification, 'f', 0)) +
          coverage;
    else if (!f.wellConditioned)
      text += QLatin1Char(' ') +
              ImportDialog::tr(
                  "Weakly conditioned: the noise of the points is amplified %1 times in the element.")
                  .arg(l.toString(f.noiseAmplification, 'f', 1)) +
              coverage;
  }
  return text;
}

}  // namespace

ImportDialog::ImportDialog(const Project& project, const QString& projectPath, QWidget* parent)
    : QDialog(parent),
      project_(project),
      projectPath_(projectPath),
      fileEdit_(new QLineEdit(this)),
      kind_(new QComboBox(this)),
      id_(new QLineEdit(this)),
      delimiter_(new QComboBox(this)),
      decimal_(new QComboBox(this)),
      headerLines_(new QSpinBox(this)),
      comment_(new QLineEdit(this)),
      skipBadRows_(new QCheckBox(tr("Skip &unreadable rows"), this)),
      dmisBox_(new QGroupBox(tr("DMIS tolerance actuals"), this)),
      taMeaning_(new QComboBox(this)),
      taSign_(new QComboBox(this)),
      embed_(new QCheckBox(tr("Cop&y the file into the project (data folder)"), this)),
      rowProblems_(new QListWidget(this)),
      detected_(new QLabel(this)),
      mapping_(new QTableWidget(this)),
      preview_(new QTableWidget(this)),
      problemLabel_(new QLabel(this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
  setObjectName(QStringLiteral("importDialog"));
  setWindowTitle(tr("Import data"));
  fileEdit_->setObjectName(QStringLiteral("importFile"));
  fileEdit_->setReadOnly(true);
  kind_->setObjectName(QStringLiteral("importKind"));
  id_->setObjectName(QStringLiteral("importId"));
  delimiter_->setObjectName(QStringLiteral("importDelimiter"));
  decimal_->setObjectName(QStringLiteral("importDecimal"));
  detected_->setObjectName(QStringLiteral("importDetected"));
  headerLines_->setObjectName(QStringLiteral("importHeaderLines"));
  headerLines_->setRange(-1, 10000);
  headerLines_->setValue(-1);
  headerLines_->setSpecialValueText(tr("detect"));
  headerLines_->setToolTip(
      tr("Lines before the column names, skipped whatever they hold (an instrument's preamble)"));
  comment_->setObjectName(QStringLiteral("importComment"));
  comment_->setPlaceholderText(QStringLiteral("#"));
  comment_->setMaxLength(16);
  comment_->setToolTip(tr("What starts a comment line before the column names"));
  skipBadRows_->setObjectName(QStringLiteral("importSkipBadRows"));
  skipBadRows_->setToolTip(
      tr("Leave out the rows listed under the preview; the project keeps this setting and the readers "
         "count the rows they leave out. Off: the first unreadable row is an error."));
  dmisBox_->setObjectName(QStringLiteral("importDmis"));
  taMeaning_->setObjectName(QStringLiteral("importTaMeaning"));
  taMeaning_->addItem(tr("auto (nearer the nominal: the actual value)"), QStringLiteral("auto"));
  taMeaning_->addItem(tr("deviation (actual − nominal)"), QStringLiteral("deviation"));
  taMeaning_->addItem(tr("actual value"), QStringLiteral("actual"));
  taSign_->setObjectName(QStringLiteral("importTaSign"));
  taSign_->addItem(tr("plain (actual − nominal)"), QStringLiteral("plain"));
  taSign_->addItem(tr("follows the nominal's sign"), QStringLiteral("nominal"));
  embed_->setObjectName(QStringLiteral("importEmbed"));
  rowProblems_->setObjectName(QStringLiteral("importRowProblems"));
  rowProblems_->setMaximumHeight(110);
  detected_->setWordWrap(true);
  detected_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  mapping_->setObjectName(QStringLiteral("importMapping"));
  preview_->setObjectName(QStringLiteral("importPreview"));
  problemLabel_->setObjectName(QStringLiteral("importProblem"));
  problemLabel_->setWordWrap(true);
  problemLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  problemLabel_->setStyleSheet(QStringLiteral("color: #b00020;"));
  buttons_->button(QDialogButtonBox::Ok)->setText(tr("&Import"));
  buttons_->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));

  for (const std::string& name : datasetKindNames()) {
    const QString cli = QString::fromStdString(name);
    kind_->addItem(datasetKindTitle(projectKind(cli)), cli);
  }
  for (char c : {char{0}, ',', ';', '\t'}) delimiter_->addItem(delimiterText(c), static_cast<int>(c));
  for (char c : {char{0}, '.', ','}) decimal_->addItem(decimalText(c), static_cast<int>(c));

  auto* browse = new QPushButton(tr("&Browse…"), this);
  auto* fileRow = new QHBoxLayout;
  fileRow->addWidget(fileEdit_, 1);
  fileRow->addWidget(browse);
  auto* form = new QFormLayout;
  form_ = form;
  auto* fileLabel = new QLabel(tr("&File:"), this);
  fileLabel->setBuddy(browse);
  form->addRow(fileLabel, fileRow);
  form->addRow(tr("&Kind:"), kind_);
  form->addRow(tr("&Id:"), id_);
  // A QIF file holds one or several measured parts; probe points are those of one part.
  qifPart_ = new QComboBox(this);
  qifPart_->setObjectName(QStringLiteral("importQifPart"));
  qifPart_->setToolTip(
      tr("The measured part (MeasurementResults) of the QIF file whose features become "
         "the probe points"));
  form->addRow(tr("Measured &part:"), qifPart_);
  form->setRowVisible(qifPart_, false);
  connect(qifPart_, &QComboBox::currentIndexChanged, this, [this] { revalidate(); });
  // An MTConnect log is resampled to a grid (zero-order hold); its step is the dataset's sample interval.
  sampleInterval_ = new QDoubleSpinBox(this);
  sampleInterval_->setObjectName(QStringLiteral("importSampleInterval"));
  sampleInterval_->setDecimals(3);
  sampleInterval_->setRange(0.001, 86400.0);
  sampleInterval_->setValue(kMtconnectDefaultIntervalS);
  sampleInterval_->setSuffix(QStringLiteral(" s"));
  sampleInterval_->setToolTip(
      tr("The MTConnect log is resampled every this many seconds: each cell holds the last value at or "
         "before its time (empty while UNAVAILABLE)"));
  form->addRow(tr("Sample &interval:"), sampleInterval_);
  form->setRowVisible(sampleInterval_, false);
  connect(sampleInterval_, &QDoubleSpinBox::valueChanged, this, [this] { revalidate(); });

  auto* dialect = new QGroupBox(tr("How the file is read"), this);
  auto* dialectForm = new QFormLayout(dialect);
  dialectForm->addRow(tr("&Delimiter:"), delimiter_);
  dialectForm->addRow(tr("Decimal &mark:"), decimal_);
  auto* headerRow = new QHBoxLayout;
  headerRow->addWidget(headerLines_);
  auto* commentLabel = new QLabel(tr("&Comment prefix:"), dialect);
  commentLabel->setBuddy(comment_);
  headerRow->addWidget(commentLabel);
  headerRow->addWidget(comment_);
  headerRow->addWidget(skipBadRows_);
  headerRow->addStretch(1);
  auto* headerLabel = new QLabel(tr("&Lines before the header:"), dialect);
  headerLabel->setBuddy(headerLines_);
  dialectForm->addRow(headerLabel, headerRow);
  dialectForm->addRow(tr("Found:"), detected_);
  auto* dmisForm = new QFormLayout(dmisBox_);
  dmisForm->addRow(tr("TA &value is:"), taMeaning_);
  dmisForm->addRow(tr("TA si&gn:"), taSign_);
  dmisBox_->setVisible(false);

  mapping_->setColumnCount(MapColumnCount);
  mapping_->setHorizontalHeaderLabels({tr("Column in the file"), tr("First value"), tr("Read as")});
  mapping_->verticalHeader()->hide();
  mapping_->setSelectionMode(QAbstractItemView::NoSelection);
  mapping_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  mapping_->horizontalHeader()->setSectionResizeMode(MapFileColumn, QHeaderView::ResizeToContents);
  mapping_->horizontalHeader()->setSectionResizeMode(MapFirstValue, QHeaderView::ResizeToContents);
  mapping_->horizontalHeader()->setSectionResizeMode(MapRole, QHeaderView::Stretch);
  preview_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  preview_->setAlternatingRowColors(true);
  preview_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

  auto* mappingBox = new QGroupBox(tr("Columns"), this);
  mappingBox->setObjectName(QStringLiteral("importMappingBox"));
  auto* mappingLayout = new QVBoxLayout(mappingBox);
  auto* mappingHint = new QLabel(
      tr("Give a column the name the readers look for (time_s, disp_z_um, qx, x_cmd_mm, …); empty: "
         "the name in the file. The project stores this mapping, not a converted copy."),
      mappingBox);
  mappingHint->setWordWrap(true);
  mappingLayout->addWidget(mappingHint);
  mappingLayout->addWidget(mapping_, 1);
  auto* previewBox = new QGroupBox(tr("Preview (first %1 rows)").arg(kPreviewRows), this);
  auto* previewLayout = new QVBoxLayout(previewBox);
  previewLayout->addWidget(preview_, 1);
  auto* problemsTitle = new QLabel(tr("Rows that cannot be read:"), previewBox);
  problemsTitle->setObjectName(QStringLiteral("importRowProblemsTitle"));
  problemsTitle->setWordWrap(true);  // its hint must not widen the preview at the mapping's cost
  previewLayout->addWidget(problemsTitle);
  previewLayout->addWidget(rowProblems_);
  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->addWidget(mappingBox);
  splitter->addWidget(previewBox);
  splitter->setStretchFactor(0, 2);
  splitter->setStretchFactor(1, 3);
  splitter->setChildrenCollapsible(false);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(dialect);
  layout->addWidget(dmisBox_);
  buildNominalsBox();
  layout->addWidget(nominalsBox_);
  layout->addWidget(splitter, 1);
  series_ = new QCheckBox(this);
  series_->setObjectName(QStringLiteral("importSeries"));
  series_->setChecked(true);
  series_->setVisible(false);
  layout->addWidget(series_);
  layout->addWidget(embed_);
  layout->addWidget(problemLabel_);
  layout->addWidget(buttons_);
  resize(1000, 680);

  connect(browse, &QPushButton::clicked, this, &ImportDialog::browse);
  connect(buttons_, &QDialogButtonBox::accepted, this, [this] { importNow(); });
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(kind_, &QComboBox::currentIndexChanged, this, [this] {
    if (updating_) return;
    kindChosen_ = true;       // the user's choice: no longer re-guessed when the dialect changes
    rebuildMapping(header_);  // the role suggestions are the kind's
    guessRoles();
    revalidate();
  });
  connect(delimiter_, &QComboBox::currentIndexChanged, this, [this] {
    if (!updating_) reguessKind();
  });
  connect(decimal_, &QComboBox::currentIndexChanged, this, [this] {
    if (!updating_) reguessKind();
  });
  connect(id_, &QLineEdit::textChanged, this, [this] {
    if (!updating_) revalidate();
  });
  connect(headerLines_, &QSpinBox::valueChanged, this, [this] {
    if (!updating_) reguessKind();
  });
  connect(comment_, &QLineEdit::textChanged, this, [this] {
    if (!updating_) reguessKind();
  });
  for (QCheckBox* box : {skipBadRows_, embed_, series_})
    connect(box, &QCheckBox::toggled, this, [this] {
      if (!updating_) revalidate();
    });
  for (QComboBox* box : {taMeaning_, taSign_})
    connect(box, &QComboBox::currentIndexChanged, this, [this] {
      if (!updating_) revalidate();
    });
  const bool saved = QFileInfo::exists(projectPath_);
  embed_->setEnabled(saved);
  embed_->setToolTip(saved ? tr("Copy the file to the project's data folder as <id>.<extension> and refer to "
                                "the copy; the import never overwrites a file there")
                           : tr("Save the project first: the copy goes into the project's folder"));
  revalidate();
}

QString ImportDialog::guessKind(const QString& path, const QByteArray& head) {
  return QString::fromStdString(guessDatasetKind(path.toStdString(), head.toStdString()));
}

void ImportDialog::reguessKind() {
  // The kind follows what the file turns out to be once the dialect or the header line is right
  // (a title line above the header, a ';' file read with ','), until the user chooses one.
  if (!kindChosen_ && readError_.isEmpty() && !text_.empty()) {
    CsvReadOptions o;
    o.dialect.delimiter = static_cast<char>(delimiter_->currentData().toInt());
    o.dialect.decimal = static_cast<char>(decimal_->currentData().toInt());
    o.headerLines = headerLines_->value();
    o.commentPrefix = comment_->text().trimmed().toStdString();
    const QString guessed = QString::fromStdString(
        guessDatasetKind(file_.toStdString(), std::string_view(text_).substr(0, 64 * 1024), o));
    const int k = kind_->findData(guessed);
    if (k >= 0 && k != kind_->currentIndex()) {
      {
        const QSignalBlocker block(kind_);
        kind_->setCurrentIndex(k);
      }
      roles_.clear();
      revalidate();
      rebuildMapping(header_);
      guessRoles();
    }
  }
  revalidate();
}

QStringList ImportDialog::rolesForKind(const QString& kind) {
  if (kind == QLatin1String("thermal-log"))
    return {QStringLiteral("time_s"),    QStringLiteral("time_min"),   QStringLiteral("time_h"),
            QStringLiteral("disp_x_um"), QStringLiteral("disp_y_um"),  QStringLiteral("disp_z_um"),
            QStringLiteral("T1"),        QStringLiteral("T2"),         QStringLiteral("T3"),
            QStringLiteral("T4"),        QStringLiteral("T5"),         QStringLiteral("T6"),
            QStringLiteral("T_amb"),     QStringLiteral("spindle_rpm")};
  if (kind == QLatin1String("probe-points"))
    return {QStringLiteral("id"), QStringLiteral("surface"), QStringLiteral("qx"), QStringLiteral("qy"),
            QStringLiteral("qz"), QStringLiteral("px"),      QStringLiteral("py"), QStringLiteral("pz"),
            QStringLiteral("nx"), QStringLiteral("ny"),      QStringLiteral("nz")};
  if (kind == QLatin1String("circular-test"))
    return {QStringLiteral("x_cmd_mm"),     QStringLiteral("y_cmd_mm"),  QStringLiteral("x_meas_mm"),
            QStringLiteral("y_meas_mm"),    QStringLiteral("angle_deg"), QStringLiteral("deviation_um"),
            QStringLiteral("deviation_mm"), QStringLiteral("direction"), QStringLiteral("run"),
            QStringLiteral("radius_mm")};
  if (kind == QLatin1String("cmm-report"))
    return {QStringLiteral("part"),        QStringLiteral("time_min"),    QStringLiteral("dimension"),
            QStringLiteral("nominal_mm"),  QStringLiteral("measured_mm"), QStringLiteral("lower_tol_mm"),
            QStringLiteral("upper_tol_mm")};
  return {};
}

void ImportDialog::browse() {
  const QString start = file_.isEmpty() ? QFileInfo(projectPath_).path() : QFileInfo(file_).path();
  // All files first: CMM exports and data loggers often write files without an extension (a Wenzel
  // point file "SPH1_1"), which the data-file filter would hide.
  QString selected = tr("All files (*)");
  const QString path = QFileDialog::getOpenFileName(this, tr("Import data"), start, fileFilter(), &selected);
  if (!path.isEmpty()) setFile(path);
}

QString ImportDialog::fileFilter() {
  return tr("All files (*)") + QStringLiteral(";;") +
         tr("Data files (*.csv *.txt *.tsv *.json *.dmi *.dms *.dmis *.xml "
            "*.qif *.QIF *.dfq *.DFQ *.stl *.STL)");
}

void ImportDialog::setFile(const QString& path) {
  file_ = QFileInfo(path).absoluteFilePath();
  text_.clear();
  readError_.clear();
  QFile f(file_);
  if (!f.open(QIODevice::ReadOnly)) {
    readError_ = tr("%1: cannot read the file (%2)").arg(QDir::toNativeSeparators(file_), f.errorString());
  } else if (f.size() > kMaxFileBytes) {
    readError_ = tr("%1: the file is larger than 256 MiB").arg(QDir::toNativeSeparators(file_));
  } else {
    text_ = f.readAll().toStdString();
  }
  {
    const QSignalBlocker b1(kind_), b2(delimiter_), b3(decimal_), b4(id_), b5(headerLines_), b6(comment_),
        b7(skipBadRows_), b8(taMeaning_), b9(taSign_);
    fileEdit_->setText(QDir::toNativeSeparators(file_));
    fileEdit_->setToolTip(fileEdit_->text());
    kindChosen_ = false;
    const int k = kind_->findData(guessKind(file_, QByteArray::fromStdString(text_.substr(0, 64 * 1024))));
    if (k >= 0) kind_->setCurrentIndex(k);
    delimiter_->setCurrentIndex(0);
    decimal_->setCurrentIndex(0);
    headerLines_->setValue(-1);
    comment_->clear();
    skipBadRows_->setChecked(false);
    taMeaning_->setCurrentIndex(0);
    taSign_->setCurrentIndex(0);
    id_->clear();
    id_->setPlaceholderText(QFileInfo(file_).completeBaseName());
  }
  // The measured parts of a QIF file (a file that does not read leaves the list empty: the dataset
  // check below then names its problem).
  qifParts_.clear();
  if (looksLikeQif(text_)) {
    try {
      const QifFile qif = qifFromText(text_, displayPath(file_.toStdString()));
      for (std::size_t k = 0; k < qif.parts.size(); ++k) {
        QStringList label{QString::number(k + 1)};
        if (!qif.parts[k].serial.empty()) label << QString::fromStdString(qif.parts[k].serial);
        if (!qif.parts[k].status.empty()) label << QString::fromStdString(qif.parts[k].status);
        qifParts_ << label.join(QStringLiteral(" · "));
      }
    } catch (const std::exception&) {
      qifParts_.clear();
    }
  }
  {
    const QSignalBlocker block(qifPart_);
    qifPart_->clear();
    qifPart_->addItems(qifParts_);
  }
  roles_.clear();
  header_.clear();
  revalidate();
  guessRoles();
  revalidate();
}

int ImportDialog::qifPart() const {
  // Only probe points are one part; a qif (or cmm-report) dataset reads every part.
  const bool choosesPart =
      qifParts_.size() > 1 && projectKind(kind()) == QLatin1String(dataset_kind::kProbePoints);
  return choosesPart ? qifPart_->currentIndex() + 1 : 0;
}

void ImportDialog::setQifPart(int part) {
  if (part >= 1 && part <= qifPart_->count()) qifPart_->setCurrentIndex(part - 1);
}

QString ImportDialog::file() const {
  return file_;
}

void ImportDialog::setKind(const QString& kind) {
  const int k = kind_->findData(kind);
  if (k >= 0) kind_->setCurrentIndex(k);
}

QString ImportDialog::kind() const {
  return kind_->currentData().toString();
}

void ImportDialog::setDatasetId(const QString& id) {
  id_->setText(id);
}

void ImportDialog::setDelimiter(char delimiter) {
  const int i = delimiter_->findData(static_cast<int>(delimiter));
  if (i >= 0) delimiter_->setCurrentIndex(i);
}

void ImportDialog::setDecimal(char decimal) {
  const int i = decimal_->findData(static_cast<int>(decimal));
  if (i >= 0) decimal_->setCurrentIndex(i);
}

void ImportDialog::setRole(const QString& column, const QString& role) {
  for (int r = 0; r < mapping_->rowCount(); ++r) {
    if (mapping_->item(r, MapFileColumn)->text() != column) continue;
    if (auto* combo = qobject_cast<QComboBox*>(mapping_->cellWidget(r, MapRole))) {
      combo->setCurrentText(role);  // revalidates through currentTextChanged
      return;
    }
  }
  roles_[column] = role.trimmed();
  revalidate();
}

QString ImportDialog::role(const QString& column) const {
  return roles_.value(column);
}

bool ImportDialog::isMtconnectLog() const {
  const QString k = projectKind(kind());
  return (k == QLatin1String(dataset_kind::kMtconnect) || k == QLatin1String(dataset_kind::kThermalLog)) &&
         looksLikeMtconnectLog(std::string_view(text_).substr(0, 64 * 1024));
}

void ImportDialog::setSampleIntervalS(double seconds) {
  sampleInterval_->setValue(seconds);
}

double ImportDialog::sampleIntervalS() const {
  return sampleInterval_->value();
}

CsvReadOptions ImportDialog::csvOptions() const {
  CsvReadOptions o;
  if (isMtconnectLog()) {
    // The grid in minutes, as the project stores a thermal log's interval (thermal_log.h); the default
    // grid is not stored.
    if (sampleInterval_->value() != kMtconnectDefaultIntervalS)
      o.sampleIntervalMin = sampleInterval_->value() / 60.0;
    return o;
  }
  if (!datasetKindIsCsv(projectKind(kind()).toStdString()) || looksLikeCmmTextReport(text_) || isDmisFile())
    return o;
  o.dialect.delimiter = static_cast<char>(delimiter_->currentData().toInt());
  o.dialect.decimal = static_cast<char>(decimal_->currentData().toInt());
  o.headerLines = headerLines_->value();
  o.commentPrefix = comment_->text().toStdString();
  o.skipBadRows = skipBadRows_->isChecked();
  for (const std::string& column : header_) {
    const QString role = roles_.value(QString::fromStdString(column));
    if (!role.isEmpty() && role.toStdString() != column) o.columnMap.emplace_back(role.toStdString(), column);
  }
  // In the order the project file gives them back (a JSON object, sorted by role), so that a saved
  // and reopened dataset equals the one imported.
  std::sort(o.columnMap.begin(), o.columnMap.end());
  return o;
}

void ImportDialog::setHeaderLines(int lines) {
  headerLines_->setValue(lines);
}

void ImportDialog::setCommentPrefix(const QString& prefix) {
  comment_->setText(prefix);
}

void ImportDialog::setSkipBadRows(bool skip) {
  skipBadRows_->setChecked(skip);
}

QStringList ImportDialog::rowProblems() const {
  QStringList out;
  for (int i = 0; i < rowProblems_->count(); ++i) out << rowProblems_->item(i)->text();
  return out;
}

bool ImportDialog::isDmisFile() const {
  const QString k = kind();
  return (k == QLatin1String("dmis") || k == QLatin1String("cmm-report")) && setup::looksLikeDmis(text_);
}

void ImportDialog::setTaMeaning(const QString& meaning) {
  const int i = taMeaning_->findData(meaning);
  if (i >= 0) taMeaning_->setCurrentIndex(i);
}

void ImportDialog::setTaSign(const QString& sign) {
  const int i = taSign_->findData(sign);
  if (i >= 0) taSign_->setCurrentIndex(i);
}

setup::DmisOptions ImportDialog::dmisOptions() const {
  setup::DmisOptions o;
  if (!isDmisFile()) return o;
  o.taMeaning = setup::parseDmisTaMeaning(taMeaning_->currentData().toString().toStdString());
  o.signFollowsNominal = taSign_->currentData().toString() == QLatin1String("nominal");
  return o;
}

void ImportDialog::setSeriesFiles(const QStringList& more) {
  seriesFiles_ = more;
  series_->setText(tr("Read the %n selected files as one DMIS &series (one dataset, one file per workpiece)",
                      nullptr, static_cast<int>(more.size() + 1)));
  series_->setToolTip(tr("Also: %1").arg(more.join(QStringLiteral(", "))));
  series_->setVisible(!more.isEmpty());
  revalidate();
}

void ImportDialog::setReadsSeries(bool series) {
  series_->setChecked(series);
}

bool ImportDialog::readsSeries() const {
  return !seriesFiles_.isEmpty() && series_->isChecked();
}

void ImportDialog::setEmbed(bool embed) {
  embed_->setChecked(embed);
}

bool ImportDialog::embed() const {
  return embed_->isEnabled() && embed_->isChecked();
}

void ImportDialog::importNow() {
  if (!canImport()) return;
  if (embed()) {
    try {
      embedDataset(QFile::encodeName(projectPath_).toStdString(), QFile::encodeName(file_).toStdString(),
                   dataset_);
    } catch (const std::exception& e) {
      problem_ = QString::fromStdString(e.what());
      problemLabel_->setText(problem_);
      problemLabel_->setStyleSheet(QStringLiteral("color: #b00020;"));
      buttons_->button(QDialogButtonBox::Ok)->setEnabled(false);
      return;
    }
  }
  accept();
}

void ImportDialog::guessRoles() {
  if (header_.empty()) return;
  // Core's suggestions (core/project/import_guess.h): names matched ignoring case, in English, German
  // and Polish, with the unit from the bracket; a column the user gave a role keeps it.
  bool changed = false;
  for (const auto& [role, column] : suggestColumnRoles(kind().toStdString(), header_)) {
    const QString c = QString::fromStdString(column);
    const QString r = QString::fromStdString(role);
    if (!roles_.value(c).isEmpty()) continue;
    bool used = false;
    for (auto it = roles_.cbegin(); it != roles_.cend(); ++it) used = used || it.value() == r;
    if (used) continue;
    roles_[c] = r;
    changed = true;
  }
  if (changed) rebuildMapping(header_);
  // A thermal log's time column when the file names its unit in another way ("t (s)", "t_s").
  if (kind() != QLatin1String("thermal-log")) return;
  for (const std::string& c : header_) {
    if (c == "time_s" || c == "time_min" || c == "time_h") return;
    if (!roles_.value(QString::fromStdString(c)).isEmpty()) {
      const QString r = roles_.value(QString::fromStdString(c));
      if (r.startsWith(QLatin1String("time_"))) return;
    }
  }
  const QString first = QString::fromStdString(header_.front());
  const QString lower = first.toLower().remove(QLatin1Char(' '));
  QString role;
  if (lower.contains(QLatin1String("[s]")) || lower.contains(QLatin1String("(s)")) ||
      lower.endsWith(QLatin1String("_s")))
    role = QStringLiteral("time_s");
  else if (lower.contains(QLatin1String("[min]")) || lower.contains(QLatin1String("(min)")))
    role = QStringLiteral("time_min");
  else if (lower.contains(QLatin1String("[h]")) || lower.contains(QLatin1String("(h)")))
    role = QStringLiteral("time_h");
  if (role.isEmpty()) return;
  roles_[first] = role;
  rebuildMapping(header_);
}

void ImportDialog::rebuildMapping(const std::vector<std::string>& header) {
  header_ = header;
  const QSignalBlocker blocker(mapping_);
  // The role editors being replaced are hidden now: the view deletes them later, and when the dialog
  // runs as a nested loop (exec() from the main window) "later" is after it closes, so they would stay
  // on screen where the first layout put them (over the column names).
  for (int r = 0; r < mapping_->rowCount(); ++r)
    if (QWidget* old = mapping_->cellWidget(r, MapRole)) old->hide();
  mapping_->setRowCount(static_cast<int>(header.size()));
  const QStringList roles = rolesForKind(kind());
  for (int r = 0; r < static_cast<int>(header.size()); ++r) {
    const QString column = QString::fromStdString(header[static_cast<std::size_t>(r)]);
    mapping_->setItem(r, MapFileColumn, new QTableWidgetItem(column));
    if (!mapping_->item(r, MapFirstValue)) mapping_->setItem(r, MapFirstValue, new QTableWidgetItem);
    auto* combo = new QComboBox(mapping_);
    combo->setEditable(true);
    combo->setInsertPolicy(QComboBox::NoInsert);
    combo->addItem(QString());
    for (const QString& role : roles) {
      combo->addItem(role);
      combo->setItemData(combo->count() - 1, roleDescription(role), Qt::ToolTipRole);
    }
    combo->lineEdit()->setPlaceholderText(tr("as in the file"));
    combo->setCurrentText(roles_.value(column));
    combo->setObjectName(QStringLiteral("importRole_%1").arg(r));
    connect(combo, &QComboBox::currentTextChanged, this, [this, column](const QString& text) {
      roles_[column] = text.trimmed();
      if (!updating_) revalidate();
    });
    mapping_->setCellWidget(r, MapRole, combo);
  }
}

void ImportDialog::showRawPreview() {
  preview_->clear();
  preview_->setColumnCount(1);
  preview_->setHorizontalHeaderLabels({tr("Line")});
  QStringList lines = QString::fromStdString(text_.substr(0, 64 * 1024)).split(QLatin1Char('\n'));
  if (lines.size() > kRawPreviewLines) lines = lines.mid(0, kRawPreviewLines);
  preview_->setRowCount(static_cast<int>(lines.size()));
  for (int r = 0; r < lines.size(); ++r) {
    QString line = lines[r];
    line.remove(QLatin1Char('\r'));
    preview_->setItem(r, 0, new QTableWidgetItem(line));
  }
  preview_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
}

void ImportDialog::fillPreview(const CsvTable& table) {
  preview_->clear();
  const int columns = static_cast<int>(table.columnCount());
  const int rows = static_cast<int>(std::min<std::size_t>(table.rowCount(), kPreviewRows));
  preview_->setColumnCount(columns);
  preview_->setRowCount(rows);
  QStringList labels;
  for (int c = 0; c < columns; ++c) {
    const QString column = QString::fromStdString(table.header()[static_cast<std::size_t>(c)]);
    const QString role = roles_.value(column);
    labels << (role.isEmpty() || role == column ? column : column + QStringLiteral("\n→ ") + role);
  }
  preview_->setHorizontalHeaderLabels(labels);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c)
      preview_->setItem(r, c,
                        new QTableWidgetItem(QString::fromStdString(
                            table.cell(static_cast<std::size_t>(r), static_cast<std::size_t>(c)))));
  preview_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  for (int r = 0; r < mapping_->rowCount(); ++r) {
    QTableWidgetItem* item = mapping_->item(r, MapFirstValue);
    if (item)
      item->setText(table.rowCount() > 0 && r < columns
                        ? QString::fromStdString(table.cell(0, static_cast<std::size_t>(r)))
                        : QString());
  }
}

void ImportDialog::previewDmis() {
  // With a setup model in the project: the deviations the setup study will read with these settings.
  const SetupStudyFiles files = setupStudyFiles(project_, QFile::encodeName(projectPath_).toStdString());
  if (files.modelPath.empty()) {
    detected_->setText(
        tr("DMIS output: add a setup model to the project to preview the deviations read "
           "with these settings."));
    return;
  }
  try {
    const setup::Model model = setup::readModel(files.modelPath);
    // A series: every file, as the setup study reads it (the means over the workpieces); else the file.
    std::vector<std::string> series;
    if (readsSeries()) {
      series.push_back(QFile::encodeName(file_).toStdString());
      for (const QString& more : seriesFiles_) series.push_back(QFile::encodeName(more).toStdString());
    }
    const setup::Measurements m =
        series.empty()
            ? setup::dmisReportFromText(text_, displayPath(file_.toStdString()), model, dmisOptions())
            : setup::readMeasurements(series, model, {}, dmisOptions());
    preview_->clear();
    preview_->setColumnCount(2);
    preview_->setRowCount(static_cast<int>(model.dimensions.size()));
    preview_->setHorizontalHeaderLabels({tr("Dimension"), tr("Deviation (mm)")});
    for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
      preview_->setItem(static_cast<int>(q), 0,
                        new QTableWidgetItem(QString::fromStdString(model.dimensions[q].id)));
      preview_->setItem(static_cast<int>(q), 1,
                        new QTableWidgetItem(m.samples[q] > 0 ? QString::number(m.deviationMm[q], 'g', 6)
                                                              : QStringLiteral("–")));
    }
    preview_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    detected_->setText(
        series.empty()
            ? tr("DMIS output read against the setup model “%1”.").arg(QString::fromStdString(files.modelId))
            : tr("DMIS series of %1 files read against the setup model “%2”: the mean deviation over the "
                 "workpieces.")
                  .arg(series.size())
                  .arg(QString::fromStdString(files.modelId)));
  } catch (const std::exception& e) {
    // Not a reason to refuse the file (it may belong to another model): said, not blocking.
    detected_->setText(tr("DMIS output; read against the setup model “%1”: %2")
                           .arg(QString::fromStdString(files.modelId), QString::fromStdString(e.what())));
  }
}

void ImportDialog::previewMtconnect() {
  try {
    const MtcSampleTable t =
        readMtconnectSampleTable(QFile::encodeName(file_).toStdString(), sampleInterval_->value());
    fillPreview(t.table);
    detected_->setText(tr("MTConnect log resampled every %1 s (zero-order hold: the last value at or before "
                          "each time): %2 rows, %3 sample columns; %4 data items are not columns (events, "
                          "conditions, no numbers).")
                           .arg(QLocale().toString(t.intervalS, 'g', 6))
                           .arg(t.table.rowCount())
                           .arg(t.table.columnCount() - 1)
                           .arg(t.skipped.size()));
  } catch (const std::exception& e) {
    // The dataset check below names the problem (file and line); the raw lines stay in the preview.
    detected_->setText(QString::fromStdString(e.what()));
  }
}

void ImportDialog::previewContent(const std::string& file) {
  try {
    auto content = std::make_shared<const DatasetContent>(readDatasetContentFile(file, dataset_));
    DatasetTableModel model;
    model.setContent(content);
    const int rows = std::min(model.rowCount(), kPreviewRows);
    const int columns = model.columnCount();
    preview_->clear();
    preview_->setColumnCount(columns);
    preview_->setRowCount(rows);
    QStringList labels;
    for (int c = 0; c < columns; ++c) labels << model.headerData(c, Qt::Horizontal).toString();
    preview_->setHorizontalHeaderLabels(labels);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        const QModelIndex index = model.index(r, c);
        auto* item = new QTableWidgetItem(model.data(index).toString());
        const QVariant background = model.data(index, Qt::BackgroundRole);
        if (background.isValid()) item->setBackground(background.value<QBrush>());
        const QVariant icon = model.data(index, Qt::DecorationRole);
        if (icon.isValid()) item->setIcon(icon.value<QIcon>());
        preview_->setItem(r, c, item);
      }
    }
    preview_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    const QString shape = content->shape == DatasetContent::Shape::Features
                              ? tr("%n feature row(s)", nullptr, model.rowCount())
                              : tr("%n row(s)", nullptr, model.rowCount());
    detected_->setText(
        tr("%1: read as %2, %3.")
            .arg(QString::fromStdString(content->format), datasetKindTitle(projectKind(kind())), shape));
  } catch (const std::exception&) {
    // The raw lines stay; the dataset check has accepted the file, so the studies will say more.
  }
}

void ImportDialog::revalidate() {
  if (updating_) return;
  updating_ = true;
  problem_.clear();
  nominalsSummary_.clear();
  const std::string cliKind = kind().toStdString();
  // A CMM text report is read by its own reader whatever CSV kind it is imported as.
  const bool csv = datasetKindIsCsv(projectKind(kind()).toStdString()) && !looksLikeCmmTextReport(text_) &&
                   !isDmisFile() && !isMtconnectLog();
  delimiter_->setEnabled(csv);
  decimal_->setEnabled(csv);
  headerLines_->setEnabled(csv);
  comment_->setEnabled(csv);
  skipBadRows_->setEnabled(csv);
  mapping_->setEnabled(csv);
  // A file that is no CSV has no columns to map: the preview takes the whole width.
  findChild<QGroupBox*>(QStringLiteral("importMappingBox"))->setVisible(csv || file_.isEmpty());
  rowProblems_->clear();
  dmisBox_->setVisible(!file_.isEmpty() && readError_.isEmpty() && isDmisFile());
  nominalsBox_->setVisible(needsNominals());
  form_->setRowVisible(qifPart_, qifPart() > 0);
  form_->setRowVisible(sampleInterval_, !file_.isEmpty() && readError_.isEmpty() && isMtconnectLog());
  auto* problemsTitle = findChild<QLabel*>(QStringLiteral("importRowProblemsTitle"));
  problemsTitle->setText(tr("Rows that cannot be read:"));
  int skipped = 0;
  if (file_.isEmpty()) {
    problem_ = tr("Choose a file to import.");
    detected_->clear();
    preview_->clear();
    preview_->setRowCount(0);
    preview_->setColumnCount(0);
  } else if (!readError_.isEmpty()) {
    problem_ = readError_;
    detected_->clear();
  } else if (!csv) {
    detected_->setText(tr("Not a CSV file: read as %1 (no delimiter, decimal mark or column mapping).")
                           .arg(datasetKindTitle(projectKind(kind()))));
    if (!header_.empty()) rebuildMapping({});
    showRawPreview();
    if (isDmisFile()) previewDmis();
    if (isMtconnectLog()) previewMtconnect();
  } else {
    const std::string shown = displayPath(file_.toStdString());
    CsvReadOptions dialectOnly;
    dialectOnly.dialect.delimiter = static_cast<char>(delimiter_->currentData().toInt());
    dialectOnly.dialect.decimal = static_cast<char>(decimal_->currentData().toInt());
    dialectOnly.headerLines = headerLines_->value();
    dialectOnly.commentPrefix = comment_->text().toStdString();
    // The preview shows the rows that can be read and lists the others under it.
    dialectOnly.skipBadRows = true;
    try {
      const CsvTable table = parseCsv(text_, shown, dialectOnly);
      if (table.header() != header_) rebuildMapping(table.header());
      fillPreview(table);
      const long line = table.headerLineNumber();
      const auto comments = static_cast<long>(table.comments().size());
      headerLines_->setSpecialValueText(tr("detect (%1)").arg(line - 1));
      for (const CsvRowProblem& p : table.skippedRows())
        rowProblems_->addItem(QString::fromStdString(describeRowProblem(p)));
      skipped = static_cast<int>(table.skippedRows().size());
      if (skipped > 0 && !skipBadRows_->isChecked()) {
        problemsTitle->setText(
            tr("Rows that cannot be read (%1): tick “Skip unreadable rows” to import without them.")
                .arg(skipped));
        // Strict: the first unreadable row is the error, as the readers give it.
        const CsvRowProblem& first = table.skippedRows().front();
        const int column = table.columnIndex(first.column);
        problem_ = QString::fromStdString(
            ParseError(ErrorContext{shown, first.line, column + 1L, first.column}, first.why).what());
      } else if (skipped > 0) {
        problemsTitle->setText(tr("Rows that cannot be read (%1), left out:").arg(skipped));
      }
      const auto found = [](char chosen, const QString& text) {
        return chosen == 0 ? tr("%1 (detected)").arg(text) : text;
      };
      detected_->setText(
          tr("delimiter %1 · decimal mark %2 · header in line %3 (%4 columns) · comment lines: %5 "
             "· data rows: %6")
              .arg(found(dialectOnly.dialect.delimiter, delimiterText(table.dialect().delimiter)),
                   found(dialectOnly.dialect.decimal, decimalText(table.dialect().decimal)))
              .arg(line)
              .arg(table.columnCount())
              .arg(comments)
              .arg(table.rowCount()));
    } catch (const std::exception& e) {
      problem_ = QString::fromStdString(e.what());
      detected_->clear();
      showRawPreview();
    }
  }
  if (problem_.isEmpty()) {
    try {
      Project scratch = project_;
      AddDatasetRequest request;
      request.kind = cliKind;
      request.file = QFile::encodeName(file_).toStdString();
      request.id = id_->text().trimmed().toStdString();
      request.csv = csvOptions();
      request.dmis = dmisOptions();
      if (needsNominals()) request.nominals = nominals();
      request.part = qifPart();
      if (readsSeries())
        for (const QString& more : seriesFiles_)
          request.moreFiles.push_back(QFile::encodeName(more).toStdString());
      dataset_ = addDataset(scratch, QFile::encodeName(projectPath_).toStdString(), request);
      // A file that is no CSV (QIF, DFQ, Calypso, an OGP or PC-DMIS report, a setup model) is previewed
      // as the studies will read it: a feature table or the points, not its raw lines.
      if (!csv && !isDmisFile() && !isMtconnectLog()) previewContent(request.file);
      if (dataset_.nominals.from == "cad") {
        // addDataset read the points onto the part already; say which part.
        nominalsSummary_ = tr("Nominals: the closest points of the CAD part “%1”; the matching moves the "
                              "points onto it at each posture (closed form or minimum zone).")
                               .arg(QString::fromStdString(dataset_.nominals.cad));
      } else if (!dataset_.nominals.empty()) {
        // What the nominals came out as: the element's size and form (the same computation the
        // readers make, core/project/nominals.h).
        std::optional<geometry::PointSet> reference;
        if (const DatasetRef* r = nominalReference(scratch, dataset_))
          reference = geometry::readPointTable(
              resolveDatasetPath(QFile::encodeName(projectPath_).toStdString(), *r), r->csv);
        const NominalsOutcome out = nominalsFor(geometry::readPointTable(request.file, dataset_.csv),
                                                dataset_.nominals, reference ? &*reference : nullptr);
        nominalsSummary_ = nominalsText(out, dataset_.nominals);
      }
    } catch (const std::exception& e) {
      problem_ = QString::fromStdString(e.what());
    }
  }
  if (problem_.isEmpty() && embed()) {
    const QString copy =
        QString::fromStdString(embeddedDatasetPath(dataset_.id, file_.toStdString(), dataset_.kind));
    const QString target = QFileInfo(projectPath_).absoluteDir().filePath(copy);
    if (QFileInfo::exists(target))
      problem_ = tr("%1: already exists; an embedded copy never overwrites a file (choose another id)")
                     .arg(QDir::toNativeSeparators(target));
  }
  QString ready = tr("Ready to import as %1 “%2”.")
                      .arg(datasetKindTitle(projectKind(kind())), QString::fromStdString(dataset_.id));
  if (readsSeries())
    ready += QLatin1Char(' ') + tr("The %n file(s) are one DMIS series: one workpiece per file.", nullptr,
                                   static_cast<int>(dataset_.paths.size()));
  if (skipped > 0) ready += QLatin1Char(' ') + tr("%n unreadable row(s) will be left out.", nullptr, skipped);
  if (problem_.isEmpty() && !nominalsSummary_.isEmpty()) ready += QLatin1Char(' ') + nominalsSummary_;
  if (embed())
    ready += QLatin1Char(' ') + tr("The file is copied to %1.")
                                    .arg(QString::fromStdString(embeddedDatasetPath(
                                        dataset_.id, file_.toStdString(), dataset_.kind)));
  // The list of unreadable rows takes room from the preview only when it has something to say.
  rowProblems_->setVisible(rowProblems_->count() > 0);
  problemsTitle->setVisible(rowProblems_->count() > 0);
  problemLabel_->setText(problem_.isEmpty() ? ready : problem_);
  problemLabel_->setStyleSheet(problem_.isEmpty() ? QString() : QStringLiteral("color: #b00020;"));
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(problem_.isEmpty());
  updating_ = false;
}

void ImportDialog::buildNominalsBox() {
  nominalsBox_ = new QGroupBox(tr("Nominals of the measured points"), this);
  nominalsBox_->setObjectName(QStringLiteral("importNominals"));
  nominalFrom_ = new QComboBox(nominalsBox_);
  nominalFrom_->setObjectName(QStringLiteral("importNominalFrom"));
  nominalFrom_->addItem(tr("a fitted element"), QStringLiteral("element"));
  nominalFrom_->addItem(tr("a second measurement of the part"), QStringLiteral("reference"));
  nominalFrom_->addItem(tr("a CAD part"), QStringLiteral("cad"));
  nominalElement_ = new QComboBox(nominalsBox_);
  nominalElement_->setObjectName(QStringLiteral("importNominalElement"));
  nominalElement_->addItem(tr("no normals (positions only)"), QString());
  for (const char* e : {"plane", "line", "circle", "sphere", "cylinder", "cone"})
    nominalElement_->addItem(elementTitle(QString::fromLatin1(e)), QString::fromLatin1(e));
  nominalElement_->setCurrentIndex(nominalElement_->findData(QStringLiteral("sphere")));
  nominalRadius_ = new QDoubleSpinBox(nominalsBox_);
  nominalRadius_->setObjectName(QStringLiteral("importNominalRadius"));
  nominalRadius_->setRange(0.0, 1.0e6);
  nominalRadius_->setDecimals(4);
  nominalRadius_->setSuffix(tr(" mm"));
  nominalRadius_->setSpecialValueText(tr("free (fitted)"));
  nominalRadius_->setToolTip(tr("A calibrated or drawing radius the element keeps; free: fitted"));
  nominalCriterion_ = new QComboBox(nominalsBox_);
  nominalCriterion_->setObjectName(QStringLiteral("importNominalCriterion"));
  nominalCriterion_->addItem(tr("least squares"), QStringLiteral("ls"));
  nominalCriterion_->addItem(tr("minimum zone"), QStringLiteral("minimax"));
  nominalInner_ = new QCheckBox(tr("&Bore or hole (material outside)"), nominalsBox_);
  nominalInner_->setObjectName(QStringLiteral("importNominalInner"));
  nominalInner_->setToolTip(tr("The normals point out of the material: into a bore, out of a shaft or ball"));
  nominalRobust_ = new QCheckBox(tr("Leave stray points out of the fit"), nominalsBox_);
  nominalRobust_->setObjectName(QStringLiteral("importNominalRobust"));
  nominalReference_ = new QComboBox(nominalsBox_);
  nominalReference_->setObjectName(QStringLiteral("importNominalReference"));
  for (const DatasetRef& d : project_.datasets)
    if (d.kind == dataset_kind::kProbePoints)
      nominalReference_->addItem(QString::fromStdString(d.id), QString::fromStdString(d.id));
  nominalCad_ = new QComboBox(nominalsBox_);
  nominalCad_->setObjectName(QStringLiteral("importNominalCad"));
  for (const DatasetRef& d : project_.datasets)
    if (d.kind == dataset_kind::kCadModel)
      nominalCad_->addItem(QString::fromStdString(d.id), QString::fromStdString(d.id));
  if (nominalCad_->count() == 0) {
    nominalFrom_->setItemData(2, 0, Qt::UserRole - 1);
    nominalFrom_->setItemData(2, tr("Import the part's STL file first"), Qt::ToolTipRole);
  }
  nominalPair_ = new QComboBox(nominalsBox_);
  nominalPair_->setObjectName(QStringLiteral("importNominalPair"));
  nominalPair_->addItem(tr("by id"), QStringLiteral("id"));
  nominalPair_->addItem(tr("by order"), QStringLiteral("order"));
  if (nominalReference_->count() == 0) {
    // Without another probe-point dataset there is no second measurement to choose.
    nominalFrom_->setItemData(1, 0, Qt::UserRole - 1);
    nominalFrom_->setItemData(1, tr("Import the first measurement of the part first"), Qt::ToolTipRole);
  }
  auto* form = new QFormLayout(nominalsBox_);
  auto* fromRow = new QHBoxLayout;
  fromRow->addWidget(nominalFrom_);
  auto* referenceLabel = new QLabel(tr("&Measurement:"), nominalsBox_);
  referenceLabel->setObjectName(QStringLiteral("importNominalReferenceLabel"));
  referenceLabel->setBuddy(nominalReference_);
  fromRow->addWidget(referenceLabel);
  fromRow->addWidget(nominalReference_);
  fromRow->addWidget(nominalPair_);
  fromRow->addWidget(nominalCad_);
  fromRow->addStretch(1);
  auto* fromLabel = new QLabel(tr("&From:"), nominalsBox_);
  fromLabel->setBuddy(nominalFrom_);
  form->addRow(fromLabel, fromRow);
  auto* elementRow = new QHBoxLayout;
  elementRow->addWidget(nominalElement_);
  auto* radiusLabel = new QLabel(tr("&Radius:"), nominalsBox_);
  radiusLabel->setBuddy(nominalRadius_);
  elementRow->addWidget(radiusLabel);
  elementRow->addWidget(nominalRadius_);
  elementRow->addWidget(nominalCriterion_);
  elementRow->addWidget(nominalInner_);
  elementRow->addWidget(nominalRobust_);
  elementRow->addStretch(1);
  auto* elementLabel = new QLabel(tr("&Element:"), nominalsBox_);
  elementLabel->setBuddy(nominalElement_);
  form->addRow(elementLabel, elementRow);
  nominalsBox_->setVisible(false);
  updateNominalControls();
  const auto changed = [this] {
    updateNominalControls();
    revalidate();
  };
  for (QComboBox* c :
       {nominalFrom_, nominalElement_, nominalCriterion_, nominalReference_, nominalPair_, nominalCad_})
    connect(c, &QComboBox::currentIndexChanged, this, changed);
  connect(nominalRadius_, &QDoubleSpinBox::valueChanged, this, changed);
  for (QCheckBox* c : {nominalInner_, nominalRobust_}) connect(c, &QCheckBox::toggled, this, changed);
}

void ImportDialog::updateNominalControls() {
  const bool reference = nominalFrom_->currentData().toString() == QLatin1String("reference");
  const bool cad = nominalFrom_->currentData().toString() == QLatin1String("cad");
  nominalCad_->setVisible(cad);
  nominalElement_->setEnabled(!cad);
  // "no normals" only for a second measurement: an element's own nominals need an element.
  nominalElement_->setItemData(0, reference ? QVariant() : QVariant(0), Qt::UserRole - 1);
  if (!reference && nominalElement_->currentData().toString().isEmpty()) {
    const QSignalBlocker block(nominalElement_);
    nominalElement_->setCurrentIndex(nominalElement_->findData(QStringLiteral("sphere")));
  }
  const QString element = nominalElement_->currentData().toString();
  const bool fitted = !element.isEmpty() && !cad;
  nominalReference_->setVisible(reference);
  nominalPair_->setVisible(reference);
  if (auto* l = findChild<QLabel*>(QStringLiteral("importNominalReferenceLabel"))) l->setVisible(reference);
  geometry::ElementKind kind{};
  const bool radius =
      fitted && geometry::parseElementKind(element.toStdString(), &kind) && geometry::takesFixedRadius(kind);
  nominalRadius_->setEnabled(radius);
  nominalCriterion_->setEnabled(fitted);
  nominalInner_->setEnabled(fitted);
  nominalRobust_->setEnabled(fitted);
}

bool ImportDialog::needsNominals() const {
  if (kind() != QLatin1String("probe-points") || file_.isEmpty() || !readError_.isEmpty() ||
      header_.empty() || looksLikeCmmTextReport(text_) || looksLikeHoleTable(text_))
    return false;
  // The names the readers see: a column's role, or its own name.
  QStringList names;
  for (const std::string& h : header_) {
    const QString column = QString::fromStdString(h);
    const QString role = roles_.value(column);
    names << (role.isEmpty() ? column : role);
  }
  const bool points = names.contains(QStringLiteral("px")) || names.contains(QStringLiteral("x_mm")) ||
                      names.contains(QStringLiteral("x"));
  return points && !names.contains(QStringLiteral("qx"));
}

void ImportDialog::setNominals(const NominalSource& n) {
  {
    const QSignalBlocker b1(nominalFrom_), b2(nominalElement_), b3(nominalRadius_), b4(nominalCriterion_),
        b5(nominalInner_), b6(nominalRobust_), b7(nominalReference_), b8(nominalPair_);
    nominalFrom_->setCurrentIndex(std::max(0, nominalFrom_->findData(QString::fromStdString(n.from))));
    updateNominalControls();
    nominalElement_->setCurrentIndex(
        std::max(0, nominalElement_->findData(QString::fromStdString(n.element))));
    nominalRadius_->setValue(n.radiusMm);
    nominalCriterion_->setCurrentIndex(n.criterion == "minimax" ? 1 : 0);
    nominalInner_->setChecked(n.inner);
    nominalRobust_->setChecked(n.robust);
    const int r = nominalReference_->findData(QString::fromStdString(n.reference));
    if (r >= 0) nominalReference_->setCurrentIndex(r);
    nominalPair_->setCurrentIndex(n.pair == "order" ? 1 : 0);
    const int c = nominalCad_->findData(QString::fromStdString(n.cad));
    if (c >= 0) nominalCad_->setCurrentIndex(c);
  }
  updateNominalControls();
  revalidate();
}

NominalSource ImportDialog::nominals() const {
  NominalSource n;
  n.from = nominalFrom_->currentData().toString().toStdString();
  if (n.from == "cad") {
    n.cad = nominalCad_->currentData().toString().toStdString();
    return n;
  }
  n.element = nominalElement_->currentData().toString().toStdString();
  const bool fitted = !n.element.empty();
  if (fitted && nominalRadius_->isEnabled()) n.radiusMm = nominalRadius_->value();
  if (fitted && nominalCriterion_->currentData().toString() == QLatin1String("minimax"))
    n.criterion = "minimax";
  n.inner = fitted && nominalInner_->isChecked();
  n.robust = fitted && nominalRobust_->isChecked();
  if (n.from == "reference") {
    n.reference = nominalReference_->currentData().toString().toStdString();
    n.pair = nominalPair_->currentData().toString().toStdString();
  }
  return n;
}

}  // namespace metrofit
