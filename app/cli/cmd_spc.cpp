// metrofit-cli spc: X-bar/R chart limits, capability indices and the SPC-gated
// compensation decision of a measured feature.
//   spc --data F.csv --column C --subgroup N [--base K] [--lsl L --usl U] [--nominal X] [--coverage K]
//       [--out J.json]: N = 1 charts individuals and moving range; --base K takes the limits from the first K
//       subgroups (phase I) and judges the later ones against them (phase II); the result lists the Nelson
//       rules broken (core/spc/nelson.h)
//       [--dfq F.dfq [--dfq-part P]]: also the series as a Q-DAS DFQ file (core/io/dfq.h): one
//       characteristic (the column) with its nominal, limits, unit (the column name's suffix) and values,
//       the times from a `timestamp` column when the file has one
//   spc --data F.dfq|F_chr.txt --characteristic N|NAME ...: a Q-DAS DFQ file or a Zeiss Calypso _chr table
//       (recognised by content): the series of one characteristic, N its number (DFQ K2001; Calypso id),
//       NAME its description (DFQ K2002; Calypso id); values in measured-part order, DFQ values that are
//       not valid (attribute >= 255, core/io/dfq.h) left out; the nominal and limits from the file unless
//       --nominal / --lsl --usl are given; a QIF 3 Results file likewise, one value per measured part, N the
//       characteristic's Name (qifCmmReport's key), NAME its type (Diameter, Position) when unique
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/io/calypso.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/dfq.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/io/qif.h"
#include "core/spc/spc.h"
#include "core/study/study_settings.h"

