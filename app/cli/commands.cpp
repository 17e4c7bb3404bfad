#include "app/cli/commands.h"

#include <unistd.h>
#include <CLI/CLI.hpp>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <clocale>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>

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

TerminalProgress::TerminalProgress(std::function<std::string(const IterationSummary&)> line)
    : tty_(::isatty(::fileno(stderr)) == 1),
      line_(std::move(line)),
      observer_([this](const IterationSummary& s) {
        if (tty_ && line_)
          if (const std::string l = line_(s); !l.empty()) show(l);
        return ObserverDecision::Continue;
      }) {}

TerminalProgress::~TerminalProgress() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
}

void TerminalProgress::show(const std::string& line) {
  if (!tty_) return;
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  std::fprintf(stderr, "\r%s\033[K", line.c_str());
  std::fflush(stderr);
  shown_ = true;
}
namespace {

std::function<int()> g_selected;
std::string g_delimiter = "auto";
std::string g_taMeaning = "auto";
std::string g_taSign = "plain";
std::string g_decimal = "auto";
std::string g_sampleInterval;  ///< --sample-interval as given ("15s"), empty when not given
int g_argc = 0;
char** g_argv = nullptr;

/// Qt is needed only for the PDF report (QPdfWriter, Qt Charts). Headless by default.
std::unique_ptr<QApplication> makeQtApp() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    // Qt warns on stderr without one; the CLI keeps stderr to its one-line summary.
    const QString runtime = QDir::temp().filePath(QStringLiteral("metrofit-runtime-%1").arg(::getuid()));
    if (QDir().mkpath(runtime)) {
      QFile::setPermissions(runtime,
                            QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
      qputenv("XDG_RUNTIME_DIR", runtime.toLocal8Bit());
    }
  }
  static int argc = 1;
  static char name[] = "metrofit-cli";
  static char* argv[] = {name, nullptr};
  auto app = std::make_unique<QApplication>(argc, argv);
  // QApplication set the C locale from the environment; numbers stay '.'-decimal (issue 27).
  std::setlocale(LC_NUMERIC, "C");
  // The CLI and the report it writes (also for the GUI's Export report) are in English: numbers Qt
  // formats (chart legends, axis labels) follow the same C conventions whatever LANG says, so an
  // English sentence never shows a German decimal comma ("exact optimum f1 = 0,0797 mm").
  QLocale::setDefault(QLocale::c());
  return app;
}

void summary(const std::string& line) {
  std::fprintf(stderr, "%s\n", line.c_str());
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
  summary("demo: project '" + project.name + "' in " + dir.toStdString() + ", report with " +
          std::to_string(s.pages) + " pages (" + s.sections.join(QStringLiteral(", ")).toStdString() + ")");
  std::printf("%s\n", pdf.toStdString().c_str());
  return 0;
}

struct ReportArgs {
  std::string project;
  std::string out;
  std::string lang = "en";
};

/// The report's sentences in LANGUAGE ("en" needs nothing). Its numbers keep the decimal point in
/// every language, as the NC blocks and CMM protocols it quotes do.
void useReportLanguage(QApplication& app, const std::string& language) {
  if (language == "en") return;
  const QString code = QString::fromStdString(language);
  auto* qt = new QTranslator(&app);
  if (qt->load(QStringLiteral("qtbase_") + code, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
    QCoreApplication::installTranslator(qt);
  else
    delete qt;
  auto* own = new QTranslator(&app);
  if (!own->load(QStringLiteral(":/i18n/metrofit_") + code)) {
    delete own;
    throw ValidationError(ErrorContext{{}, 0, 0, "--lang"},
                          "no translation for '" + language + "' is built in");
  }
  QCoreApplication::installTranslator(own);
}

int runReport(const ReportArgs& a) {
  const Project project = loadProject(a.project);
  auto app = makeQtApp();
  useReportLanguage(*app, a.lang);
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
  std::string shape = "block";  ///< simulate probe: block | s-piece
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
  ProbeSimOptions o = parseProbeShape(a.shape, "--shape") == ProbeShape::SPiece
                          ? ProbeSimOptions::sPieceDefaults()
                          : ProbeSimOptions();
  o.seed = a.seed;
  const ProbePointSet set = simulateProbing(o);
  writeResult(a.out, probePointsToCsv(set));
  summary("simulate probe: " + a.shape + ", " + std::to_string(set.points.size()) + " points, seed " +
          std::to_string(a.seed));
  return 0;
}

}  // namespace

void writeResult(const std::string& outPath, const std::string& text) {
  if (outPath.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    return;
  }
  writeFileAtomic(outPath, text);
}

void selectRunner(std::function<int()> runner) {
  g_selected = std::move(runner);
}

CLI::Option* existingFile(CLI::Option* option) {
  return option->check(CLI::Validator(
      [](std::string& text) -> std::string { return text == "-" ? std::string() : CLI::ExistingFile(text); },
      "FILE (or - for standard input)"));
}

void addCsvOptions(CLI::App* sub) {
  sub->add_option(
         "--delimiter", g_delimiter,
         "CSV field delimiter: auto (the most frequent of ',', ';', tab in the header), ',', ';' or tab")
      ->check(CLI::IsMember({"auto", ",", ";", "tab"}))
      ->capture_default_str();
  sub->add_option(
         "--decimal", g_decimal,
         "CSV decimal separator: auto (',' when a ';'- or tab-separated file writes decimal commas), "
         "'.' or ','")
      ->check(CLI::IsMember({"auto", ".", ","}))
      ->capture_default_str();
}

void addSampleIntervalOption(CLI::App* sub) {
  sub->add_option("--sample-interval", g_sampleInterval,
                  "Thermal log without a time column: the rows are this far apart, a number with its unit "
                  "s, min or h (e.g. 15s, 1min); the first row is at time 0. An MTConnect log: the grid it "
                  "is resampled to (zero-order hold; default 1s)");
}

void addThermalLogOptions(CLI::App* sub) {
  addCsvOptions(sub);
  addSampleIntervalOption(sub);
}

void addDmisOptions(CLI::App* sub) {
  sub->add_option(
         "--ta-meaning", g_taMeaning,
         "DMIS output without F/FA: TA(label) is the deviation, the actual value, or auto (nearer the "
         "nominal than zero: the actual value)")
      ->check(CLI::IsMember({"auto", "deviation", "actual"}))
      ->capture_default_str();
  sub->add_option("--ta-sign", g_taSign,
                  "DMIS output: plain (TA = actual - nominal) or nominal (the writer reports sign(nominal) * "
                  "(actual - nominal))")
      ->check(CLI::IsMember({"plain", "nominal"}))
      ->capture_default_str();
}

setup::DmisOptions dmisOptions() {
  setup::DmisOptions o;
  o.taMeaning = setup::parseDmisTaMeaning(g_taMeaning, "--ta-meaning");
  o.signFollowsNominal = g_taSign == "nominal";
  return o;
}

CsvReadOptions csvOptions() {
  CsvReadOptions o;
  o.dialect.delimiter = parseCsvDelimiter(g_delimiter);
  o.dialect.decimal = parseCsvDecimal(g_decimal);
  if (!g_sampleInterval.empty()) o.sampleIntervalMin = parseSampleInterval(g_sampleInterval);
  return o;
}

CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0.0;
        if (parseNumber(text, &v) && v > 0.0) return {};
        return "must be a positive number, got '" + text + "'";
      },
      "POSITIVE");
}

