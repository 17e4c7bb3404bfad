#include "app/gui/machinedialog.h"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <nlohmann/json.hpp>

#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/project/project.h"

namespace metrofit {
namespace {

using machine::MachineDefinition;
using machine::Topology;

constexpr Topology kTopologies[] = {Topology::Xfyzba, Topology::AcTable, Topology::BcTable,
                                    Topology::HeadTable};
constexpr machine::FrameFormat kControls[] = {machine::FrameFormat::Heidenhain, machine::FrameFormat::Siemens,
                                              machine::FrameFormat::Fanuc};
constexpr double kLinearRange = 1e5;  // mm: any machine's travel

QString topologyText(Topology t) {
  switch (t) {
    case Topology::Xfyzba:
      return MachineDialog::tr("Head-head XFYZBA (A and B on the head; the paper's machine)");
    case Topology::AcTable:
      return MachineDialog::tr("Table-table AC (A trunnion carrying a C table)");
    case Topology::BcTable:
      return MachineDialog::tr("Table-table BC (B trunnion carrying a C table)");
    case Topology::HeadTable:
      return MachineDialog::tr("Head-table (B swivel head, C rotary table)");
  }
  return {};
}

QString controlText(machine::FrameFormat f) {
  switch (f) {
    case machine::FrameFormat::Heidenhain:
      return QStringLiteral("HEIDENHAIN");
    case machine::FrameFormat::Siemens:
      return QStringLiteral("SINUMERIK");
    case machine::FrameFormat::Fanuc:
      return QStringLiteral("FANUC");
  }
  return {};
}

}  // namespace

QDoubleSpinBox* MachineDialog::lengthSpin(double lo, double hi, const QString& name) {
  auto* s = new QDoubleSpinBox(this);
  s->setRange(lo, hi);
  s->setDecimals(4);
  s->setObjectName(name);
  s->setKeyboardTracking(false);
  s->setAccelerated(true);
  connect(s, &QDoubleSpinBox::valueChanged, this, &MachineDialog::validate);
  return s;
}

MachineDialog::MachineDialog(const MachineDefinition& definition, machine::FrameFormat controller,
                             QWidget* parent)
    : QDialog(parent),
      topology_(new QComboBox(this)),
      controller_(new QComboBox(this)),
      headHead_(new QGroupBox(tr("Head-head geometry (Eq. 12–13)"), this)),
      table_(new QGroupBox(tr("Tilt axis (table-table)"), this)),
      headTable_(new QGroupBox(tr("Swivel head (head-table)"), this)),
      cAxis_(new QGroupBox(tr("C axis of the rotary table"), this)),
      problem_(new QLabel(this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
  setWindowTitle(tr("Machine"));
  setObjectName(QStringLiteral("machineDialog"));
  for (Topology t : kTopologies) topology_->addItem(topologyText(t), static_cast<int>(t));
  topology_->setObjectName(QStringLiteral("machineTopology"));
  topology_->setToolTip(tr("The kinematics the adjustment values are computed for"));
  for (machine::FrameFormat f : kControls) controller_->addItem(controlText(f), static_cast<int>(f));
  controller_->setObjectName(QStringLiteral("machineController"));
  controller_->setToolTip(tr("The control the controller frame is written for"));

  auto* top = new QFormLayout;
  top->addRow(tr("&Topology:"), topology_);
  top->addRow(tr("&Control:"), controller_);

  const QString mm = tr(" mm");
  lx_ = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLX"));
  ly_ = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLY"));
  lz_ = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLZ"));
  lab_ = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLAB"));
  pivot_ = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machinePivot"));
  for (QDoubleSpinBox* s : {lx_, ly_, lz_, lab_, pivot_}) s->setSuffix(mm);
  {
    auto* f = new QFormLayout(headHead_);
    f->addRow(tr("LX (cutter location in the A frame):"), lx_);
    f->addRow(tr("LY:"), ly_);
    f->addRow(tr("LZ:"), lz_);
    f->addRow(tr("LAB (A origin in the B frame):"), lab_);
  }
  auto pointRow = [&](std::array<QDoubleSpinBox*, 3>& spins, const QString& prefix) {
    auto* row = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
      spins[static_cast<std::size_t>(i)] =
          lengthSpin(-kLinearRange, kLinearRange, prefix + QLatin1Char("xyz"[i]));
      spins[static_cast<std::size_t>(i)]->setSuffix(mm);
      row->addWidget(new QLabel(QString(QLatin1Char("XYZ"[i])), this));
      row->addWidget(spins[static_cast<std::size_t>(i)], 1);
    }
    return row;
  };
  {
    auto* f = new QVBoxLayout(table_);
    f->addWidget(
        new QLabel(tr("A point on the tilt axis at the zero position (workpiece coordinates):"), this));
    f->addLayout(pointRow(tiltPoint_, QStringLiteral("machineTiltPoint")));
  }
  {
    auto* f = new QVBoxLayout(cAxis_);
    f->addWidget(new QLabel(tr("A point on the C axis at the zero position (workpiece coordinates):"), this));
    f->addLayout(pointRow(rotaryPoint_, QStringLiteral("machineRotaryPoint")));
  }
  {
    auto* f = new QFormLayout(headTable_);
    f->addRow(tr("Pivot length (B axis above the tool point):"), pivot_);
  }

  auto* travel = new QGroupBox(tr("Travel"), this);
  auto* grid = new QGridLayout(travel);
  grid->addWidget(new QLabel(tr("Axis"), this), 0, 0);
  grid->addWidget(new QLabel(tr("Limited"), this), 0, 1);
  grid->addWidget(new QLabel(tr("Minimum"), this), 0, 2);
  grid->addWidget(new QLabel(tr("Maximum"), this), 0, 3);
  for (std::size_t i = 0; i < 2; ++i) {
    const int row = static_cast<int>(i) + 1;
    rotaryName_[i] = new QLabel(this);
    rotaryMin_[i] = lengthSpin(-100000.0, 100000.0, QStringLiteral("machineRotaryMin%1").arg(i));
    rotaryMax_[i] = lengthSpin(-100000.0, 100000.0, QStringLiteral("machineRotaryMax%1").arg(i));
    for (QDoubleSpinBox* s : {rotaryMin_[i], rotaryMax_[i]}) {
      s->setSuffix(QStringLiteral(" °"));
      s->setDecimals(3);
    }
    auto* always = new QLabel(tr("always"), this);
    always->setEnabled(false);
    grid->addWidget(rotaryName_[i], row, 0);
    grid->addWidget(always, row, 1);
    grid->addWidget(rotaryMin_[i], row, 2);
    grid->addWidget(rotaryMax_[i], row, 3);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const int row = static_cast<int>(i) + 3;
    const QChar axis = QLatin1Char("XYZ"[i]);
    linearLimited_[i] = new QCheckBox(this);
    linearLimited_[i]->setObjectName(QStringLiteral("machineLinearLimited%1").arg(axis));
    linearLimited_[i]->setToolTip(tr("Check the adjustment value S%1 against a travel").arg(axis));
    linearMin_[i] = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLinearMin%1").arg(axis));
    linearMax_[i] = lengthSpin(-kLinearRange, kLinearRange, QStringLiteral("machineLinearMax%1").arg(axis));
    linearMin_[i]->setSuffix(mm);
    linearMax_[i]->setSuffix(mm);
    connect(linearLimited_[i], &QCheckBox::toggled, this, [this, i](bool on) {
      linearMin_[i]->setEnabled(on);
      linearMax_[i]->setEnabled(on);
      validate();
    });
    grid->addWidget(new QLabel(QStringLiteral("S") + axis, this), row, 0);
    grid->addWidget(linearLimited_[i], row, 1);
    grid->addWidget(linearMin_[i], row, 2);
    grid->addWidget(linearMax_[i], row, 3);
  }
  grid->setColumnStretch(2, 1);
  grid->setColumnStretch(3, 1);

  problem_->setObjectName(QStringLiteral("machineProblem"));
  problem_->setWordWrap(true);
  problem_->setStyleSheet(QStringLiteral("color: #b00020;"));

  auto* preset = buttons_->addButton(tr("&Preset"), QDialogButtonBox::ResetRole);
  preset->setToolTip(tr("The topology's default geometry and travel"));
  auto* importButton = buttons_->addButton(tr("&Import…"), QDialogButtonBox::ActionRole);
  importButton->setToolTip(
      tr("Read a machine JSON (as metrofit-cli match --machine-def reads) or a project"));
  auto* exportButton = buttons_->addButton(tr("E&xport…"), QDialogButtonBox::ActionRole);
  exportButton->setToolTip(tr("Write the machine JSON for metrofit-cli match --machine-def"));
  connect(preset, &QPushButton::clicked, this, &MachineDialog::resetToPreset);
  connect(importButton, &QPushButton::clicked, this, &MachineDialog::importDialog);
  connect(exportButton, &QPushButton::clicked, this, &MachineDialog::exportDialog);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(topology_, &QComboBox::currentIndexChanged, this, &MachineDialog::topologyChanged);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(headHead_);
  layout->addWidget(table_);
  layout->addWidget(headTable_);
  layout->addWidget(cAxis_);
  layout->addWidget(travel);
  layout->addWidget(problem_);
  layout->addStretch(1);
  layout->addWidget(buttons_);

  controller_->setCurrentIndex(std::max(0, controller_->findData(static_cast<int>(controller))));
  setDefinition(definition);
}

void MachineDialog::setDefinition(const MachineDefinition& d) {
  {
    const QSignalBlocker b(topology_);
    topology_->setCurrentIndex(std::max(0, topology_->findData(static_cast<int>(d.topology))));
  }
  lx_->setValue(d.lx);
  ly_->setValue(d.ly);
  lz_->setValue(d.lz);
  lab_->setValue(d.lab);
  pivot_->setValue(d.pivot);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    tiltPoint_[k]->setValue(d.tiltAxisPoint(i));
    rotaryPoint_[k]->setValue(d.rotaryAxisPoint(i));
    const bool limited = std::isfinite(d.linearMinMm[k]) || std::isfinite(d.linearMaxMm[k]);
    // An open end shows the spin's extreme (kLinearRange: beyond any machine).
    linearMin_[k]->setValue(std::isfinite(d.linearMinMm[k]) ? d.linearMinMm[k] : -kLinearRange);
    linearMax_[k]->setValue(std::isfinite(d.linearMaxMm[k]) ? d.linearMaxMm[k] : kLinearRange);
    linearLimited_[k]->setChecked(limited);
    linearMin_[k]->setEnabled(limited);
    linearMax_[k]->setEnabled(limited);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    rotaryMin_[i]->setValue(d.rotaryMinDeg[i]);
    rotaryMax_[i]->setValue(d.rotaryMaxDeg[i]);
  }
  topologyChanged();
}

