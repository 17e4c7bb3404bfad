#include "core/project/report_model.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/file_io.h"
#include "core/project/dataset_content.h"
#include "core/setup/report.h"

namespace metrofit {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// Limits as the reader checks them: printed as both 0 (OGP's "no tolerance") counts as none.
void setLimits(ReportCharacteristic& c, std::optional<double> lower, std::optional<double> upper) {
  if (lower && upper && (*lower != 0.0 || *upper != 0.0)) {
    c.lower = lower;
    c.upper = upper;
  }
}

void textReportCharacteristics(const CmmTextReport& report, ReportFeatures& out) {
  std::set<std::string> seen;  // labels, upper case
  for (const CmmRun& run : report.runs) {
    // A feature label that names two features of one run cannot be a dimension's label: "Step n".
    std::map<std::string, int> labelCount;
    for (const CmmFeature& f : run.features)
      if (!f.label.empty()) ++labelCount[upper(f.label)];
    for (const CmmFeature& f : run.features) {
      std::string feature;
      if (report.format == CmmReportFormat::PcDmis) {
        feature = !f.label.empty() ? f.label : f.featureName;
      } else if (isCharacteristicTable(report.format)) {
        feature = !f.label.empty() && labelCount[upper(f.label)] == 1 ? f.label : f.featureName;
      } else {
        feature =
            !f.label.empty() && labelCount[upper(f.label)] == 1 ? f.label : "Step " + std::to_string(f.step);
      }
      for (const CmmValue& v : f.values) {
        ReportCharacteristic c;
        c.feature = feature;
        c.characteristic = v.name;
        c.label = feature + ":" + v.name;
        if (!seen.insert(upper(c.label)).second) continue;
        c.unit = v.angle ? "deg" : "mm";
        c.nominal = v.nominal;
        setLimits(c, v.lower, v.upper);
        c.line = v.line;
        if (v.angle) {
          c.usable = false;
          c.why = "an angle (deg), not a length a setup correction moves";
        } else if (!v.nominal && !v.printedDeviation) {
          c.usable = false;
          c.why = "the report prints no nominal for it";
        }
        out.characteristics.push_back(std::move(c));
      }
    }
  }
}

void dmisCharacteristics(const std::vector<FeatureTableRow>& rows, ReportFeatures& out) {
  // One characteristic per DMIS label: the tolerance row (T / TA) when there is one, else the position.
  std::vector<std::string> order;
  std::map<std::string, ReportCharacteristic> byLabel;
  for (const FeatureTableRow& r : rows) {
    const std::string key = upper(r.feature);
    const bool tolerance = r.characteristic != "X" && r.characteristic != "Y" && r.characteristic != "Z" &&
                           r.characteristic != "D";
    auto it = byLabel.find(key);
    if (it == byLabel.end()) {
      order.push_back(key);
      ReportCharacteristic c;
      c.feature = r.feature;
      c.label = r.feature;
      c.characteristic = tolerance ? r.characteristic : std::string("position");
      c.line = r.line;
      it = byLabel.emplace(key, std::move(c)).first;
    }
    if (tolerance) {
      ReportCharacteristic& c = it->second;
      c.characteristic = r.characteristic;
      setLimits(c, r.lower, r.upper);
    }
  }
  for (const std::string& key : order) out.characteristics.push_back(byLabel[key]);
}

void csvCharacteristics(const std::vector<FeatureTableRow>& rows, ReportFeatures& out) {
  std::set<std::string> seen;
  for (const FeatureTableRow& r : rows) {
    if (!seen.insert(r.feature).second) continue;
    ReportCharacteristic c;
    c.feature = r.feature;
    c.nominal = r.nominal;
    setLimits(c, r.lower, r.upper);
    c.line = r.line;
    out.characteristics.push_back(std::move(c));
  }
}

std::string uniqueId(const setup::Model& m, std::string id) {
  const auto used = [&m](const std::string& s) {
    for (const auto& d : m.setup)
      if (d.id == s) return true;
    for (const auto& f : m.features)
      if (f.id == s) return true;
    for (const auto& d : m.dimensions)
      if (d.id == s) return true;
    return false;
  };
  if (!used(id)) return id;
  for (int n = 2;; ++n) {
    const std::string candidate = id + " #" + std::to_string(n);
    if (!used(candidate)) return candidate;
  }
}

}  // namespace

