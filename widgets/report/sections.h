#pragma once
// The sections of the PDF report, one function each, and what they share: the project's datasets,
// read once before the first page is drawn (so a dataset that cannot be read fails the report
// before anything is written). report.cpp lists the sections, decides which ones a project has and
// draws each section's heading on a new page; the write...Section function draws the body below it.
// A new section is a new write...Section function plus one line in that list.
#include <QList>
#include <QString>
#include <QStringList>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

#include "core/matching/matching.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
class ReportPainter;
namespace diagnose {
struct Diagnosis;
}

/// A dataset of the project as the report sees it.
struct ReportDataset {
  DatasetRef ref;
  QString path;                         ///< resolved against the project folder
  std::vector<std::string> paths;       ///< every file resolved (a DMIS series: one per workpiece)
  long rows = -1;                       ///< data rows or points; -1 when the kind has no rows (setup model)
  std::vector<std::string> columns;     ///< column names (CSV kinds), for the settings check
  std::optional<ThermalLog> thermal;    ///< for thermal_log datasets
  std::optional<ProbePointSet> probes;  ///< for probe_points datasets
};

/// What the sections compute once per report: the report is laid out twice (report.cpp: page
/// numbers first), so a section keeps a result it computed in the first pass here and finds it in
/// the second. Owned by the ReportContext of one writeReport: nothing outlives the report, and a
/// report is built by one thread.
class ReportMemo {
 public:
  /// The value kept under (T, key); the first time, `make()` (returning a std::shared_ptr<const T>)
  /// makes it. When make() throws nothing is kept (the next call tries again).
  template <class T, class Make>
  std::shared_ptr<const T> get(const std::string& key, Make&& make) {
    Key k{std::type_index(typeid(T)), key};
    if (const auto it = entries_.find(k); it != entries_.end())
      return std::static_pointer_cast<const T>(it->second);
    std::shared_ptr<const T> value = std::forward<Make>(make)();
    entries_.emplace(std::move(k), value);
    return value;
  }
  /// Values kept.
  std::size_t size() const { return entries_.size(); }

 private:
  using Key = std::pair<std::type_index, std::string>;
  std::map<Key, std::shared_ptr<const void>> entries_;
};

/// What a section concludes: drawn at the end of the section (concludeSection) and gathered on page 1.
struct SectionFinding {
  QString study;  ///< the section's title
  /// What the study found, one or two sentences.
  QString found;
  /// What to change on the machine: {what (register, axis, model), value with its unit, where it goes
  /// (controller file or page)}; empty when nothing is to be changed.
  QList<QStringList> changes;
  QString before;       ///< the error before, with its unit (empty when the study has none)
  QString after;        ///< the error after the change
  QString unexplained;  ///< what is still unexplained (the closed loop), empty elsewhere
  QString conclusion;
  QString recommendation;
};

/// Tolerance (mm) of the probe-point section when the project's matching study sets none.
inline constexpr double kDefaultProbeToleranceMm = matching::kDefaultToleranceMm;

/// Everything a section may draw from.
struct ReportContext {
  const Project* project = nullptr;
  QString title;  ///< report title (the project name unless the options say otherwise)
  QString date;   ///< when the report was made, as printed
  std::vector<ReportDataset> datasets;
  /// Symmetric tolerance (mm) the probe-point section counts deviations against: the matching
  /// study's "tolerance_mm" when the project sets one, else kDefaultProbeToleranceMm.
  double probeToleranceMm = kDefaultProbeToleranceMm;
  /// Results kept between the two layout passes (see ReportMemo).
  mutable ReportMemo memo;
  /// What the sections concluded in this layout pass, in report order (concludeSection adds).
  mutable std::vector<SectionFinding> findings;

  /// The datasets of one kind (dataset_kind::...), in project order.
  std::vector<const ReportDataset*> ofKind(const char* kind) const;
};

/// A text made by core (evidence, notes, the SPC decision) in the reader's symbols: ± for "+-", → for
/// "->", µm for "um", ° for "deg" after a number, and small numbers to three significant digits
/// (0.00123535 → 0.00124).
QString readerText(const std::string& text);

/// Ends a section: a "Conclusion" block with the finding's conclusion and recommendation, and keeps
/// the finding for the summary on page 1 (summarysection.cpp).
void concludeSection(ReportPainter& out, const ReportContext& context, SectionFinding finding);

/// The seeds the report cites, as the references list prints them: "[1]" ... (summarysection.cpp).
/// `seed` is the number of the paper in the seed folder (0, 1, 2, 4).
QString citation(int seed);

/// Page 1: what was measured, what each study found, what to change on the machine, the error
/// before and after, what is still unexplained, and the contents. `findings` and `sectionPages`
/// come from the previous layout pass (empty in the first).
void writeSummary(ReportPainter& out, const ReportContext& context, const QStringList& sectionTitles,
                  const std::vector<SectionFinding>& findings, const QList<int>& sectionPages);
/// The project's name; core's default "Untitled" (a project nobody named) in the report's language.
QString reportProjectName(const Project& project);
QString referencesTitle();
/// "References": the papers cited as [n].
void writeReferences(ReportPainter& out, const ReportContext& context);
QString appendixTitle();
/// "Appendix: data provenance": every dataset with its file, size, date, licence and description,
/// and the settings of every study.
void writeAppendix(ReportPainter& out, const ReportContext& context);

QString setupSectionTitle();
/// "Setup-data correction": the model, the report data, exact / CRIPSO / PSO (fixed seeds) with the
/// convergence chart, comparison, corrections, margins and the Fanuc export (setupsection.cpp).
void writeSetupSection(ReportPainter& out, const ReportContext& context);

QString thermalSectionTitle();
/// "Thermal": per thermal log, the trend chart (vector) and a table of its channels.
void writeThermalSection(ReportPainter& out, const ReportContext& context);

QString probePointsSectionTitle();
/// "Posture matching — probe points": per probe set, XY and XZ projections coloured by deviation,
/// the deviation statistics before matching and a table per surface.
void writeProbePointsSection(ReportPainter& out, const ReportContext& context);

QString kinematicSectionTitle();
/// "Kinematic compensation and SPC": per circular test the identified errors, path and polar plot,
/// the compensation result; the SPC charts and indices of the kinematics study's feature series.
void writeKinematicSection(ReportPainter& out, const ReportContext& context);

QString matchingSectionTitle();
/// True when the project has probe points and a matching study (studies.matching, not empty).
bool hasMatchingStudy(const ReportContext& context);
/// "Posture matching — before and after" (matchingsection.cpp): the before / after views, the
/// deviation table, the methods table, the machine adjustment values and the remeasure loop.
void writeMatchingSection(ReportPainter& out, const ReportContext& context);

QString diagnosisSectionTitle();
/// True when the project's studies.diagnosis configures at least one domain.
bool hasDiagnosisStudy(const ReportContext& context);
/// "Closed loop: diagnosis" (diagnosissection.cpp): per configured domain the loop step by step, the
/// residual plots of the accepted effects and the errors before / after.
void writeDiagnosisSection(ReportPainter& out, const ReportContext& context);
/// The part of the diagnosis section that says what is left unexplained: the residual check's
/// verdict, structure with shares, generic effects and outliers in reader's words, and the final
/// residual against the variable of the strongest structure with the generic fit. Nothing when the
/// diagnosis has no residual check.
void writeResidualCheck(ReportPainter& out, const diagnose::Diagnosis& diagnosis);

}  // namespace metrofit