MachineDefinition MachineDialog::definition() const {
  MachineDefinition d;
  d.topology = static_cast<Topology>(topology_->currentData().toInt());
  d.lx = lx_->value();
  d.ly = ly_->value();
  d.lz = lz_->value();
  d.lab = lab_->value();
  d.pivot = pivot_->value();
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    d.tiltAxisPoint(i) = tiltPoint_[k]->value();
    d.rotaryAxisPoint(i) = rotaryPoint_[k]->value();
    const bool limited = linearLimited_[k]->isChecked();
    const double lo = linearMin_[k]->value(), hi = linearMax_[k]->value();
    d.linearMinMm[k] = limited && lo > -kLinearRange ? lo : -MachineDefinition::kUnlimited;
    d.linearMaxMm[k] = limited && hi < kLinearRange ? hi : MachineDefinition::kUnlimited;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    d.rotaryMinDeg[i] = rotaryMin_[i]->value();
    d.rotaryMaxDeg[i] = rotaryMax_[i]->value();
  }
  return d;
}

machine::FrameFormat MachineDialog::controller() const {
  return static_cast<machine::FrameFormat>(controller_->currentData().toInt());
}

bool MachineDialog::isDefinitionValid() const {
  return problemText_.isEmpty();
}

QString MachineDialog::problem() const {
  return problem_->text();
}