void addOut(CLI::App* sub, std::string& out) {
  sub->add_option("--out", out, "Result file (JSON; written atomically). Default: stdout");
}

void addSeed(CLI::App* sub, std::uint64_t& seed) {
  sub->add_option("--seed", seed, "Seed of the stochastic methods (same seed, same result)")
      ->capture_default_str();
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    // "a, b" as people type it: the blanks around a name are not part of it.
    const auto first = item.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    out.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
  }
  return out;
}

ThermalLog readThermalArgs(const std::string& data, const std::string& target, const std::string& inputList,
                           const CsvReadOptions& csv) {
  ThermalLog log = readThermalLog(data, 3, csv);
  (void)log.channel(target);
  const auto inputs = splitList(inputList);
  if (inputs.empty())
    throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "needs at least one column name");
  for (const auto& in : inputs) {
    if (in == target)
      throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "'" + in + "' is also the --target");
    (void)log.channel(in);
  }
  return log;
}

void registerCommands(CLI::App& app, int argc, char** argv) {
  g_argc = argc;
  g_argv = argv;

  {
    auto a = std::make_shared<DemoArgs>();
    auto* sub =
        app.add_subcommand("demo", "Run the main job on the bundled sample project and write the PDF report");
    sub->add_option("--out-dir", a->outDir, "Folder for the demo project, its data and the report")
        ->capture_default_str();
    sub->callback([a] { g_selected = [a]() -> int { return runDemo(*a); }; });
  }
  {
    auto a = std::make_shared<ReportArgs>();
    auto* sub = app.add_subcommand("report", "Write the PDF report of a saved project");
    existingFile(sub->add_option("--project", a->project, "Project file (.metrofit)")->required());
    sub->add_option("--out", a->out, "PDF file to write")->required();
    sub->add_option("--lang", a->lang,
                    "Language of the report's text: en, de or pl (numbers keep the decimal point)")
        ->check(CLI::IsMember({"en", "de", "pl"}))
        ->capture_default_str();
    sub->callback([a] { g_selected = [a]() -> int { return runReport(*a); }; });
  }
  registerSetupCommand(app);
  registerMatchCommand(app);
  registerKinematicCommands(app);
  registerSpcCommand(app);
  registerThermalCommands(app);
  registerDiagnoseCommands(app);
  registerProjectCommands(app);
  registerFitElementCommand(app);
  registerWatchCommand(app);
  {
    auto* sim = app.add_subcommand("simulate", "Make test data with the built-in simulator");
    sim->require_subcommand(1);
    auto a = std::make_shared<SimArgs>();
    auto* th = sim->add_subcommand(
        "thermal", "A spindle heating/cooling test: time_min, spindle_rpm, T1..T4, T_amb, disp_z_um");
    th->add_option("--out", a->out, "Thermal log to write (CSV; written atomically). Default: stdout");
    addSeed(th, a->seed);
    th->callback([a] { g_selected = [a]() -> int { return runSimulateThermal(*a); }; });
    auto* pr = sim->add_subcommand("probe", "Contact-probed points of a workpiece with a posture error");
    pr->add_option("--shape", a->shape, "block | s-piece (ISO 10791-7 S-shaped test piece, 40 points)")
        ->check(CLI::IsMember({"block", "s-piece"}))
        ->capture_default_str();
    pr->add_option("--out", a->out, "Probe points to write (CSV; written atomically). Default: stdout");
    addSeed(pr, a->seed);
    pr->callback([a] { g_selected = [a]() -> int { return runSimulateProbe(*a); }; });
    registerSimulateSetupCommand(*sim);
    registerSimulateKinematicCommands(*sim);
  }
}

int runSelected() {
  if (!g_selected) throw ValidationError(ErrorContext{}, "no subcommand given (see metrofit-cli --help)");
  return g_selected();
}

}  // namespace metrofit::cli
