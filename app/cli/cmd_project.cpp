// metrofit-cli project: own data in a project (docs/file-formats.md#own-data-in-a-project).
//   project new P.metrofit [--name TEXT]
//   project add P.metrofit KIND|auto FILE [--id ID] [--map ROLE=COLUMN ...] [--no-guess] [--delimiter D]
//               [--decimal D] [--header-lines N] [--comment PREFIX] [--skip-bad-rows] [--ta-meaning M]
//               [--ta-sign S] [--embed] [FILE2 ...: a DMIS series, one file per workpiece]
//               [--nominal-element E [--nominal-radius R] [--nominal-criterion ls|minimax]
//                [--nominal-robust] [--inner]] [--nominal-reference ID [--pair id|order]] [--nominal-cad ID]
//               [--part N: a QIF file of several measured parts added as probe points]
//   project list P.metrofit [--out FILE]
// The logic is core/project/datasets.h; this file only parses the command line.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/io/json_util.h"
#include "core/project/datasets.h"
#include "core/project/project.h"

namespace metrofit::cli {
namespace {

struct ProjectArgs {
  std::string project;
  std::string name;
  std::string kind;
  std::vector<std::string> files;
  std::string id;
  std::vector<std::string> map;
  std::string out;
  int headerLines = -1;
  std::string comment;
  bool skipBadRows = false;
  bool embed = false;
  bool noGuess = false;
  int part = 0;
  NominalSource nominals;
  std::string nominalElement, nominalReference, nominalCad;
};

int runNew(const ProjectArgs& a) {
  if (std::filesystem::exists(a.project))
    throw ValidationError(ErrorContext{a.project, 0, 0, {}}, "already exists; 'project add' adds data to it");
  Project p;
  if (!a.name.empty()) p.name = a.name;
  saveProject(p, a.project);
  std::fprintf(stderr, "project new: %s ('%s')\n", a.project.c_str(), p.name.c_str());
  return 0;
}

int runAdd(const ProjectArgs& a) {
  Project p = loadProject(a.project);
  AddDatasetRequest r;
  r.kind = a.kind;
  r.file = a.files.front();
  r.moreFiles.assign(a.files.begin() + 1, a.files.end());
  r.part = a.part;
  // Nominals for measured points (core/project/nominals.h): a reference measurement, or an element.
  r.nominals = a.nominals;
  if (!a.nominalCad.empty()) {
    r.nominals.from = "cad";
    r.nominals.cad = a.nominalCad;
    if (!a.nominalElement.empty() || !a.nominalReference.empty())
      throw OptionsError(
          ErrorContext{{}, 0, 0, "--nominal-cad"},
          "the CAD part is the nominal: --nominal-element and --nominal-reference do not apply");
  } else if (!a.nominalReference.empty()) {
    r.nominals.from = "reference";
    r.nominals.reference = a.nominalReference;
    r.nominals.element = a.nominalElement;
  } else if (!a.nominalElement.empty()) {
    r.nominals.from = "element";
    r.nominals.element = a.nominalElement;
  } else if (!(a.nominals == NominalSource{})) {
    throw OptionsError(
        ErrorContext{{}, 0, 0, "--nominal-element"},
        "is needed with --nominal-radius, --nominal-criterion, --nominal-robust, --inner or --pair "
        "(or --nominal-reference)");
  }
  r.id = a.id;
  r.csv = csvOptions();
  for (const auto& m : a.map) r.csv.columnMap.push_back(parseColumnMapping(m));
  r.csv.headerLines = a.headerLines;
  if (!a.comment.empty() &&
      (a.comment.size() > 16 || a.comment.find_first_of("\r\n\"") != std::string::npos ||
       a.comment.front() == ' ' || a.comment.front() == '\t'))
    throw OptionsError(
        ErrorContext{{}, 0, 0, "--comment"},
        "must be 1 to 16 characters, not starting with a blank, without quotes or line breaks");
  r.csv.commentPrefix = a.comment;
  r.csv.skipBadRows = a.skipBadRows;
  r.dmis = dmisOptions();
  r.embed = a.embed;
  r.guessRoles = !a.noGuess;
  const DatasetRef ref = addDataset(p, a.project, r);
  if (a.kind == kGuessKind)
    std::fprintf(stderr, "project add: '%s' read as %s\n", r.file.c_str(), ref.kind.c_str());
  if (r.guessRoles && r.csv.columnMap.empty())
    for (const auto& [role, column] : ref.csv.columnMap)
      std::fprintf(
          stderr,
          "project add: column '%s' read as %s (guessed; --map to choose, --no-guess to keep names)\n",
          column.c_str(), role.c_str());
  saveProject(p, a.project);
  const DatasetSummary s = summarizeDataset(a.project, ref);
  std::string skipped;
  if (ref.csv.skipBadRows) {
    skipped = ", " + std::to_string(s.skipped.size()) + " unreadable rows skipped";
    for (const CsvRowProblem& row : s.skipped)
      std::fprintf(stderr, "  skipped %s\n", describeRowProblem(row).c_str());
  }
  std::fprintf(stderr, "project add: '%s' (%s, %ld rows%s) -> %s\n", ref.id.c_str(), ref.kind.c_str(), s.rows,
               skipped.c_str(), ref.path.c_str());
  return 0;
}

int runList(const ProjectArgs& a) {
  const Project p = loadProject(a.project);
  const nlohmann::json list = datasetListJson(p, a.project);
  writeResult(a.out, dumpJson(list));
  std::fprintf(stderr, "project list: %zu datasets in %s\n", list.size(), a.project.c_str());
  return 0;
}

}  // namespace

void registerProjectCommands(CLI::App& app) {
  auto* pr = app.add_subcommand("project", "Own data in a project: create one, add datasets, list them");
  pr->require_subcommand(1);

  auto n = std::make_shared<ProjectArgs>();
  auto* nw = pr->add_subcommand("new", "Create an empty project");
  nw->add_option("project", n->project, "Project file to create (.metrofit)")->required();
  nw->add_option("--name", n->name, "Project name");
  nw->callback([n] { selectRunner([n]() -> int { return runNew(*n); }); });

  auto a = std::make_shared<ProjectArgs>();
  auto* add = pr->add_subcommand("add", "Add a dataset (a file referenced relative to the project)");
  existingFile(add->add_option("project", a->project, "Project file (.metrofit)")->required());
  std::vector<std::string> kinds = datasetKindNames();
  kinds.push_back(kGuessKind);
  add->add_option(
         "kind", a->kind,
         "thermal-log|probe-points|circular-test|cmm-report|setup-model|"
         "feature-series|dmis|hole-table|dfq|calypso|cad-model|qif|mtconnect, or auto: the kind the file's "
         "name and content say")
      ->required()
      ->check(CLI::IsMember(kinds));
  existingFile(
      add->add_option("file", a->files,
                      "Data file (- for standard input, copied into the project); several DMIS output "
                      "files (one per workpiece) make one DMIS series")
          ->required()
          ->expected(1, -1));
  add->add_option("--id", a->id, "Dataset id (default: the file name without extension)");
  add->add_option("--map", a->map,
                  "ROLE=COLUMN: read the file's COLUMN as ROLE (e.g. time_min=Zeit); repeatable")
      ->take_all();
  addThermalLogOptions(add);
  add->add_option(
         "--header-lines", a->headerLines,
         "CSV: the first N lines are a preamble, skipped whatever they hold; the column names follow "
         "(default: detect, skipping blank and comment lines)")
      ->check(CLI::Range(0, 10000));
  add->add_option("--comment", a->comment, "CSV: what starts a comment line before the header (default #)");
  add->add_flag("--skip-bad-rows", a->skipBadRows,
                "CSV: leave out rows that cannot be read (stored in the project, counted when read); "
                "default: the first such row is an error");
  addDmisOptions(add);
  add->add_flag("--no-guess", a->noGuess,
                "CSV without --map: keep the file's column names (default: read the columns whose names say "
                "a role as that role, e.g. 'Zeit [min]' as time_min, 'Soll X [µm]' as qx in mm)");
  add->add_flag("--embed", a->embed,
                "Copy the file into the project's folder as data/<id>.<ext> (never overwriting) instead of "
                "referencing it");
  add->add_option(
      "--nominal-element", a->nominalElement,
      "Probe points of measured points only: the nominals are their feet on this element fitted to "
      "them (plane|line|circle|sphere|cylinder|cone); with --nominal-reference the element whose "
      "normals the reference points take");
  add->add_option("--nominal-radius", a->nominals.radiusMm,
                  "The element's fixed radius in mm (sphere, circle, "
                  "cylinder)");
  add->add_option("--nominal-criterion", a->nominals.criterion,
                  "How the element is fitted: ls | minimax [ls]")
      ->check(CLI::IsMember({"ls", "minimax"}));
  add->add_flag("--nominal-robust", a->nominals.robust, "Leave stray points out of the element's fit");
  add->add_flag("--inner", a->nominals.inner,
                "The element is a bore or hole (the material is outside it): normals point inwards");
  add->add_option("--nominal-reference", a->nominalReference,
                  "Probe points of measured points only: the nominals are the same points of a second "
                  "measurement, the probe-point dataset ID of the project");
  add->add_option(
      "--nominal-cad", a->nominalCad,
      "Probe points of measured points only: the nominals are their closest points on this CAD part "
      "(the cad-model dataset ID of the project); the matching re-projects them at each posture");
  add->add_option("--part", a->part,
                  "A QIF file of several measured parts added as probe points: the part, by its number "
                  "(1 = the first MeasurementResults)")
      ->check(CLI::Range(1, 1000000));
  add->add_option("--pair", a->nominals.pair, "How points meet their reference points: id | order [id]")
      ->check(CLI::IsMember({"id", "order"}));
  add->callback([a] { selectRunner([a]() -> int { return runAdd(*a); }); });

  auto l = std::make_shared<ProjectArgs>();
  auto* ls = pr->add_subcommand("list", "The datasets as JSON: [{id, kind, path, rows, columns}]");
  existingFile(ls->add_option("project", l->project, "Project file (.metrofit)")->required());
  addOut(ls, l->out);
  ls->callback([l] { selectRunner([l]() -> int { return runList(*l); }); });
}

}  // namespace metrofit::cli
