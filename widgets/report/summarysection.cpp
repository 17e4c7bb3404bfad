// The parts of the report around the study sections (see sections.h): page 1, the summary a
// manager reads in a minute (what was measured, what each study found, what to change on the
// machine, the error before and after, what the closed loop leaves unexplained, the contents); the
// conclusion that ends every section; the references; and the appendix with the data provenance
// and the study settings.
#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QRegularExpression>

#include <functional>
#include <map>
#include <set>
#include <string>

#include "metrofit/version.h"
#include "widgets/report/reportpainter.h"
#include "widgets/report/sections.h"

namespace metrofit {
namespace {

struct ReportText {
  Q_DECLARE_TR_FUNCTIONS(metrofit::Report)
};

/// The papers behind the four methods, in the order of the references list.
struct Reference {
  int seed;
  const char* text;
};
constexpr Reference kReferences[] = {
    {0,
     "R. Stryczek: A metaheuristic for fast machining error compensation. Journal of Intelligent "
     "Manufacturing 27(6), 1209–1220, 2016."},
    {1,
     "L. Jiang, Y. Li, Y. Zou, K. Tang, Y. Fu, S. Ma: Posture adjustment of workpiece based on stepwise "
     "matching by self-adaptive differential evolution algorithm. Mechanical Sciences 9, 267–280, 2018."},
    {2,
     "Kinematic compensation algorithm for reducing errors in a closed-loop manufacturing system. IEEE "
     "Access (authors and year are not given in the copy at hand)."},
    {4,
     "A. M. Abdulshahed, A. P. Longstaff, S. Fletcher, A. Potdar: Thermal error modelling of a "
     "gantry-type 5-axis machine tool using a Grey Neural Network Model. Journal of Manufacturing "
     "Systems 41, 130–142, 2016."},
};

/// A dataset kind in the reader's words.
QString kindName(const std::string& kind) {
  if (kind == dataset_kind::kThermalLog) return ReportText::tr("thermal log");
  if (kind == dataset_kind::kProbePoints) return ReportText::tr("probed points");
  if (kind == dataset_kind::kCircularTest) return ReportText::tr("circular test");
  if (kind == dataset_kind::kCmmReport) return ReportText::tr("CMM report");
  if (kind == dataset_kind::kSetupModel) return ReportText::tr("setup model");
  if (kind == dataset_kind::kFeatureSeries) return ReportText::tr("feature series");
  if (kind == dataset_kind::kDmis) return ReportText::tr("DMIS output");
  if (kind == dataset_kind::kDfq) return ReportText::tr("Q-DAS DFQ file");
  if (kind == dataset_kind::kCalypso) return ReportText::tr("Zeiss Calypso table");
  if (kind == dataset_kind::kQif) return ReportText::tr("QIF results");
  if (kind == dataset_kind::kMtconnect) return ReportText::tr("MTConnect log");
  if (kind == dataset_kind::kCadModel) return ReportText::tr("CAD part");
  if (kind == dataset_kind::kHoleTable) return ReportText::tr("hole table");
  return QString::fromStdString(kind);
}

QString fileDate(const ReportDataset& d) {
  const QFileInfo info(d.path);
  return info.exists() ? info.lastModified().toString(QStringLiteral("yyyy-MM-dd")) : QStringLiteral("—");
}

QString rowsText(const ReportDataset& d) {
  return d.rows >= 0 ? QString::number(d.rows) : QStringLiteral("—");
}

QString licenceText(const ReportDataset& d) {
  return d.ref.licence.empty() ? ReportText::tr("none given") : QString::fromStdString(d.ref.licence);
}

/// The ids of the datasets the project's studies name (any "dataset", "model" or "spc.dataset" key).
std::set<std::string> usedDatasetIds(const Project& project) {
  std::set<std::string> ids;
  const std::function<void(const nlohmann::json&)> walk = [&](const nlohmann::json& j) {
    if (!j.is_object()) return;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if ((it.key() == "dataset" || it.key() == "model") && it->is_string())
        ids.insert(it->get<std::string>());
      walk(*it);
    }
  };
  walk(project.studies);
  return ids;
}

}  // namespace

QString readerText(const std::string& text) {
  QString s = QString::fromStdString(text);
  s.replace(QStringLiteral("+-"), QStringLiteral("±")).replace(QStringLiteral("->"), QStringLiteral("→"));
  s.replace(QRegularExpression(QStringLiteral("(\\d) um\\b")), QStringLiteral("\\1 µm"));
  s.replace(QRegularExpression(QStringLiteral("(\\d) deg\\b")), QStringLiteral("\\1°"));
  static const QRegularExpression small(QStringLiteral("(?<![\\d.])0\\.0*[1-9]\\d{3,}"));
  QString out;
  qsizetype last = 0;
  for (auto it = small.globalMatch(s); it.hasNext();) {
    const QRegularExpressionMatch m = it.next();
    out += s.mid(last, m.capturedStart() - last) + QString::number(m.captured().toDouble(), 'g', 3);
    last = m.capturedEnd();
  }
  return out + s.mid(last);
}