ReportFeatures readReportFeatures(const std::string& file, const CsvReadOptions& csv) {
  ReportFeatures out;
  out.source = file;
  const std::string text = readFile(file, 256u << 20);
  if (setup::looksLikeDmis(text)) {
    out.format = "DMIS output";
    dmisCharacteristics(dmisFeatureRows(text, displayPath(file)), out);
  } else if (looksLikeCmmTextReport(text)) {
    const CmmTextReport report = cmmTextReportFromText(text, displayPath(file));
    out.format = toString(report.format);
    textReportCharacteristics(report, out);
  } else {
    out.format = "CSV";
    out.byId = true;
    csvCharacteristics(cmmCsvFeatureRows(readCsvFile(file, csv)), out);
  }
  return out;
}

ReportFeatures datasetReportFeatures(const std::string& projectPath, const DatasetRef& dataset) {
  const std::vector<std::string> files = resolveDatasetPaths(projectPath, dataset);
  ReportFeatures out = readReportFeatures(files.front(), dataset.csv);
  // A DMIS series: the characteristics of every file, each once (a multi-part fixture's files measure
  // different workpieces' features).
  std::set<std::string> seen;
  for (const ReportCharacteristic& c : out.characteristics)
    seen.insert(upper(c.label.empty() ? c.feature : c.label));
  for (std::size_t k = 1; k < files.size(); ++k) {
    const ReportFeatures more = readReportFeatures(files[k], dataset.csv);
    for (const ReportCharacteristic& c : more.characteristics)
      if (seen.insert(upper(c.label.empty() ? c.feature : c.label)).second) out.characteristics.push_back(c);
  }
  return out;
}

int modelDimensionFor(const setup::Model& model, const ReportFeatures& report,
                      const ReportCharacteristic& c) {
  for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
    const setup::Dimension& d = model.dimensions[q];
    if (report.byId ? d.id == c.feature : upper(d.dmisLabel()) == upper(c.label)) return static_cast<int>(q);
  }
  return -1;
}

setup::Model newReportModel(const std::string& name, const std::string& axis) {
  setup::Model m;
  m.name = name;
  m.axis = axis;
  setup::SetupDatum w;
  w.id = "W1";
  w.kind = setup::DatumKind::Wks;
  m.setup.push_back(w);
  return m;
}

setup::Model addReportCharacteristics(setup::Model model, const ReportFeatures& report,
                                      const std::vector<std::size_t>& chosen,
                                      const ReportModelOptions& options) {
  if (!options.connectTo.empty() && model.setupIndex(options.connectTo) < 0)
    throw ValidationError(ErrorContext{model.source, 0, 0, "connect to"},
                          "'" + options.connectTo + "' is not a setup datum of the model");
  std::map<std::string, std::string> featureNode;  // report feature -> feature node id added here
  for (const std::size_t k : chosen) {
    if (k >= report.characteristics.size())
      throw ValidationError(ErrorContext{report.source, 0, 0, "characteristic"},
                            "no characteristic " + std::to_string(k + 1) + " in the report");
    const ReportCharacteristic& c = report.characteristics[k];
    const std::string name = c.label.empty() ? c.feature : c.label;
    const ErrorContext where{report.source, c.line, 0, name};
    if (!c.usable) throw ValidationError(where, "cannot be a dimension of a setup model: " + c.why);
    if (modelDimensionFor(model, report, c) >= 0) continue;  // the model reads it already
    setup::Dimension d;
    if (c.lower && c.upper) {
      d.lower = *c.lower;
      d.upper = *c.upper;
    } else if (options.defaultToleranceMm > 0.0) {
      d.lower = -options.defaultToleranceMm;
      d.upper = options.defaultToleranceMm;
    } else {
      throw ValidationError(where, "the report prints no tolerance for it; give a tolerance for such values");
    }
    d.nominal = c.nominal;
    if (report.byId) {
      d.id = c.feature;
      if (model.dimensionIndex(d.id) >= 0 || model.setupIndex(d.id) >= 0)
        throw ValidationError(where, "the model has a node '" + d.id + "' that is not this dimension");
      for (const auto& f : model.features)
        if (f.id == d.id) throw ValidationError(where, "the model has a feature node '" + d.id + "'");
    } else {
      d.label = c.label;
    }
    // One feature node per report feature (shared by its values).
    auto node = featureNode.find(c.feature);
    if (node == featureNode.end()) {
      const std::string id = uniqueId(model, report.byId ? c.feature + " F" : c.feature);
      model.features.push_back({id});
      node = featureNode.emplace(c.feature, id).first;
      if (!options.connectTo.empty()) model.arcs.push_back({options.connectTo, id, 1.0});
    }
    if (!report.byId) {
      d.id =
          uniqueId(model, c.characteristic.empty() ? c.feature + " D" : c.feature + " " + c.characteristic);
    }
    model.dimensions.push_back(d);
    model.arcs.push_back({node->second, d.id, 1.0});
  }
  return model;
}

}  // namespace metrofit