namespace metrofit::cli {
namespace {

/// The defaults are the project study's SPC series (studies.kinematics.spc, KinematicsSettings::Spc).
struct SpcArgs {
  std::string data, column, characteristic, out, dfq, dfqPart;
  int subgroup = KinematicsSettings::Spc{}.subgroup;
  int base = 0;  ///< --base K, 0 when not given
  double lsl = 0.0, usl = 0.0, nominal = 0.0, coverage = KinematicsSettings::Spc{}.coverage;
  CLI::Option *lslOpt = nullptr, *uslOpt = nullptr, *nominalOpt = nullptr, *baseOpt = nullptr;
};

std::string g(double v, const char* format = "%.4g") {
  char buf[48];
  metrofit::c_snprintf(buf, sizeof buf, format, v);
  return buf;
}

SpcOptions spcOptions(const SpcArgs& a) {
  if (a.subgroup < 1 || a.subgroup > kMaxSubgroupSize) {
    throw ValidationError(ErrorContext{{}, 0, 0, "--subgroup"},
                          "must be between 1 (individuals and moving range) and 25 (the range of the "
                          "A2/D3/D4 table), got " +
                              std::to_string(a.subgroup));
  }
  if (a.baseOpt->count() > 0 && a.base < 2) {
    throw ValidationError(ErrorContext{{}, 0, 0, "--base"},
                          "must be at least 2 subgroups (the limits need ranges to be set from), got " +
                              std::to_string(a.base));
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
  if (a.baseOpt->count() > 0) o.baseSubgroups = static_cast<std::size_t>(a.base);
  std::string why;
  if (!o.isValid(&why)) throw OptionsError(ErrorContext{{}, 0, 0, "spc options"}, why);
  return o;
}

/// One characteristic of a DFQ file or a Calypso _chr table, as an SPC series.
struct CharacteristicSeries {
  std::string title;   ///< "number (description)"
  std::string column;  ///< a column name for the DFQ export: the number
  std::vector<double> values;
  std::optional<double> nominal, lower, upper;  ///< absolute
};

/// The series `choice` names in a DFQ file or a Calypso _chr table (`text`), or nullopt for another file.
std::optional<CharacteristicSeries> characteristicSeries(std::string_view text, const std::string& source,
                                                         const std::string& choice) {
  CharacteristicSeries s;
  if (looksLikeDfq(text)) {
    const DfqFile f = dfqFromText(text, source);
    std::vector<std::pair<std::string, std::string>> list;
    for (const DfqReadCharacteristic& c : f.characteristics) list.emplace_back(c.number, c.description);
    const DfqReadCharacteristic& c = f.characteristics[chooseCharacteristic(list, choice, source)];
    s.title = c.title();
    s.column = c.number;
    for (const DfqReadValue& v : c.values)
      if (v.valid()) s.values.push_back(*v.value);
    s.nominal = c.nominal;
    s.lower = c.lowerLimit;
    s.upper = c.upperLimit;
    return s;
  }
  if (looksLikeCalypsoCharacteristics(text)) {
    const CalypsoCharacteristics t = calypsoCharacteristicsFromText(text, source);
    std::vector<std::pair<std::string, std::string>> list;
    for (const CalypsoCharacteristic& c : t.rows) {
      bool seen = false;
      for (const auto& [id, name] : list) seen = seen || id == c.id;
      if (!seen) list.emplace_back(c.id, c.id);
    }
    const std::string id = list[chooseCharacteristic(list, choice, source)].first;
    s.title = id;
    s.column = id;
    for (const CalypsoCharacteristic& c : t.rows) {
      if (c.id != id) continue;
      s.values.push_back(c.actual);
      if (!s.nominal) s.nominal = c.nominal;
      if (c.nominal && c.lowerTol && !s.lower) s.lower = *c.nominal + *c.lowerTol;
      if (c.nominal && c.upperTol && !s.upper) s.upper = *c.nominal + *c.upperTol;
    }
    return s;
  }
  if (looksLikeQif(text)) {
    // A QIF Results file: one value per measured part (MeasurementResults), the characteristic by its
    // key (the Name, made unique as qifCmmReport says) or its type ("Diameter") when that is unique.
    const CmmTextReport report = qifCmmReport(qifFromText(text, source));
    std::vector<std::pair<std::string, std::string>> list;
    std::set<std::string> seen;
    for (const CmmRun& run : report.runs)
      for (const CmmFeature& f : run.features)
        if (seen.insert(f.featureName).second) list.emplace_back(f.featureName, f.type);
    if (list.empty())
      throw ValidationError(ErrorContext{source, 0, 0, "--characteristic"},
                            "the file has no measured characteristic with a value");
    const std::string key = list[chooseCharacteristic(list, choice, source)].first;
    s.title = key;
    s.column = key;
    for (const CmmRun& run : report.runs)
      for (const CmmFeature& f : run.features) {
        if (f.featureName != key || f.values.empty()) continue;
        const CmmValue& v = f.values.front();
        s.values.push_back(v.actual);
        if (!s.nominal) s.nominal = v.nominal;
        if (v.nominal && v.lower && !s.lower) s.lower = *v.nominal + *v.lower;
        if (v.nominal && v.upper && !s.upper) s.upper = *v.nominal + *v.upper;
      }
    return s;
  }
  return std::nullopt;
}

int runSpc(const SpcArgs& a) {
  SpcOptions o = spcOptions(a);
  const std::string text = readFile(a.data, 256u << 20);
  const std::string source = displayPath(a.data);
  const bool characteristics =
      looksLikeDfq(text) || looksLikeCalypsoCharacteristics(text) || looksLikeQif(text);
  if (characteristics && !a.column.empty())
    throw ValidationError(ErrorContext{source, 0, 0, "--column"},
                          "is for CSV files; a DFQ, QIF or Calypso file takes --characteristic N|NAME");
  if (!characteristics && !a.characteristic.empty())
    throw ValidationError(ErrorContext{source, 0, 0, "--characteristic"},
                          "is for DFQ and QIF files and Calypso _chr tables; a CSV file takes --column");
  if (!characteristics && a.column.empty())
    throw ValidationError(ErrorContext{source, 0, 0, "--column"},
                          "is required: the column of the feature to chart");
  CsvTable table;
  std::vector<double> values;
  std::string name = a.column, what = "column";
  if (characteristics) {
    const CharacteristicSeries c = *characteristicSeries(text, source, a.characteristic);
    values = c.values;
    name = c.column;
    what = "characteristic '" + c.title + "'";
    // The file's nominal and limits unless the command line gives them.
    if (!o.nominal) o.nominal = c.nominal;
    if (!o.lsl && !o.usl && c.lower && c.upper) {
      o.lsl = c.lower;
      o.usl = c.upper;
    }
    std::vector<std::vector<std::string>> rows;
    std::vector<long> lines;
    for (double v : values) {
      rows.push_back({CsvWriter::formatNumber(v)});
      lines.push_back(0);
    }
    table = CsvTable::fromCells(source, {name}, std::move(rows), std::move(lines));
  } else {
    // A CMM text report (one row per run) or a CSV file; the file is read once, so "-" works.
    table = looksLikeCmmTextReport(text) ? cmmReportFeatureTable(cmmTextReportFromText(text, source))
                                         : parseCsv(text, source, csvOptions());
    values = table.numericColumn(a.column);
    what = "column '" + a.column + "'";
  }
  const std::size_t complete = values.size() / static_cast<std::size_t>(o.subgroupSize);
  if (o.baseSubgroups > complete) {
    throw ValidationError(
        ErrorContext{source, 0, 0, "--base"},
        "is " + std::to_string(o.baseSubgroups) + " subgroups but " + what + " has " +
            std::to_string(complete) +
            (o.subgroupSize == 1 ? " values" : " complete subgroups of " + std::to_string(o.subgroupSize)));
  }
  const SpcResult r =
      analyseSpc(values, o, ErrorContext{source, 0, 0, characteristics ? "--characteristic" : a.column});
  if (!a.dfq.empty()) {
    writeFileAtomic(a.dfq, writeDfq(seriesDfqPart(table, name, values, o.nominal, o.lsl, o.usl, a.data,
                                                  a.dfqPart, source)));
  }
  writeResult(a.out, dumpJson(spcResultToJson(r)));
  std::string line = "spc: " + what + ", " +
                     (o.subgroupSize == 1 ? std::to_string(r.chart.subgroups()) + " individual values (X-MR)"
                                          : std::to_string(r.chart.subgroups()) + " subgroups of " +
                                                std::to_string(o.subgroupSize));
  if (r.valuesIgnored) line += " (" + std::to_string(r.valuesIgnored) + " trailing values left out)";
  if (r.chart.baseSubgroups < r.chart.subgroups())
    line += ", limits from the first " + std::to_string(r.chart.baseSubgroups);
  line += r.chart.inControl() ? ", in control" : ", OUT OF CONTROL";
  if (!r.rules.empty()) {
    line += " (rules broken:";
    for (const RuleBreak& b : r.rules)
      line += std::string(" ") + ruleChartName(b.chart) + " " + ruleName(b.rule) + ";";
    line.back() = ')';
  }
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
      "spc",
      "X-bar/R (or X-MR) control chart limits, Nelson rules, Cp/Cpk and the SPC-gated compensation decision");
  existingFile(
      sub->add_option(
             "--data", a->data,
             "Measurements (CSV, rows in production order; a CMM text report; a Q-DAS DFQ file, a QIF 3 "
             "Results file or a Zeiss Calypso _chr table, read by content)")
          ->required());
  sub->add_option("--column", a->column, "Column of the feature to chart (CSV files and CMM text reports)");
  sub->add_option(
      "--characteristic", a->characteristic,
      "DFQ, QIF file or Calypso _chr table: the characteristic to chart, by number (DFQ K2001, Calypso "
      "id, QIF Name) or name (DFQ K2002 description, QIF characteristic type when unique)");
  addCsvOptions(sub);
  sub->add_option(
         "--subgroup", a->subgroup,
         "Subgroup size n (1..25): consecutive rows form a subgroup; 1: individuals and moving range")
      ->required();
  a->baseOpt = sub->add_option(
      "--base", a->base,
      "Control limits from the first K subgroups (phase I, K >= 2); the later ones are judged against them "
      "(phase II). Default: every subgroup");
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
