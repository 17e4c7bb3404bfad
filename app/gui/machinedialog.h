#pragma once
// The machine of a project's matching study (studies.matching.machine, core/machine/machine.h): its
// topology (head-head XFYZBA, table-table AC / BC, head-table), the geometry that topology uses,
// the travel of the rotary and linear axes, and the control the frame is written for. Import and
// Export read and write the same JSON as `metrofit-cli match --machine-def` (docs/file-formats.md,
// "Machine definition"). The dialog edits a copy; the matching page writes it back as one undo step.
#include <array>

#include <QDialog>

#include "core/machine/controller_frame.h"
#include "core/machine/machine.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QDialogButtonBox;
class QGroupBox;

namespace metrofit {

class MachineDialog : public QDialog {
  Q_OBJECT
 public:
  MachineDialog(const machine::MachineDefinition& definition, machine::FrameFormat controller,
                QWidget* parent = nullptr);

  /// The definition the fields make (valid when isDefinitionValid()).
  machine::MachineDefinition definition() const;
  machine::FrameFormat controller() const;
  /// Shows a definition in the fields (topology included).
  void setDefinition(const machine::MachineDefinition& definition);
  /// False with the reason under the fields (and OK disabled) when the travel is inconsistent.
  bool isDefinitionValid() const;
  /// The line under the fields: why the definition is invalid, or why an import or export failed.
  QString problem() const;

  /// Reads a machine JSON (or a .metrofit project's studies.matching.machine) into the fields. Returns
  /// false and shows the one-line reason (file and field) when it cannot be used.
  bool importFile(const QString& path);
  /// Writes the fields' definition as machine JSON (atomically). False and the reason when it fails.
  bool exportFile(const QString& path);

  QComboBox* topologyCombo() const { return topology_; }
  QComboBox* controllerCombo() const { return controller_; }

 private:
  void topologyChanged();
  void resetToPreset();
  void validate();
  void importDialog();
  void exportDialog();
  QDoubleSpinBox* lengthSpin(double lo, double hi, const QString& name);

  QComboBox* topology_;
  QComboBox* controller_;
  QGroupBox* headHead_;
  QGroupBox* table_;
  QGroupBox* headTable_;
  QGroupBox* cAxis_;
  QDoubleSpinBox *lx_, *ly_, *lz_, *lab_, *pivot_;
  std::array<QDoubleSpinBox*, 3> tiltPoint_{}, rotaryPoint_{};
  std::array<QLabel*, 2> rotaryName_{};
  std::array<QDoubleSpinBox*, 2> rotaryMin_{}, rotaryMax_{};
  std::array<QCheckBox*, 3> linearLimited_{};
  std::array<QDoubleSpinBox*, 3> linearMin_{}, linearMax_{};
  QLabel* problem_;
  QDialogButtonBox* buttons_;
  QString problemText_;
};

}  // namespace metrofit
