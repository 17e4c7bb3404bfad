// The PDF report (see report.h): read every dataset first, lay the report out once into memory to
// learn the page numbers, then draw it again into a QSaveFile that is committed only at the end.
#include "widgets/report/report.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>

#include <vector>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/matching/hole_table.h"
#include "core/project/datasets.h"
#include "core/project/nominals.h"
#include "core/project/project.h"
#include "core/study/study_check.h"
#include "metrofit/version.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

constexpr int kMinDpi = 72;
constexpr int kMaxDpi = 1200;

/// A section of the report: its title, whether the project has something for it, its body.
struct SectionEntry {
  QString (*title)();
  bool (*present)(const ReportContext&);
  void (*write)(ReportPainter&, const ReportContext&);
};

/// True when the project declares the study (studies.<name>, an object): sections report only the
/// studies the project declares, never every dataset of a kind.
bool declares(const ReportContext& c, const char* name) {
  const auto it = c.project->studies.find(name);
  return it != c.project->studies.end() && it->is_object();
}

/// Every section, in report order. Later studies add their line here.
const SectionEntry kSections[] = {
    {&setupSectionTitle,
     [](const ReportContext& c) {
       return declares(c, study::kSetup) && !c.ofKind(dataset_kind::kSetupModel).empty();
     },
     &writeSetupSection},
    {&thermalSectionTitle,
     [](const ReportContext& c) {
       return declares(c, study::kThermal) && !c.ofKind(dataset_kind::kThermalLog).empty();
     },
     &writeThermalSection},
    {&probePointsSectionTitle,
     [](const ReportContext& c) {
       return declares(c, study::kMatching) && !c.ofKind(dataset_kind::kProbePoints).empty();
     },
     &writeProbePointsSection},
    {&matchingSectionTitle, &hasMatchingStudy, &writeMatchingSection},
    {&kinematicSectionTitle,
     [](const ReportContext& c) {
       // A circular test, or a part series charted on its own (studies.kinematics.spc).
       return declares(c, study::kKinematics) && (!c.ofKind(dataset_kind::kCircularTest).empty() ||
                                                  c.project->studies.at(study::kKinematics).contains("spc"));
     },
     &writeKinematicSection},
    {&diagnosisSectionTitle, &hasDiagnosisStudy, &writeDiagnosisSection},
};

/// What one layout pass found out: page count, the first page of each section, and what the
/// sections concluded (for the summary on page 1 of the next pass).
struct Layout {
  int pages = 0;
  QList<int> sectionPages;
  std::vector<SectionFinding> findings;
};

/// Reads every dataset of the project; InputError (from core) when one cannot be read.
std::vector<ReportDataset> readDatasets(const Project& project, const QString& projectPath) {
  std::vector<ReportDataset> datasets;
  for (const DatasetRef& ref : project.datasets) {
    ReportDataset d;
    d.ref = ref;
    const std::string path = resolveDatasetPath(projectPath.toStdString(), ref);
    d.path = QString::fromStdString(path);
    d.paths = resolveDatasetPaths(projectPath.toStdString(), ref);
    if (datasetKindServes(dataset_kind::kThermalLog, ref.kind)) {
      d.thermal = readThermalLog(path, 3, ref.csv);
      d.rows = static_cast<long>(d.thermal->rows());
      d.columns.push_back(d.thermal->timeColumn);
      for (const ThermalChannel& c : d.thermal->channels) d.columns.push_back(c.name);
    } else if (ref.kind == dataset_kind::kProbePoints) {
      // With its nominals from an element or a reference measurement where it says so.
      d.probes = readProjectProbePoints(project, projectPath.toStdString(), ref, 3);
      d.rows = static_cast<long>(d.probes->points.size());
    } else if (ref.kind == dataset_kind::kSetupModel) {
      readFile(path);  // a JSON model: no rows, but it must be readable
    } else {
      // With the dataset's dialect and mapping (core/project/datasets.h).
      const DatasetSummary summary = summarizeDataset(projectPath.toStdString(), ref);
      d.rows = summary.rows;
      d.columns = summary.columns;
    }
    datasets.push_back(std::move(d));
  }
  return datasets;
}