void MachineDialog::topologyChanged() {
  const auto t = static_cast<Topology>(topology_->currentData().toInt());
  headHead_->setVisible(t == Topology::Xfyzba);
  table_->setVisible(t == Topology::AcTable || t == Topology::BcTable);
  headTable_->setVisible(t == Topology::HeadTable);
  cAxis_->setVisible(t != Topology::Xfyzba);
  table_->setTitle(t == Topology::BcTable ? tr("B tilt axis (parallel to Y)")
                                          : tr("A tilt axis (parallel to X)"));
  const auto names = machine::rotaryAxisNames(t);
  for (std::size_t i = 0; i < 2; ++i) rotaryName_[i]->setText(QLatin1Char('S') + QLatin1String(names[i]));
  validate();
}

void MachineDialog::resetToPreset() {
  setDefinition(MachineDefinition::preset(static_cast<Topology>(topology_->currentData().toInt())));
}

void MachineDialog::validate() {
  problemText_.clear();
  const MachineDefinition d = definition();
  for (std::size_t i = 0; i < 2 && problemText_.isEmpty(); ++i) {
    if (d.rotaryMinDeg[i] > d.rotaryMaxDeg[i])
      problemText_ = tr("Travel of %1: the minimum %2° is above the maximum %3°.")
                         .arg(rotaryName_[i]->text(), QLocale().toString(d.rotaryMinDeg[i]),
                              QLocale().toString(d.rotaryMaxDeg[i]));
  }
  for (std::size_t i = 0; i < 3 && problemText_.isEmpty(); ++i) {
    if (linearLimited_[i]->isChecked() && linearMin_[i]->value() > linearMax_[i]->value())
      problemText_ =
          tr("Travel of S%1: the minimum %2 mm is above the maximum %3 mm.")
              .arg(QLatin1Char("XYZ"[i]))
              .arg(QLocale().toString(linearMin_[i]->value()), QLocale().toString(linearMax_[i]->value()));
  }
  if (problemText_.isEmpty()) {
    std::string why;
    if (!d.isValid(&why)) problemText_ = QString::fromStdString(why);
  }
  problem_->setText(problemText_);
  problem_->setVisible(!problemText_.isEmpty());
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(problemText_.isEmpty());
}

