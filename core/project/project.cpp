#include "core/project/project.h"

#include <cmath>
#include <set>

#include "core/common/error.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"
#include "core/machine/machine.h"
#include "core/project/nominals.h"

namespace metrofit {
namespace {

nlohmann::json nominalSourceToJson(const NominalSource& n) {
  nlohmann::json o{{"from", n.from}};
  if (!n.element.empty()) o["element"] = n.element;
  if (!n.criterion.empty() && n.criterion != "ls") o["criterion"] = n.criterion;
  if (n.radiusMm > 0.0) o["radius_mm"] = n.radiusMm;
  if (n.robust) o["robust"] = true;
  if (n.inner) o["inner"] = true;
  if (!n.reference.empty()) o["reference"] = n.reference;
  if (!n.cad.empty()) o["cad"] = n.cad;
  if (n.from == "reference") o["pair"] = n.pair;
  return o;
}

NominalSource nominalSourceFromJson(const JsonReader& r, const std::string& inDataset) {
  for (const auto& [key, value] : r.json().items()) {
    static const std::set<std::string> known{"from",  "element",   "criterion", "radius_mm", "robust",
                                             "inner", "reference", "pair",      "cad"};
    if (!known.count(key))
      r.fail(inDataset +
                 "unknown key (nominals takes from, element, criterion, radius_mm, robust, inner, "
                 "reference, pair, cad)",
             key);
  }
  NominalSource n;
  n.from = r.string("from");
  n.element = r.string("element", "");
  n.criterion = r.string("criterion", "");
  n.radiusMm = r.number("radius_mm", 0.0);
  n.robust = r.boolean("robust", false);
  n.inner = r.boolean("inner", false);
  n.reference = r.string("reference", "");
  n.pair = r.string("pair", "id");
  n.cad = r.string("cad", "");
  try {
    checkNominalSource(n);
  } catch (const Error& e) {
    r.fail(inDataset + e.detail(), e.context().field);
  }
  return n;
}

}  // namespace

const DatasetRef* Project::dataset(const std::string& id) const {
  for (const auto& d : datasets) {
    if (d.id == id) return &d;
  }
  return nullptr;
}

const DatasetRef* Project::firstOfKind(const std::string& kind) const {
  for (const auto& d : datasets) {
    if (d.kind == kind) return &d;
  }
  return nullptr;
}

nlohmann::json Project::toJson() const {
  nlohmann::json j;
  j["format"] = kFormatName;
  j["version"] = kFormatVersion;
  j["name"] = name;
  j["description"] = description;
  j["datasets"] = nlohmann::json::array();
  for (const auto& d : datasets) {
    nlohmann::json o{{"id", d.id}, {"kind", d.kind}, {"path", d.path}};
    if (d.paths.size() > 1) o["paths"] = d.paths;
    if (!d.description.empty()) o["description"] = d.description;
    if (!d.licence.empty()) o["licence"] = d.licence;
    if (d.csv.dialect.delimiter) o["delimiter"] = csvDelimiterName(d.csv.dialect.delimiter);
    if (d.csv.dialect.decimal) o["decimal"] = csvDecimalName(d.csv.dialect.decimal);
    if (d.csv.sampleIntervalMin > 0.0) o["sample_interval_min"] = d.csv.sampleIntervalMin;
    if (d.csv.headerLines >= 0) o["header_lines"] = d.csv.headerLines;
    if (!d.csv.commentPrefix.empty()) o["comment"] = d.csv.commentPrefix;
    if (d.csv.skipBadRows) o["skip_bad_rows"] = true;
    if (!(d.dmis == setup::DmisOptions{})) {
      nlohmann::json dmis = nlohmann::json::object();
      if (d.dmis.taMeaning != setup::DmisTaMeaning::Auto)
        dmis["ta_meaning"] = setup::dmisTaMeaningName(d.dmis.taMeaning);
      if (d.dmis.signFollowsNominal) dmis["ta_sign"] = "nominal";
      o["dmis"] = std::move(dmis);
    }
    if (!d.nominals.empty()) o["nominals"] = nominalSourceToJson(d.nominals);
    if (d.part > 0) o["part"] = d.part;
    if (!d.csv.columnMap.empty()) {
      nlohmann::json map = nlohmann::json::object();
      for (const auto& [role, column] : d.csv.columnMap) map[role] = column;
      o["map"] = std::move(map);
    }
    j["datasets"].push_back(std::move(o));
  }
  j["studies"] = studies;
  j["results"] = results;
  return j;
}

Project Project::fromJson(const nlohmann::json& j, const std::string& source) {
  JsonReader r(j, source);
  r.requireObject();
  const std::string format = r.string("format");
  if (format != kFormatName)
    r.fail("is '" + format + "', expected '" + kFormatName + "' (not a Metrofit project)", "format");
  const long version = r.integer("version");
  if (version < 1) r.fail("must be 1 or more", "version");
  if (version > kFormatVersion) {
    r.fail("format version " + std::to_string(version) +
               " was written by a newer Metrofit; this build reads up to " + std::to_string(kFormatVersion),
           "version");
  }
  Project p;
  p.name = r.string("name", "Untitled");
  p.description = r.string("description", "");
  if (r.has("datasets")) {
    const JsonReader ds = r.array("datasets");
    std::set<std::string> ids;
    for (std::size_t i = 0; i < ds.size(); ++i) {
      const JsonReader d = ds.at(i);
      d.requireObject();
      DatasetRef ref;
      ref.id = d.string("id");
      if (ref.id.empty()) d.fail("must not be empty", "id");
      if (!ids.insert(ref.id).second) d.fail("duplicate dataset id '" + ref.id + "'", "id");
      ref.kind = d.string("kind");
      ref.path = d.string("path");
      if (ref.path.empty()) d.fail("must not be empty", "path");
      if (d.has("paths")) {
        const JsonReader paths = d.array("paths");
        if (paths.size() == 0) d.fail("must list the files of the series", "paths");
        if (ref.kind != dataset_kind::kCmmReport && ref.kind != dataset_kind::kDmis)
          d.fail("a series of files is a DMIS series: only for kinds cmm_report and dmis", "paths");
        for (std::size_t k = 0; k < paths.size(); ++k) {
          const nlohmann::json& p = paths.json()[k];
          if (!p.is_string() || p.get<std::string>().empty())
            d.fail("must be a file name (a non-empty string)", "paths[" + std::to_string(k) + "]");
          ref.paths.push_back(p.get<std::string>());
        }
        if (ref.paths.front() != ref.path)
          d.fail("the first file of the series must be the dataset's \"path\" ('" + ref.path + "')",
                 "paths[0]");
        if (ref.paths.size() == 1) ref.paths.clear();
      }
      ref.description = d.string("description", "");
      ref.licence = d.string("licence", "");
      try {
        if (d.has("delimiter"))
          ref.csv.dialect.delimiter = parseCsvDelimiter(d.string("delimiter"), "delimiter");
        if (d.has("decimal")) ref.csv.dialect.decimal = parseCsvDecimal(d.string("decimal"), "decimal");
      } catch (const OptionsError& e) {
        d.fail(e.detail(), e.context().field);
      }
      if (d.has("sample_interval_min")) {
        ref.csv.sampleIntervalMin = d.number("sample_interval_min");
        if (!(ref.csv.sampleIntervalMin > 0.0) || !std::isfinite(ref.csv.sampleIntervalMin))
          d.fail("must be a positive number of minutes", "sample_interval_min");
      }
      const std::string inDataset = "dataset '" + ref.id + "': ";
      if (d.has("header_lines")) {
        const long n = d.integer("header_lines");
        if (n < 0 || n > 10000)
          d.fail(inDataset + "must be a number of lines from 0 to 10000", "header_lines");
        ref.csv.headerLines = static_cast<int>(n);
      }
      if (d.has("comment")) {
        ref.csv.commentPrefix = d.string("comment");
        if (ref.csv.commentPrefix.empty() || ref.csv.commentPrefix.size() > 16 ||
            ref.csv.commentPrefix.find_first_of("\r\n\"") != std::string::npos ||
            ref.csv.commentPrefix.front() == ' ' || ref.csv.commentPrefix.front() == '\t')
          d.fail(inDataset +
                     "must be 1 to 16 characters, not starting with a blank, without quotes or line breaks",
                 "comment");
      }
      if (d.has("skip_bad_rows")) ref.csv.skipBadRows = d.boolean("skip_bad_rows", false);
      if (d.has("dmis")) {
        const JsonReader dmis = d.object("dmis");
        for (const auto& [key, value] : dmis.json().items())
          if (key != "ta_meaning" && key != "ta_sign")
            dmis.fail(inDataset + "unknown key (dmis takes ta_meaning and ta_sign)", key);
        try {
          if (dmis.has("ta_meaning"))
            ref.dmis.taMeaning = setup::parseDmisTaMeaning(dmis.string("ta_meaning"), "ta_meaning");
          if (dmis.has("ta_sign"))
            ref.dmis.signFollowsNominal = setup::parseDmisTaSign(dmis.string("ta_sign"), "ta_sign");
        } catch (const OptionsError& e) {
          dmis.fail(inDataset + e.detail(), e.context().field);
        }
      }
      if (d.has("nominals")) {
        if (ref.kind != dataset_kind::kProbePoints)
          d.fail(inDataset + "only a probe-point dataset takes its nominals from elsewhere", "nominals");
        ref.nominals = nominalSourceFromJson(d.object("nominals"), inDataset);
      }
      if (d.has("part")) {
        const long n = d.integer("part");
        if (n < 1 || n > 1000000) d.fail(inDataset + "must be a measured part's number, from 1", "part");
        ref.part = static_cast<int>(n);
      }
      if (d.has("map")) {
        const JsonReader map = d.object("map");
        for (const auto& [role, column] : map.json().items()) {
          if (role.empty() || !column.is_string() || column.get<std::string>().empty())
            d.fail("must map role names to column names (strings)", "map");
          ref.csv.columnMap.emplace_back(role, column.get<std::string>());
        }
      }
      p.datasets.push_back(std::move(ref));
    }
  }
  if (r.has("studies")) p.studies = r.object("studies").json();
  if (r.has("results")) p.results = r.object("results").json();
  if (p.studies.contains(study::kMatching) && !p.studies[study::kMatching].is_object())
    r.fail("must be an object", std::string("studies.") + study::kMatching);
  machine::MachineDefinition unused;
  matchingMachine(p, &unused, source);
  return p;
}

bool matchingMachine(const Project& project, machine::MachineDefinition* out, const std::string& source) {
  const std::string field = std::string("studies.") + study::kMatching + ".machine";
  const auto matching = project.studies.find(study::kMatching);
  if (matching == project.studies.end() || !matching->is_object() || !matching->contains("machine"))
    return false;
  nlohmann::json j = (*matching)["machine"];
  if (!j.is_object()) throw ValidationError(ErrorContext{source, 0, 0, field}, "must be an object");
  // Short topology names as people write them.
  if (j.contains("topology") && j["topology"].is_string()) {
    const std::string t = j["topology"].get<std::string>();
    if (t == "ac" || t == "bc") j["topology"] = t + "-table";
  }
  try {
    *out = machine::MachineDefinition::fromJson(j, source);
  } catch (const ValidationError& e) {
    const std::string& inner = e.context().field;
    throw ValidationError(ErrorContext{source, 0, 0, inner.empty() ? field : field + "." + inner},
                          e.detail());
  }
  return true;
}

void setMatchingMachine(Project& project, const machine::MachineDefinition& definition) {
  nlohmann::json& matching = project.studies[study::kMatching];
  if (!matching.is_object()) matching = nlohmann::json::object();
  matching["machine"] = definition.toJson();
}

Project loadProject(const std::string& path) {
  return Project::fromJson(readJsonFile(path), path);
}

void saveProject(const Project& project, const std::string& path) {
  writeFileAtomic(path, dumpJson(project.toJson()));
}

std::string resolveDatasetPath(const std::string& projectPath, const DatasetRef& dataset) {
  return joinPath(parentFolder(projectPath), dataset.path);
}

std::vector<std::string> datasetFiles(const DatasetRef& dataset) {
  return dataset.paths.empty() ? std::vector<std::string>{dataset.path} : dataset.paths;
}

std::vector<std::string> resolveDatasetPaths(const std::string& projectPath, const DatasetRef& dataset) {
  std::vector<std::string> out;
  for (const std::string& file : datasetFiles(dataset))
    out.push_back(joinPath(parentFolder(projectPath), file));
  return out;
}

}  // namespace metrofit