/// Draws the whole report into `device`; `previous` (a first pass) supplies the page numbers.
Layout render(QIODevice& device, const ReportContext& context,
              const std::vector<const SectionEntry*>& sections, int dpi, const Layout* previous,
              const QString& pdfPath) {
  QPdfWriter writer(&device);
  writer.setPageSize(QPageSize(QPageSize::A4));
  writer.setPageOrientation(QPageLayout::Portrait);
  writer.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
  writer.setResolution(dpi);
  writer.setTitle(context.title);
  writer.setCreator(ReportText::tr("Metrofit %1").arg(QString::fromUtf8(kVersion)));

  QPainter painter;
  if (!painter.begin(&writer)) {
    throw FileError({pdfPath.toStdString(), 0, 0, {}}, "cannot start drawing the PDF report");
  }
  Layout layout;
  ReportPainter out(writer, painter, context.title, previous != nullptr ? previous->pages : 0);
  QStringList titles;
  for (const SectionEntry* section : sections) titles << section->title();
  titles << referencesTitle() << appendixTitle();
  writeSummary(out, context, titles, previous != nullptr ? previous->findings : std::vector<SectionFinding>{},
               previous != nullptr ? previous->sectionPages : QList<int>{});
  context.findings.clear();
  for (const SectionEntry* section : sections) {
    out.heading(section->title());
    layout.sectionPages << out.page();
    section->write(out, context);
  }
  if (!context.datasets.empty() || !sections.empty()) {
    out.heading(referencesTitle());
    layout.sectionPages << out.page();
    writeReferences(out, context);
    out.heading(appendixTitle());
    layout.sectionPages << out.page();
    writeAppendix(out, context);
  }
  layout.findings = context.findings;
  layout.pages = out.page();
  painter.end();
  return layout;
}

}  // namespace

std::vector<const ReportDataset*> ReportContext::ofKind(const char* kind) const {
  std::vector<const ReportDataset*> out;
  for (const ReportDataset& d : datasets) {
    if (datasetKindServes(kind, d.ref.kind)) {
      out.push_back(&d);
    }
  }
  return out;
}

ReportSummary writeReport(const Project& project, const QString& pdfPath, const ReportOptions& options) {
  if (options.resolutionDpi < kMinDpi || options.resolutionDpi > kMaxDpi) {
    throw OptionsError({"", 0, 0, "resolutionDpi"},
                       "the report resolution must lie in [" + std::to_string(kMinDpi) + ", " +
                           std::to_string(kMaxDpi) + "] dpi, not " + std::to_string(options.resolutionDpi));
  }
  // Every study setting is checked before anything is read or drawn: a bad one is an error naming
  // the study and the field, never a quiet default.
  const std::string source = options.projectPath.toStdString();
  validateStudies(project, source);
  ReportContext context;
  context.project = &project;
  context.title = options.title.isEmpty() ? reportProjectName(project) : options.title;
  context.date = QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
  context.datasets = readDatasets(project, options.projectPath);
  validateStudies(project, source, [&context](const std::string& id) -> const std::vector<std::string>* {
    for (const ReportDataset& d : context.datasets)
      if (d.ref.id == id && !d.columns.empty()) return &d.columns;
    return nullptr;
  });
  context.probeToleranceMm = kDefaultProbeToleranceMm;
  if (const auto m = project.studies.find(study::kMatching); m != project.studies.end() && m->is_object()) {
    if (const auto t = m->find("tolerance_mm"); t != m->end()) {
      if (!t->is_number() || !(t->get<double>() > 0.0)) {
        throw ValidationError({options.projectPath.toStdString(), 0, 0, "studies.matching.tolerance_mm"},
                              "must be a positive number (mm)");
      }
      context.probeToleranceMm = t->get<double>();
    }
  }

  std::vector<const SectionEntry*> sections;
  for (const SectionEntry& s : kSections) {
    if (s.present(context)) {
      sections.push_back(&s);
    }
  }

  // Two passes into memory: the first learns what the sections conclude (page 1 summarises it),
  // the second the page numbers of the report with that summary, for the contents and the footers.
  QBuffer scratch;
  scratch.open(QIODevice::WriteOnly);
  const Layout draft = render(scratch, context, sections, options.resolutionDpi, nullptr, pdfPath);
  QBuffer scratch2;
  scratch2.open(QIODevice::WriteOnly);
  const Layout first = render(scratch2, context, sections, options.resolutionDpi, &draft, pdfPath);

  QSaveFile file(pdfPath);
  if (!file.open(QIODevice::WriteOnly)) {
    throw FileError({pdfPath.toStdString(), 0, 0, {}},
                    "cannot write the report: " + file.errorString().toStdString());
  }
  const Layout laidOut = render(file, context, sections, options.resolutionDpi, &first, pdfPath);
  if (!file.commit()) {
    throw FileError({pdfPath.toStdString(), 0, 0, {}},
                    "cannot write the report: " + file.errorString().toStdString());
  }

  ReportSummary summary;
  summary.pages = laidOut.pages;
  for (const SectionEntry* s : sections) {
    summary.sections << s->title();
  }
  return summary;
}

QString reportProjectName(const Project& project) {
  const QString name = QString::fromStdString(project.name).trimmed();
  return name.isEmpty() || project.name == Project{}.name ? ReportText::tr("Untitled") : name;
}

}  // namespace metrofit
