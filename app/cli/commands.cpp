#include "app/cli/commands.h"

#include <CLI/CLI.hpp>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/matching/probe_points.h"
#include "core/project/project.h"
#include "core/sim/probe_sim.h"
#include "core/sim/thermal_sim.h"
#include "core/thermal/thermal_log.h"
#include "widgets/document/demoproject.h"
#include "widgets/report/report.h"

namespace metrofit::cli {
namespace {

std::function<int()> g_selected;
int g_argc = 0;
char** g_argv = nullptr;

/// Qt is needed only for the PDF report (QPdfWriter, Qt Charts). Headless by default.
std::unique_ptr<QApplication> makeQtApp() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    // Qt warns on stderr without one; the CLI keeps stderr to its one-line summary.
    const QString runtime = QDir::temp().filePath(QStringLiteral("metrofit-runtime-%1").arg(::getuid()));
    if (QDir().mkpath(runtime)) {
      QFile::setPermissions(runtime, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
      qputenv("XDG_RUNTIME_DIR", runtime.toLocal8Bit());
    }
  }
  static int argc = 1;
  static char name[] = "metrofit-cli";
  static char* argv[] = {name, nullptr};
  return std::make_unique<QApplication>(argc, argv);
}

void summary(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

[[noreturn]] void notInThisBuild(const std::string& what, const std::string& issue) {
  throw NotAvailable(what + " is not in this build yet (" + issue + "); the inputs were read and are valid");
}

// ---- demo / report -------------------------------------------------------------------------

struct DemoArgs {
  std::string outDir = "metrofit-demo";
};

int runDemo(const DemoArgs& a) {
  auto app = makeQtApp();
  const QString dir = QDir(QString::fromStdString(a.outDir)).absolutePath();
  const QString projectPath = extractDemoProject(dir);
  const Project project = loadProject(projectPath.toStdString());
  const QString pdf = QDir(dir).filePath(QStringLiteral("metrofit-demo-report.pdf"));
  ReportOptions options;
  options.projectPath = projectPath;
  const ReportSummary s = writeReport(project, pdf, options);
  summary("demo: project '" + project.name + "' in " + dir.toStdString() + ", report with " + std::to_string(s.pages) +
          " pages (" + s.sections.join(QStringLiteral(", ")).toStdString() + ")");
  std::printf("%s\n", pdf.toStdString().c_str());
  return 0;
}

struct ReportArgs {
  std::string project;
  std::string out;
};

int runReport(const ReportArgs& a) {
  const Project project = loadProject(a.project);
  auto app = makeQtApp();
  ReportOptions options;
  options.projectPath = QString::fromStdString(a.project);
  const ReportSummary s = writeReport(project, QString::fromStdString(a.out), options);
  summary("report: " + a.out + ", " + std::to_string(s.pages) + " pages");
  return 0;
}

// ---- simulate -------------------------------------------------------------------------------

struct SimArgs {
  std::string out;
  std::uint64_t seed = 1;
};

int runSimulateThermal(const SimArgs& a) {
  ThermalSimOptions o;
  o.seed = a.seed;
  const ThermalLog log = simulateThermalTest(o);
  writeResult(a.out, thermalLogToCsv(log));
  summary("simulate thermal: " + std::to_string(log.rows()) + " rows, seed " + std::to_string(a.seed));
  return 0;
}

int runSimulateProbe(const SimArgs& a) {
  ProbeSimOptions o;
  o.seed = a.seed;
  const ProbePointSet set = simulateProbing(o);
  writeResult(a.out, probePointsToCsv(set));
  summary("simulate probe: " + std::to_string(set.points.size()) + " points, seed " + std::to_string(a.seed));
  return 0;
}

// ---- the method subcommands (their methods land with their issues) ------------------------

struct MethodArgs {
  std::string model, data, method, machine, errors, path, target, inputs, out;
  long budget = 5000;
  std::uint64_t seed = 1;
  double tolerance = 0.05, trainFraction = 0.5;
  bool allowScale = false;
};

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

/// Reads a thermal log and checks that --target and --inputs name numeric columns of it.
ThermalLog readThermalArgs(const MethodArgs& a) {
  ThermalLog log = readThermalLog(a.data);
  (void)log.channel(a.target);
  const auto inputs = splitList(a.inputs);
  if (inputs.empty()) throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "needs at least one column name");
  for (const auto& in : inputs) {
    if (in == a.target) throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "'" + in + "' is also the --target");
    (void)log.channel(in);
  }
  return log;
}

