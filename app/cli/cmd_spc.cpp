// metrofit-cli spc: X-bar/R chart limits, capability indices and the SPC-gated
// compensation decision of a measured feature.
//   spc --data F.csv --column C --subgroup N [--lsl L --usl U] [--nominal X] [--coverage K] [--out J.json]
//       [--dfq F.dfq [--dfq-part P]]: also the series as a Q-DAS DFQ file (core/io/dfq.h): one
//       characteristic (the column) with its nominal, limits, unit (the column name's suffix) and values,
//       the times from a `timestamp` column when the file has one
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/spc/spc.h"
#include "core/study/study_settings.h"

namespace metrofit::cli {
namespace {

/// The defaults are the project study's SPC series (studies.kinematics.spc, KinematicsSettings::Spc).
struct SpcArgs {
  std::string data, column, out, dfq, dfqPart;
  int subgroup = KinematicsSettings::Spc{}.subgroup;
  double lsl = 0.0, usl = 0.0, nominal = 0.0, coverage = KinematicsSettings::Spc{}.coverage;
  CLI::Option *lslOpt = nullptr, *uslOpt = nullptr, *nominalOpt = nullptr;
};

std::string g(double v, const char* format = "%.4g") {
  char buf[48];
  metrofit::c_snprintf(buf, sizeof buf, format, v);
  return buf;
}

SpcOptions spcOptions(const SpcArgs& a) {
  if (a.subgroup < kMinSubgroupSize || a.subgroup > kMaxSubgroupSize) {
    throw ValidationError(
        ErrorContext{{}, 0, 0, "--subgroup"},
        "must be between 2 and 25 (the range of the A2/D3/D4 table), got " + std::to_string(a.subgroup));
  }
  const bool hasL = a.lslOpt->count() > 0, hasU = a.uslOpt->count() > 0;
  if (hasL != hasU) {
    throw ValidationError(ErrorContext{{}, 0, 0, hasL ? "--usl" : "--lsl"},
                          "missing: give --lsl and --usl together (Cp and Cpk need both limits)");
  }
  SpcOptions o;
  o.subgroupSize = a.subgroup;
  if (hasL) {
    if (!(a.lsl < a.usl)) {
      throw ValidationError(ErrorContext{{}, 0, 0, "--lsl"}, "lower specification limit " + g(a.lsl, "%.6g") +
                                                                 " is not below --usl " + g(a.usl, "%.6g"));
    }
    o.lsl = a.lsl;
    o.usl = a.usl;
  }
  if (a.nominalOpt->count() > 0) o.nominal = a.nominal;
  o.coverageFactor = a.coverage;
  std::string why;
  if (!o.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "spc options"}, why);
  return o;
}

int runSpc(const SpcArgs& a) {
  const SpcOptions o = spcOptions(a);
  const CsvTable table = readFeatureTable(a.data, csvOptions());
  const std::vector<double> values = table.numericColumn(a.column);
  const SpcResult r = analyseSpc(values, o, ErrorContext{displayPath(a.data), 0, 0, a.column});
  if (!a.dfq.empty()) {
    writeFileAtomic(a.dfq, writeDfq(seriesDfqPart(table, a.column, values, o.nominal, o.lsl, o.usl, a.data,
                                                  a.dfqPart, displayPath(a.data))));
  }
  writeResult(a.out, dumpJson(spcResultToJson(r)));
  std::string line = "spc: column '" + a.column + "', " + std::to_string(r.chart.subgroups()) +
                     " subgroups of " + std::to_string(o.subgroupSize);
  if (r.valuesIgnored) line += " (" + std::to_string(r.valuesIgnored) + " trailing values left out)";
  line += r.chart.inControl() ? ", in control" : ", OUT OF CONTROL";
  line += ", sigma " + g(r.capability.sigmaWithin);
  if (r.capability.cp)
    line += ", Cp " + g(*r.capability.cp, "%.3g") + ", Cpk " + g(*r.capability.cpk, "%.3g");
  if (r.systematic) line += "; " + r.decision.reason;
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

}  // namespace

void registerSpcCommand(CLI::App& app) {
  auto a = std::make_shared<SpcArgs>();
  auto* sub = app.add_subcommand(
      "spc", "X-bar/R control chart limits, Cp/Cpk and the SPC-gated compensation decision");
  existingFile(
      sub->add_option("--data", a->data, "Measurements (CSV), rows in production order")->required());
  sub->add_option("--column", a->column, "Column of the feature to chart")->required();
  addCsvOptions(sub);
  sub->add_option("--subgroup", a->subgroup, "Subgroup size n (2..25): consecutive rows form a subgroup")
      ->required();
  a->lslOpt = sub->add_option("--lsl", a->lsl, "Lower specification limit");
  a->uslOpt = sub->add_option("--usl", a->usl, "Upper specification limit");
  a->nominalOpt =
      sub->add_option("--nominal", a->nominal, "Nominal (desired) value: systematic error = nominal - mean");
  sub->add_option("--coverage", a->coverage, "Coverage factor k of the interval of the mean")
      ->check(positiveNumber())
      ->capture_default_str();
  sub->add_option("--dfq", a->dfq,
                  "Also write the series as a Q-DAS DFQ file (K-field format SPC packages import; atomic)");
  sub->add_option("--dfq-part", a->dfqPart,
                  "Part number (K1001) of the DFQ file. Default: the data file's name");
  addOut(sub, a->out);
  sub->callback([a] { selectRunner([a]() -> int { return runSpc(*a); }); });
}

}  // namespace metrofit::cli