bool MachineDialog::importFile(const QString& path) {
  try {
    const std::string file = path.toStdString();
    const nlohmann::json j = readJsonFile(file);
    MachineDefinition d;
    if (j.is_object() && j.contains("format") && j["format"] == "metrofit-project") {
      Project p;
      if (j.contains("studies")) p.studies = j["studies"];
      if (!matchingMachine(p, &d, file)) {
        problem_->setText(
            tr("%1 has no machine (studies.matching.machine).").arg(QFileInfo(path).fileName()));
        problem_->setVisible(true);
        return false;
      }
    } else {
      d = MachineDefinition::fromJson(j, file);
    }
    setDefinition(d);
    return true;
  } catch (const std::exception& e) {
    problem_->setText(QString::fromUtf8(e.what()));  // the fields keep the last good definition
    problem_->setVisible(true);
    return false;
  }
}

bool MachineDialog::exportFile(const QString& path) {
  try {
    writeFileAtomic(path.toStdString(), definition().toJson().dump(2) + "\n");
    return true;
  } catch (const std::exception& e) {
    problem_->setText(QString::fromUtf8(e.what()));
    problem_->setVisible(true);
    return false;
  }
}

void MachineDialog::importDialog() {
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Import a machine"), QString(), tr("Machine or project (*.json *.metrofit);;All files (*)"));
  if (!path.isEmpty()) importFile(path);
}

void MachineDialog::exportDialog() {
  if (!isDefinitionValid()) return;
  QString path = QFileDialog::getSaveFileName(this, tr("Export the machine"), QStringLiteral("machine.json"),
                                              tr("Machine JSON (*.json)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
  exportFile(path);
}

}  // namespace metrofit