QString citation(int seed) {
  int n = 1;
  for (const Reference& r : kReferences) {
    if (r.seed == seed) return QStringLiteral("[%1]").arg(n);
    ++n;
  }
  return {};
}

void concludeSection(ReportPainter& out, const ReportContext& context, SectionFinding finding) {
  out.subheading(ReportText::tr("Conclusion"), out.mm(20.0));
  if (!finding.conclusion.isEmpty()) out.paragraph(finding.conclusion);
  if (!finding.recommendation.isEmpty())
    out.paragraph(ReportText::tr("Recommendation: %1").arg(finding.recommendation),
                  ReportPainter::Font::Bold);
  context.findings.push_back(std::move(finding));
}

void writeSummary(ReportPainter& out, const ReportContext& context, const QStringList& sectionTitles,
                  const std::vector<SectionFinding>& findings, const QList<int>& sectionPages) {
  const Project& project = *context.project;
  out.title(ReportText::tr("Metrofit report"));
  out.paragraph(context.title, ReportPainter::Font::Heading);
  out.paragraph(
      ReportText::tr("Project “%1”, report made %2 by Metrofit version %3. The project's description "
                     "and every dataset's origin are in the appendix.")
          .arg(reportProjectName(project), context.date, QString::fromUtf8(kVersion)),
      ReportPainter::Font::Small);

  const QString dash = QStringLiteral("—");
  // Studies with something to change (the methods) first; the closed loop's domains in their own table.
  std::vector<const SectionFinding*> studies, loop;
  for (const SectionFinding& f : findings) (f.unexplained.isEmpty() ? studies : loop).push_back(&f);
  if (!studies.empty()) {
    out.subheading(ReportText::tr("What each study found"), out.mm(20.0));
    ReportTable t;
    t.header = {ReportText::tr("study"), ReportText::tr("found"), ReportText::tr("recommendation")};
    t.widths = {1.0, 3.2, 2.5};
    for (const SectionFinding* f : studies)
      t.rows.push_back({f->study, f->found.isEmpty() ? f->conclusion : f->found,
                        f->recommendation.isEmpty() ? dash : f->recommendation});
    out.table(t);
  }

  ReportTable changes;
  changes.header = {ReportText::tr("study"), ReportText::tr("change"), ReportText::tr("value"),
                    ReportText::tr("where")};
  changes.widths = {1.0, 1.2, 2.2, 2.3};
  for (const SectionFinding& f : findings) {
    bool first = true;
    for (const QStringList& c : f.changes) {
      QStringList row{first ? f.study : QString()};
      row << c;
      changes.rows.push_back(row);
      first = false;
    }
  }
  if (!findings.empty()) {
    out.subheading(ReportText::tr("What to change on the machine"), out.mm(20.0));
    if (changes.rows.isEmpty())
      out.paragraph(ReportText::tr("Nothing: no study proposes a change."));
    else
      out.table(changes);
  }

  ReportTable errors;
  errors.header = {ReportText::tr("study"), ReportText::tr("error before"), ReportText::tr("error after")};
  errors.widths = {1.0, 2.85, 2.85};
  for (const SectionFinding* f : studies)
    if (!f->before.isEmpty() || !f->after.isEmpty())
      errors.rows.push_back(
          {f->study, f->before.isEmpty() ? dash : f->before, f->after.isEmpty() ? dash : f->after});
  if (!errors.rows.isEmpty()) {
    out.subheading(ReportText::tr("Error before and after"), out.mm(20.0));
    out.table(errors);
  }

  if (!loop.empty()) {
    out.subheading(ReportText::tr("What the closed loop found and leaves unexplained"), out.mm(20.0));
    ReportTable open;
    open.header = {ReportText::tr("study"), ReportText::tr("found"), ReportText::tr("error before → after"),
                   ReportText::tr("still unexplained")};
    open.widths = {1.0, 2.1, 2.0, 1.6};
    for (const SectionFinding* f : loop)
      open.rows.push_back({f->study, f->found, f->after.isEmpty() ? f->before : f->after, f->unexplained});
    out.table(open);
  }

  // What was measured, in one paragraph: the datasets the studies use, their dates and licences.
  out.subheading(ReportText::tr("What was measured"), out.mm(15.0));
  const std::set<std::string> used = usedDatasetIds(project);
  QStringList items;
  std::map<QString, QStringList> byDate, byLicence;
  int unused = 0;
  for (const ReportDataset& d : context.datasets) {
    if (!used.empty() && used.count(d.ref.id) == 0) {
      ++unused;
      continue;
    }
    items << (d.rows >= 0
                  ? ReportText::tr("%1 (%2, %3 rows)")
                        .arg(QString::fromStdString(d.ref.id), kindName(d.ref.kind))
                        .arg(d.rows)
                  : ReportText::tr("%1 (%2)").arg(QString::fromStdString(d.ref.id), kindName(d.ref.kind)));
    byDate[fileDate(d)] << QString::fromStdString(d.ref.id);
    byLicence[licenceText(d)] << QString::fromStdString(d.ref.id);
  }
  if (context.datasets.empty()) {
    out.paragraph(ReportText::tr("The project references no datasets."));
  } else {
    const auto grouped = [&](const std::map<QString, QStringList>& m) {
      if (m.size() == 1) return m.begin()->first;
      QStringList parts;
      for (const auto& [key, ids] : m)
        parts << ReportText::tr("%1 (%2)").arg(key, ids.join(QStringLiteral(", ")));
      return parts.join(QStringLiteral("; "));
    };
    QString text = ReportText::tr("%1. Files dated %2. Licences: %3.")
                       .arg(items.join(QStringLiteral(", ")), grouped(byDate), grouped(byLicence));
    if (unused > 0)
      text += QLatin1Char(' ') +
              ReportText::tr("%n further dataset(s) of the project are used by no study.", nullptr, unused);
    out.paragraph(text, ReportPainter::Font::Small);
  }

  if (sectionTitles.isEmpty()) {
    out.paragraph(ReportText::tr("The project declares no study a section of this report could show yet."));
    return;
  }
  QStringList contents;
  for (qsizetype i = 0; i < sectionTitles.size(); ++i)
    contents << (i < sectionPages.size()
                     ? ReportText::tr("%1, page %2").arg(sectionTitles[i]).arg(sectionPages[i])
                     : sectionTitles[i]);
  out.paragraph(ReportText::tr("Contents: %1.").arg(contents.join(QStringLiteral("; "))),
                ReportPainter::Font::Small);
}

