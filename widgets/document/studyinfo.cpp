#include "widgets/document/studyinfo.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QSignalBlocker>

#include "core/project/project.h"

namespace metrofit {

QStringList studyKeys() {
  QStringList keys;
  for (const char* key : study::kAll) keys << QString::fromLatin1(key);
  return keys;
}

QString studyTitle(const QString& s) {
  if (s == QLatin1String(study::kSetup)) return QCoreApplication::translate("StudyInfo", "Setup correction");
  if (s == QLatin1String(study::kMatching))
    return QCoreApplication::translate("StudyInfo", "Posture matching");
  if (s == QLatin1String(study::kKinematics))
    return QCoreApplication::translate("StudyInfo", "Kinematics & SPC");
  if (s == QLatin1String(study::kThermal)) return QCoreApplication::translate("StudyInfo", "Thermal");
  if (s == QLatin1String(study::kDiagnosis)) return QCoreApplication::translate("StudyInfo", "Diagnosis");
  return s;
}

QString studySummary(const QString& s) {
  if (s == QLatin1String(study::kSetup)) {
    return QCoreApplication::translate(
        "StudyInfo",
        "Computes corrections of the work offsets and tool offsets from CMM reports through the relation "
        "graph of machine points, work coordinate systems, tools, features and dimensions. It maximises the "
        "smallest error budget over all dimensions with the certified exact optimum (LP, then MILP on the "
        "0.001 mm grid) and compares CRIPSO, PSO, GA and COA against it in convergence charts. Corrections "
        "export as the controller takes them.");
  }
  if (s == QLatin1String(study::kMatching)) {
    return QCoreApplication::translate(
        "StudyInfo",
        "Finds the actual posture of the workpiece from contact-probed points (nominal point, normal and "
        "measured point): rough matching from three reference points, fine matching by self-adaptive "
        "differential evolution, the closed-form least-squares optimum and a minimax tolerance-zone fit, "
        "then the adjustments of a 5-axis machine.");
  }
  if (s == QLatin1String(study::kKinematics)) {
    return QCoreApplication::translate(
        "StudyInfo",
        "Identifies the actuator origin offsets and orientation errors (squareness) of a Cartesian machine "
        "from a circular test or a measured path, computes compensated references for a nominal path, and "
        "charts measured features with X-bar/R control limits, Cp and Cpk.");
  }
  if (s == QLatin1String(study::kThermal)) {
    return QCoreApplication::translate(
        "StudyInfo",
        "Models the thermal displacement of the spindle from temperature sensors with the grey model "
        "GMC(1,N), the grey neural network GNNMCI(1,N) trained by PSO and an MLP, fitted on the first part "
        "of a log and tested on the rest; shows sensor trends and hysteresis.");
  }
  if (s == QLatin1String(study::kDiagnosis)) {
    return QCoreApplication::translate(
        "StudyInfo",
        "Closes the loop: fits each declared model, looks at the residual it leaves, traces it to an effect "
        "the model lacks (thermal lag, an undeclared input, drift, backlash, scale, cyclic error, tool wear, "
        "surface offset and more), adds the effect only on strong out-of-sample evidence and reports the "
        "error before and after.");
  }
  return {};
}

QStringList studyDatasetKinds(const QString& s) {
  if (s == QLatin1String(study::kSetup))
    return {dataset_kind::kSetupModel, dataset_kind::kCmmReport, dataset_kind::kDmis,
            dataset_kind::kDfq,        dataset_kind::kCalypso,   dataset_kind::kQif};
  if (s == QLatin1String(study::kMatching))
    return {dataset_kind::kProbePoints, dataset_kind::kHoleTable, dataset_kind::kCadModel};
  if (s == QLatin1String(study::kKinematics))
    return {dataset_kind::kCircularTest, dataset_kind::kFeatureSeries};
  if (s == QLatin1String(study::kThermal)) return {dataset_kind::kThermalLog, dataset_kind::kMtconnect};
  if (s == QLatin1String(study::kDiagnosis)) {
    return {dataset_kind::kThermalLog, dataset_kind::kCircularTest, dataset_kind::kSetupModel,
            dataset_kind::kCmmReport,  dataset_kind::kProbePoints,  dataset_kind::kDmis,
            dataset_kind::kHoleTable,  dataset_kind::kMtconnect};
  }
  return {};
}

QString datasetKindTitle(const QString& kind) {
  if (kind == QLatin1String(dataset_kind::kThermalLog))
    return QCoreApplication::translate("StudyInfo", "Thermal log");
  if (kind == QLatin1String(dataset_kind::kProbePoints)) {
    return QCoreApplication::translate("StudyInfo", "Probe points");
  }
  if (kind == QLatin1String(dataset_kind::kCircularTest)) {
    return QCoreApplication::translate("StudyInfo", "Circular test");
  }
  if (kind == QLatin1String(dataset_kind::kCmmReport))
    return QCoreApplication::translate("StudyInfo", "CMM report");
  if (kind == QLatin1String(dataset_kind::kSetupModel))
    return QCoreApplication::translate("StudyInfo", "Setup model");
  if (kind == QLatin1String(dataset_kind::kFeatureSeries))
    return QCoreApplication::translate("StudyInfo", "SPC feature series");
  if (kind == QLatin1String(dataset_kind::kDmis))
    return QCoreApplication::translate("StudyInfo", "DMIS output");
  if (kind == QLatin1String(dataset_kind::kHoleTable))
    return QCoreApplication::translate("StudyInfo", "Hole table");
  if (kind == QLatin1String(dataset_kind::kDfq))
    return QCoreApplication::translate("StudyInfo", "Q-DAS DFQ file");
  if (kind == QLatin1String(dataset_kind::kCalypso))
    return QCoreApplication::translate("StudyInfo", "Zeiss Calypso table");
  if (kind == QLatin1String(dataset_kind::kCadModel))
    return QCoreApplication::translate("StudyInfo", "CAD part (STL)");
  if (kind == QLatin1String(dataset_kind::kQif))
    return QCoreApplication::translate("StudyInfo", "QIF results");
  if (kind == QLatin1String(dataset_kind::kMtconnect))
    return QCoreApplication::translate("StudyInfo", "MTConnect log");
  return kind;
}

int fillDatasetCombo(QComboBox* combo, const std::vector<DatasetRef>& datasets, const QString& select) {
  const QSignalBlocker blocker(combo);
  combo->clear();
  for (const DatasetRef& d : datasets) {
    const QString id = QString::fromStdString(d.id);
    combo->addItem(id, id);
    combo->setItemData(combo->count() - 1, QString::fromStdString(d.description), Qt::ToolTipRole);
  }
  const int keep = combo->findData(select);
  combo->setCurrentIndex(keep >= 0 ? keep : 0);
  return combo->currentIndex();
}

}  // namespace metrofit
