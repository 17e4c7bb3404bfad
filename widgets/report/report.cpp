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
#include "core/project/project.h"
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

/// Every section, in report order. Later studies add their line here.
const SectionEntry kSections[] = {
    {&setupSectionTitle, [](const ReportContext& c) { return !c.ofKind(dataset_kind::kSetupModel).empty(); },
     &writeSetupSection},
    {&thermalSectionTitle,
     [](const ReportContext& c) { return !c.ofKind(dataset_kind::kThermalLog).empty(); },
     &writeThermalSection},
    {&probePointsSectionTitle,
     [](const ReportContext& c) { return !c.ofKind(dataset_kind::kProbePoints).empty(); },
     &writeProbePointsSection},
    {&matchingSectionTitle, &hasMatchingStudy, &writeMatchingSection},
    {&kinematicSectionTitle,
     [](const ReportContext& c) { return !c.ofKind(dataset_kind::kCircularTest).empty(); },
     &writeKinematicSection},
    {&diagnosisSectionTitle, &hasDiagnosisStudy, &writeDiagnosisSection},
};

/// What one layout pass found out: page count and the first page of each section.
struct Layout {
  int pages = 0;
  QList<int> sectionPages;
};

/// Reads every dataset of the project; InputError (from core) when one cannot be read.
std::vector<ReportDataset> readDatasets(const Project& project, const QString& projectPath) {
  std::vector<ReportDataset> datasets;
  for (const DatasetRef& ref : project.datasets) {
    ReportDataset d;
    d.ref = ref;
    const std::string path = resolveDatasetPath(projectPath.toStdString(), ref);
    d.path = QString::fromStdString(path);
    if (ref.kind == dataset_kind::kThermalLog) {
      d.thermal = readThermalLog(path, 3, ref.csv);
      d.rows = static_cast<long>(d.thermal->rows());
    } else if (ref.kind == dataset_kind::kProbePoints) {
      d.probes = readProbePointsAnyFormat(path, 3, ref.csv);
      d.rows = static_cast<long>(d.probes->points.size());
    } else if (ref.kind == dataset_kind::kSetupModel) {
      readFile(path);  // a JSON model: no rows, but it must be readable
    } else {
      d.rows =
          summarizeDataset(projectPath.toStdString(), ref).rows;  // with the dataset's dialect and mapping
    }
    datasets.push_back(std::move(d));
  }
  return datasets;
}

void writeCover(ReportPainter& out, const ReportContext& context,
                const std::vector<const SectionEntry*>& sections, const Layout* previous) {
  const Project& project = *context.project;
  out.title(ReportText::tr("Metrofit report"));
  out.paragraph(context.title, ReportPainter::Font::Heading);
  if (!project.description.empty()) {
    out.paragraph(QString::fromStdString(project.description));
  }
  out.skip(out.mm(2.0));

  ReportTable facts;
  facts.widths = {1.0, 3.0};
  facts.rows = {{ReportText::tr("project"), QString::fromStdString(project.name)},
                {ReportText::tr("date"), context.date},
                {ReportText::tr("Metrofit version"), QString::fromUtf8(kVersion)}};
  out.table(facts);

  out.subheading(ReportText::tr("Datasets"), out.mm(15.0));
  ReportTable datasets;
  datasets.header = {ReportText::tr("id"), ReportText::tr("kind"), ReportText::tr("file"),
                     ReportText::tr("rows / points"), ReportText::tr("licence")};
  datasets.widths = {1.2, 1.1, 2.0, 1.1, 2.0};
  datasets.alignment = {Qt::AlignLeft, Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight, Qt::AlignLeft};
  for (const ReportDataset& d : context.datasets) {
    datasets.rows.push_back(
        {QString::fromStdString(d.ref.id), QString::fromStdString(d.ref.kind),
         QString::fromStdString(d.ref.path), d.rows >= 0 ? QString::number(d.rows) : QStringLiteral("—"),
         d.ref.licence.empty() ? QStringLiteral("—") : QString::fromStdString(d.ref.licence)});
  }
  if (datasets.rows.isEmpty()) {
    out.paragraph(ReportText::tr("The project references no datasets."));
  } else {
    out.table(datasets);
  }

  out.subheading(ReportText::tr("Contents"), out.mm(15.0));
  if (sections.empty()) {
    out.paragraph(ReportText::tr("The project has no data a section of this report could show yet."));
    return;
  }
  ReportTable contents;
  contents.header = {ReportText::tr("section"), ReportText::tr("page")};
  contents.widths = {5.0, 1.0};
  contents.alignment = {Qt::AlignLeft, Qt::AlignRight};
  contents.widthFraction = 0.7;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const bool known = previous != nullptr && static_cast<qsizetype>(i) < previous->sectionPages.size();
    contents.rows.push_back(
        {sections[i]->title(),
         known ? QString::number(previous->sectionPages[static_cast<qsizetype>(i)]) : QStringLiteral("—")});
  }
  out.table(contents);
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
  writeCover(out, context, sections, previous);
  for (const SectionEntry* section : sections) {
    out.heading(section->title());
    layout.sectionPages << out.page();
    section->write(out, context);
  }
  layout.pages = out.page();
  painter.end();
  return layout;
}

}  // namespace

std::vector<const ReportDataset*> ReportContext::ofKind(const char* kind) const {
  std::vector<const ReportDataset*> out;
  for (const ReportDataset& d : datasets) {
    if (d.ref.kind == kind) {
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
  ReportContext context;
  context.project = &project;
  context.title = options.title.isEmpty() ? QString::fromStdString(project.name) : options.title;
  context.date = QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
  context.datasets = readDatasets(project, options.projectPath);
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

  // First pass into memory: page numbers for the contents and the footers.
  QBuffer scratch;
  scratch.open(QIODevice::WriteOnly);
  const Layout first = render(scratch, context, sections, options.resolutionDpi, nullptr, pdfPath);

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

}  // namespace metrofit