QString referencesTitle() {
  return ReportText::tr("References");
}

void writeReferences(ReportPainter& out, const ReportContext&) {
  ReportTable t;
  t.widths = {0.4, 6.0};
  int n = 1;
  for (const Reference& r : kReferences)
    t.rows.push_back({QStringLiteral("[%1]").arg(n++), QString::fromUtf8(r.text)});
  out.table(t);
}

QString appendixTitle() {
  return ReportText::tr("Appendix: data provenance");
}

void writeAppendix(ReportPainter& out, const ReportContext& context) {
  if (!context.project->description.empty()) {
    out.subheading(ReportText::tr("Project"), out.mm(18.0));
    out.paragraph(QString::fromStdString(context.project->description));
  }
  out.paragraph(
      ReportText::tr("Every dataset of the project, where it comes from and under which licence; "
                     "file names are relative to the project's folder."));
  for (const ReportDataset& d : context.datasets) {
    out.subheading(QString::fromStdString(d.ref.id), out.mm(18.0));
    ReportTable t;
    t.widths = {1.0, 4.0};
    t.rows = {{ReportText::tr("kind"), kindName(d.ref.kind)},
              {ReportText::tr("file"), QString::fromStdString(d.ref.path)},
              {ReportText::tr("rows / points"), rowsText(d)},
              {ReportText::tr("file date"), fileDate(d)},
              {ReportText::tr("licence"), licenceText(d)}};
    if (!d.ref.description.empty())
      t.rows.push_back({ReportText::tr("description"), QString::fromStdString(d.ref.description)});
    out.table(t);
  }
  if (context.project->studies.is_object() && !context.project->studies.empty()) {
    out.subheading(ReportText::tr("Study settings"), out.mm(18.0));
    ReportTable t;
    t.header = {ReportText::tr("study"), ReportText::tr("settings as the project file holds them")};
    t.widths = {1.0, 4.0};
    // The effects applied from the diagnosis are reported where a study uses them, not here.
    const std::function<void(nlohmann::json&)> dropApplied = [&](nlohmann::json& j) {
      if (!j.is_object()) return;
      j.erase("applied");
      for (auto& v : j) dropApplied(v);
    };
    for (auto it = context.project->studies.begin(); it != context.project->studies.end(); ++it) {
      nlohmann::json settings = *it;
      dropApplied(settings);
      t.rows.push_back({QString::fromStdString(it.key()), QString::fromStdString(settings.dump())});
    }
    out.table(t);
  }
}

}  // namespace metrofit