void addOut(CLI::App* sub, std::string& out) {
  sub->add_option("--out", out, "Result file (JSON; written atomically). Default: stdout");
}

void addSeed(CLI::App* sub, std::uint64_t& seed) {
  sub->add_option("--seed", seed, "Seed of the stochastic methods (same seed, same result)")->capture_default_str();
}

CLI::Option* existingFile(CLI::Option* o) { return o->check(CLI::ExistingFile); }

}  // namespace

void writeResult(const std::string& outPath, const std::string& text) {
  if (outPath.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return;
  }
  writeFileAtomic(outPath, text);
}

void registerCommands(CLI::App& app, int argc, char** argv) {
  g_argc = argc;
  g_argv = argv;

  {
    auto a = std::make_shared<DemoArgs>();
    auto* sub = app.add_subcommand("demo", "Run the main job on the bundled sample project and write the PDF report");
    sub->add_option("--out-dir", a->outDir, "Folder for the demo project, its data and the report")->capture_default_str();
    sub->callback([a] { g_selected = [a]() -> int { return runDemo(*a); }; });
  }
  {
    auto a = std::make_shared<ReportArgs>();
    auto* sub = app.add_subcommand("report", "Write the PDF report of a saved project");
    existingFile(sub->add_option("--project", a->project, "Project file (.metrofit)")->required());
    sub->add_option("--out", a->out, "PDF file to write")->required();
    sub->callback([a] { g_selected = [a]() -> int { return runReport(*a); }; });
  }
  {
    auto* sim = app.add_subcommand("simulate", "Make test data with the built-in simulator");
    sim->require_subcommand(1);
    auto a = std::make_shared<SimArgs>();
    auto* th = sim->add_subcommand("thermal", "A spindle heating/cooling test: time_min, rpm, T1..T4, T_amb, disp_z_um");
    addOut(th, a->out);
    addSeed(th, a->seed);
    th->callback([a] { g_selected = [a]() -> int { return runSimulateThermal(*a); }; });
    auto* pr = sim->add_subcommand("probe", "Contact-probed points of a block with a posture error");
    addOut(pr, a->out);
    addSeed(pr, a->seed);
    pr->callback([a] { g_selected = [a]() -> int { return runSimulateProbe(*a); }; });
  }
  {
    auto a = std::make_shared<MethodArgs>();
    auto* sub = app.add_subcommand("setup", "Setup-data correction (work and tool offsets) from CMM reports");
    existingFile(sub->add_option("--model", a->model, "Setup model (relation graph, JSON)")->required());
    existingFile(sub->add_option("--data", a->data, "CMM report series (CSV)")->required());
    sub->add_option("--method", a->method, "exact|cripso|pso|ga|coa")
        ->check(CLI::IsMember({"exact", "cripso", "pso", "ga", "coa"}))
        ->default_val("exact");
    sub->add_option("--budget", a->budget, "Evaluation budget of a metaheuristic")->check(CLI::PositiveNumber);
    addSeed(sub, a->seed);
    addOut(sub, a->out);
    sub->callback([a] {
      g_selected = [a]() -> int {
        (void)readJsonFile(a->model);
        (void)readCsvFile(a->data);
        notInThisBuild("setup-data correction", "issue 4");
      };
    });
  }
  {
    auto a = std::make_shared<MethodArgs>();
    auto* sub = app.add_subcommand("match", "Workpiece posture matching and 5-axis machine adjustment");
    existingFile(sub->add_option("--data", a->data, "Probe points (CSV)")->required());
    sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")->check(CLI::PositiveNumber);
    sub->add_option("--method", a->method, "sade|ga-simplex|closed-form|minimax")
        ->check(CLI::IsMember({"sade", "ga-simplex", "closed-form", "minimax"}))
        ->default_val("sade");
    sub->add_flag("--allow-scale", a->allowScale, "Fit an isotropic scale too");
    sub->add_option("--machine", a->machine, "Machine topology, e.g. xfyzba")->default_val("xfyzba");
    addSeed(sub, a->seed);
    addOut(sub, a->out);
    sub->callback([a] {
      g_selected = [a]() -> int {
        (void)readProbePoints(a->data);
        notInThisBuild("posture matching", "issue 5");
      };
    });
  }
  {
    auto* kin = app.add_subcommand("kinematic", "Kinematic error identification and compensation");
    kin->require_subcommand(1);
    auto a = std::make_shared<MethodArgs>();
    auto* id = kin->add_subcommand("identify", "Identify actuator errors from a measured path or circular test");
    existingFile(id->add_option("--data", a->data, "Measured path (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)")->required());
    addOut(id, a->out);
    id->callback([a] {
      g_selected = [a]() -> int {
        const CsvTable t = readCsvFile(a->data);
        for (const char* c : {"x_cmd_mm", "y_cmd_mm", "x_meas_mm", "y_meas_mm"}) (void)t.numericColumn(c);
        notInThisBuild("kinematic identification", "issue 6");
      };
    });
    auto b = std::make_shared<MethodArgs>();
    auto* comp = kin->add_subcommand("compensate", "Compensated references for a nominal path");
    existingFile(comp->add_option("--errors", b->errors, "Errors (JSON written by identify)")->required());
    existingFile(comp->add_option("--path", b->path, "Nominal path (CSV x_mm,y_mm)")->required());
    addOut(comp, b->out);
    comp->callback([b] {
      g_selected = [b]() -> int {
        (void)readJsonFile(b->errors);
        const CsvTable t = readCsvFile(b->path);
        for (const char* c : {"x_mm", "y_mm"}) (void)t.numericColumn(c);
        notInThisBuild("kinematic compensation", "issue 6");
      };
    });
  }
  {
    auto* th = app.add_subcommand("thermal", "Thermal error modelling");
    th->require_subcommand(1);
    auto a = std::make_shared<MethodArgs>();
    auto* fit = th->add_subcommand("fit", "Fit a thermal error model on the first part of a log, test on the rest");
    existingFile(fit->add_option("--data", a->data, "Thermal log (CSV)")->required());
    fit->add_option("--target", a->target, "Column to model (e.g. disp_z_um)")->required();
    fit->add_option("--inputs", a->inputs, "Comma-separated input columns")->required();
    fit->add_option("--model", a->method, "gnnmci|gmc|mlp")->check(CLI::IsMember({"gnnmci", "gmc", "mlp"}))->default_val("gnnmci");
    fit->add_option("--train-fraction", a->trainFraction, "Fraction of rows used for fitting")
        ->check(CLI::Range(0.05, 0.95))
        ->capture_default_str();
    addSeed(fit, a->seed);
    addOut(fit, a->out);
    fit->callback([a] {
      g_selected = [a]() -> int {
        (void)readThermalArgs(*a);
        notInThisBuild("thermal model fitting", "issue 7");
      };
    });
  }
  {
    auto* dg = app.add_subcommand("diagnose", "Closed loop: residual -> missing effect -> error before and after");
    dg->require_subcommand(1);
    for (const char* domain : {"thermal", "kinematic", "setup", "matching"}) {
      auto a = std::make_shared<MethodArgs>();
      auto* sub = dg->add_subcommand(domain, std::string("Diagnose the ") + domain + " model");
      existingFile(sub->add_option("--data", a->data, "Measured data")->required());
      if (std::string(domain) == "setup") existingFile(sub->add_option("--model", a->model, "Setup model (JSON)")->required());
      if (std::string(domain) == "thermal") {
        sub->add_option("--target", a->target, "Column to model")->required();
        sub->add_option("--inputs", a->inputs, "Declared input columns")->required();
        sub->add_option("--train-fraction", a->trainFraction, "Fraction of rows fitted; the rest is held out")
            ->check(CLI::Range(0.05, 0.95))
            ->capture_default_str();
      }
      if (std::string(domain) == "matching") {
        sub->add_option("--tolerance", a->tolerance, "Symmetric tolerance, mm")->check(CLI::PositiveNumber);
      }
      addSeed(sub, a->seed);
      addOut(sub, a->out);
      const std::string d = domain;
      sub->callback([a, d] {
        g_selected = [a, d]() -> int {
          if (d == "thermal") (void)readThermalArgs(*a);
          else if (d == "matching") (void)readProbePoints(a->data);
          else (void)readCsvFile(a->data);
          if (!a->model.empty()) (void)readJsonFile(a->model);
          notInThisBuild("the " + d + " diagnosis", "issue 8");
        };
      });
    }
  }
}

int runSelected() {
  if (!g_selected) throw ValidationError(ErrorContext{}, "no subcommand given (see metrofit-cli --help)");
  return g_selected();
}

}  // namespace metrofit::cli
