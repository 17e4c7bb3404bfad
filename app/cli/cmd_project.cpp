// metrofit-cli project: own data in a project (docs/file-formats.md#own-data-in-a-project).
//   project new P.metrofit [--name TEXT]
//   project add P.metrofit KIND FILE [--id ID] [--map ROLE=COLUMN ...] [--delimiter D] [--decimal D]
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
  std::string file;
  std::string id;
  std::vector<std::string> map;
  std::string out;
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
  r.file = a.file;
  r.id = a.id;
  r.csv = csvOptions();
  for (const auto& m : a.map) r.csv.columnMap.push_back(parseColumnMapping(m));
  const DatasetRef ref = addDataset(p, a.project, r);
  saveProject(p, a.project);
  const DatasetSummary s = summarizeDataset(a.project, ref);
  std::fprintf(stderr, "project add: '%s' (%s, %ld rows) -> %s\n", ref.id.c_str(), ref.kind.c_str(), s.rows,
               ref.path.c_str());
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
  add->add_option("kind", a->kind,
                  "thermal-log|probe-points|circular-test|cmm-report|setup-model|"
                  "feature-series|dmis|hole-table")
      ->required()
      ->check(CLI::IsMember(datasetKindNames()));
  existingFile(add->add_option("file", a->file, "Data file (- for standard input, copied into the project)")
                   ->required());
  add->add_option("--id", a->id, "Dataset id (default: the file name without extension)");
  add->add_option("--map", a->map,
                  "ROLE=COLUMN: read the file's COLUMN as ROLE (e.g. time_min=Zeit); repeatable")
      ->take_all();
  addThermalLogOptions(add);
  add->callback([a] { selectRunner([a]() -> int { return runAdd(*a); }); });

  auto l = std::make_shared<ProjectArgs>();
  auto* ls = pr->add_subcommand("list", "The datasets as JSON: [{id, kind, path, rows, columns}]");
  existingFile(ls->add_option("project", l->project, "Project file (.metrofit)")->required());
  addOut(ls, l->out);
  ls->callback([l] { selectRunner([l]() -> int { return runList(*l); }); });
}

}  // namespace metrofit::cli
