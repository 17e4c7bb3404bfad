#include "core/io/qif.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <set>
#include <unordered_map>

#include <pugixml.hpp>

#include "core/common/error.h"
#include "core/io/cmm_text_report.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/xml_text.h"

namespace metrofit {
namespace {

constexpr std::string_view kQifNamespace = "http://qifstandards.org/xsd/qif3";

using xml::localName;

bool endsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

pugi::xml_node child(const pugi::xml_node& n, std::string_view name) {
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && localName(c) == name) return c;
  return {};
}

std::vector<pugi::xml_node> elements(const pugi::xml_node& n) {
  std::vector<pugi::xml_node> out;
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element) out.push_back(c);
  return out;
}

/// The reading state: the text (for line numbers) and the source name.
class Reader {
 public:
  Reader(std::string_view text, std::string source) : source_(std::move(source)), lines_(text) {}

  const std::string& source() const { return source_; }

  const xml::LineIndex& lines() const { return lines_; }
  long line(const pugi::xml_node& n) const { return lines_.of(n); }

  [[noreturn]] void parseError(const pugi::xml_node& n, const std::string& what) const {
    throw ParseError(ErrorContext{source_, line(n), 0, {}}, what);
  }
  [[noreturn]] void invalid(const pugi::xml_node& n, const std::string& what) const {
    throw ValidationError(ErrorContext{source_, line(n), 0, {}}, what);
  }

  /// "CircleFeatureNominal 45" (the element and its id).
  static std::string named(const pugi::xml_node& n) {
    std::string s(localName(n));
    if (const pugi::xml_attribute id = n.attribute("id")) s += std::string(" ") + id.value();
    return s;
  }

  long integer(const pugi::xml_node& where, std::string_view text, const std::string& what) const {
    const std::string_view t = trimmed(text);
    long v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
      parseError(where, what + ": '" + std::string(t) + "' is not an integer id");
    return v;
  }

  long id(const pugi::xml_node& n) const {
    const pugi::xml_attribute a = n.attribute("id");
    if (!a) invalid(n, named(n) + " has no id");
    return integer(n, a.value(), named(n));
  }

  /// The integer text of child `name` of `n`; ValidationError when absent.
  long ref(const pugi::xml_node& n, std::string_view name) const {
    const pugi::xml_node c = child(n, name);
    if (!c) invalid(n, named(n) + ": no " + std::string(name));
    return integer(c, c.child_value(), named(n) + " " + std::string(name));
  }

  /// The Id children of list `name` of `n` (empty when there is no such list).
  std::vector<long> refList(const pugi::xml_node& n, std::string_view name) const {
    std::vector<long> out;
    const pugi::xml_node list = child(n, name);
    for (const pugi::xml_node& c : elements(list))
      if (localName(c) == "Id")
        out.push_back(integer(c, c.child_value(), named(n) + " " + std::string(name)));
    return out;
  }

  std::optional<double> number(const pugi::xml_node& n, std::string_view name) const {
    const pugi::xml_node c = child(n, name);
    if (!c) return std::nullopt;
    double v = 0.0;
    if (!parseNumber(trimmed(c.child_value()), &v))
      parseError(c, named(n) + " " + std::string(name) + ": '" + std::string(trimmed(c.child_value())) +
                        "' is not a number");
    return v;
  }

  std::optional<Eigen::Vector3d> vector3(const pugi::xml_node& n, std::string_view name) const {
    const pugi::xml_node c = child(n, name);
    if (!c) return std::nullopt;
    std::string_view t = trimmed(c.child_value());
    Eigen::Vector3d v;
    int k = 0;
    while (!t.empty()) {
      std::size_t end = 0;
      while (end < t.size() && !std::isspace(static_cast<unsigned char>(t[end]))) ++end;
      double x = 0.0;
      if (k == 3 || !parseNumber(t.substr(0, end), &x))
        parseError(c, named(n) + " " + std::string(name) + ": '" + std::string(trimmed(c.child_value())) +
                          "' is not three numbers");
      v[k++] = x;
      t = trimmed(t.substr(end));
    }
    if (k != 3)
      parseError(c, named(n) + " " + std::string(name) + ": '" + std::string(trimmed(c.child_value())) +
                        "' is not three numbers");
    return v;
  }

 private:
  std::string source_;
  xml::LineIndex lines_;
};

/// id -> node of the elements in a list, refusing duplicate ids.
std::unordered_map<long, pugi::xml_node> byId(const Reader& r, const pugi::xml_node& list) {
  std::unordered_map<long, pugi::xml_node> out;
  for (const pugi::xml_node& n : elements(list)) {
    const long id = r.id(n);
    if (!out.emplace(id, n).second) r.invalid(n, "duplicate id " + std::to_string(id));
  }
  return out;
}

pugi::xml_node lookUp(const Reader& r, const std::unordered_map<long, pugi::xml_node>& map, long id,
                      const pugi::xml_node& from, const std::string& refName, const std::string& kind) {
  const auto it = map.find(id);
  if (it == map.end())
    r.invalid(from, Reader::named(from) + ": " + refName + " " + std::to_string(id) + " names no " + kind);
  return it->second;
}

/// The type of an element named "<T><suffix>" ("CircleFeatureNominal" -> "Circle").
std::string typeOf(const pugi::xml_node& n, std::string_view suffix) {
  const std::string_view s = localName(n);
  return std::string(endsWith(s, suffix) ? s.substr(0, s.size() - suffix.size()) : s);
}

bool isAngleType(const std::string& type) {
  return type.find("Angle") != std::string::npos;
}

struct Units {
  double linear = 1.0;   ///< file unit -> mm
  double angular = 1.0;  ///< file unit -> degrees
  std::string linearName = "mm";
};

double unitFactor(const Reader& r, const pugi::xml_node& unit, double toSi, bool angular) {
  const std::string name(trimmed(child(unit, "UnitName").child_value()));
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!angular) {
    if (lower == "mm" || lower == "millimeter" || lower == "millimetre") return 1.0;
    if (lower == "inch" || lower == "in") return 25.4;
    if (lower == "m" || lower == "meter" || lower == "metre") return 1000.0;
  } else {
    if (lower == "degree" || lower == "deg") return 1.0;
    if (lower == "radian" || lower == "rad") return 180.0 / 3.14159265358979323846;
  }
  if (const pugi::xml_node conv = child(unit, "UnitConversion")) {
    const std::optional<double> f = r.number(conv, "Factor");
    if (f && *f > 0.0) return *f * toSi;
  }
  r.invalid(unit, std::string(angular ? "AngularUnit" : "LinearUnit") + " '" + name +
                      "' is not a known unit and has no UnitConversion Factor");
}

Units readUnits(const Reader& r, const pugi::xml_node& root) {
  const pugi::xml_node fileUnits = child(root, "FileUnits");
  if (!fileUnits) r.invalid(root, "QIFDocument has no FileUnits");
  const pugi::xml_node primary = child(fileUnits, "PrimaryUnits");
  Units u;
  if (const pugi::xml_node lin = child(primary, "LinearUnit")) {
    u.linear = unitFactor(r, lin, 1000.0, false);
    u.linearName = std::string(trimmed(child(lin, "UnitName").child_value()));
  } else {
    r.invalid(fileUnits, "FileUnits has no PrimaryUnits/LinearUnit");
  }
  if (const pugi::xml_node ang = child(primary, "AngularUnit"))
    u.angular = unitFactor(r, ang, 180.0 / 3.14159265358979323846, true);
  return u;
}

}  // namespace

bool QifFeature::hasSurfaceNormal() const {
  return type == "Point" || type == "EdgePoint" || type == "Plane";
}

std::optional<double> QifCharacteristic::nominalValue(const std::vector<QifFeature>& all) const {
  if (target) return target;
  if ((type == "Diameter" || type == "Radius") && !features.empty()) {
    const std::optional<double>& d = all.at(features.front()).diameter;
    if (d) return type == "Radius" ? std::optional<double>(*d / 2.0) : d;
  }
  if (zone) return 0.0;
  return std::nullopt;
}

std::optional<double> QifCharacteristic::lowerLimit(const std::vector<QifFeature>& all) const {
  if (minValue) {
    if (!definedAsLimit) return minValue;
    const std::optional<double> nom = nominalValue(all);
    return nom ? std::optional<double>(*minValue - *nom) : std::nullopt;
  }
  if (maxValue) return std::nullopt;
  if (zone) {
    if (type.find("Profile") != std::string::npos)
      return outerDisposition ? *outerDisposition - *zone : -*zone / 2.0;
    return 0.0;
  }
  return std::nullopt;
}

std::optional<double> QifCharacteristic::upperLimit(const std::vector<QifFeature>& all) const {
  if (maxValue) {
    if (!definedAsLimit) return maxValue;
    const std::optional<double> nom = nominalValue(all);
    return nom ? std::optional<double>(*maxValue - *nom) : std::nullopt;
  }
  if (minValue) return std::nullopt;
  if (zone) {
    if (type.find("Profile") != std::string::npos) return outerDisposition ? *outerDisposition : *zone / 2.0;
    return *zone;
  }
  return std::nullopt;
}

std::optional<std::size_t> QifFile::feature(std::string_view name) const {
  for (std::size_t i = 0; i < features.size(); ++i)
    if (features[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> QifFile::characteristic(std::string_view name) const {
  for (std::size_t i = 0; i < characteristics.size(); ++i)
    if (characteristics[i].name == name) return i;
  return std::nullopt;
}

const QifFeatureMeasurement* QifFile::measurement(std::size_t part, std::size_t feat) const {
  if (part >= parts.size()) return nullptr;
  for (const QifFeatureMeasurement& m : parts[part].features)
    if (m.feature == feat) return &m;
  return nullptr;
}

bool looksLikeQif(std::string_view text) {
  return xml::rootName(text) == "QIFDocument";
}

QifFile qifFromText(std::string_view text, const std::string& source) {
  const Reader r(text, source);
  pugi::xml_document doc;
  xml::parse(doc, text, source, r.lines());
  const pugi::xml_node root = doc.document_element();
  if (!root) throw ParseError(ErrorContext{source, 0, 0, {}}, "no XML root element");
  {
    const std::string_view name = root.name();
    const auto colon = name.find(':');
    const std::string xmlnsAttr =
        colon == std::string_view::npos ? "xmlns" : "xmlns:" + std::string(name.substr(0, colon));
    if (localName(root) != "QIFDocument")
      r.invalid(root, "root element <" + std::string(name) + "> is not a QIF QIFDocument");
    if (std::string_view(root.attribute(xmlnsAttr.c_str()).value()) != kQifNamespace)
      r.invalid(root, "QIFDocument is not in the QIF 3 namespace " + std::string(kQifNamespace) +
                          " (it is '" + root.attribute(xmlnsAttr.c_str()).value() + "')");
  }
  const Units units = readUnits(r, root);

  QifFile file;
  file.source = source;
  file.linearUnit = units.linearName;

  // ---- Features --------------------------------------------------------------------------------------
  const pugi::xml_node features = child(root, "Features");
  const auto featureDefs = byId(r, child(features, "FeatureDefinitions"));
  const auto featureNoms = byId(r, child(features, "FeatureNominals"));
  std::unordered_map<long, std::size_t> featureByItem;
  for (const pugi::xml_node& item : elements(child(features, "FeatureItems"))) {
    QifFeature f;
    f.itemId = r.id(item);
    f.type = typeOf(item, "FeatureItem");
    f.name = std::string(trimmed(child(item, "FeatureName").child_value()));
    f.line = r.line(item);
    // DeterminationMode/Set: a feature given (a reference), not measured; its "measurement" repeats it.
    f.set = static_cast<bool>(child(child(item, "DeterminationMode"), "Set"));
    f.nominalId = r.ref(item, "FeatureNominalId");
    const pugi::xml_node nom =
        lookUp(r, featureNoms, f.nominalId, item, "FeatureNominalId", "FeatureNominal");
    if (const pugi::xml_node defRef = child(nom, "FeatureDefinitionId")) {
      f.definitionId = r.ref(nom, "FeatureDefinitionId");
      const pugi::xml_node def =
          lookUp(r, featureDefs, f.definitionId, nom, "FeatureDefinitionId", "FeatureDefinition");
      if (const auto d = r.number(def, "Diameter")) f.diameter = *d * units.linear;
      f.internalExternal = std::string(trimmed(child(def, "InternalExternal").child_value()));
    }
    if (const pugi::xml_node axis = child(nom, "Axis")) {
      f.location = r.vector3(axis, "AxisPoint");
      f.direction = r.vector3(axis, "Direction");
    } else {
      f.location = r.vector3(nom, "Location");
      f.direction = r.vector3(nom, "Normal");
    }
    if (f.location) *f.location *= units.linear;
    if (!featureByItem.emplace(f.itemId, file.features.size()).second)
      r.invalid(item, "duplicate id " + std::to_string(f.itemId));
    file.features.push_back(std::move(f));
  }

  // ---- Characteristics -------------------------------------------------------------------------------
  const pugi::xml_node chars = child(root, "Characteristics");
  const auto charDefs = byId(r, child(chars, "CharacteristicDefinitions"));
  const auto charNoms = byId(r, child(chars, "CharacteristicNominals"));
  std::unordered_map<long, std::size_t> charByItem;
  for (const pugi::xml_node& item : elements(child(chars, "CharacteristicItems"))) {
    QifCharacteristic c;
    c.itemId = r.id(item);
    c.type = typeOf(item, "CharacteristicItem");
    c.name = std::string(trimmed(child(item, "Name").child_value()));
    c.line = r.line(item);
    c.angle = isAngleType(c.type);
    const double scale = c.angle ? units.angular : units.linear;
    c.nominalId = r.ref(item, "CharacteristicNominalId");
    const pugi::xml_node nom =
        lookUp(r, charNoms, c.nominalId, item, "CharacteristicNominalId", "CharacteristicNominal");
    c.definitionId = r.ref(nom, "CharacteristicDefinitionId");
    const pugi::xml_node def =
        lookUp(r, charDefs, c.definitionId, nom, "CharacteristicDefinitionId", "CharacteristicDefinition");
    if (const auto t = r.number(nom, "TargetValue")) c.target = *t * scale;
    if (const pugi::xml_node tol = child(def, "Tolerance")) {
      if (const auto v = r.number(tol, "MinValue")) c.minValue = *v * scale;
      if (const auto v = r.number(tol, "MaxValue")) c.maxValue = *v * scale;
      c.definedAsLimit = trimmed(child(tol, "DefinedAsLimit").child_value()) == "true" ||
                         trimmed(child(tol, "DefinedAsLimit").child_value()) == "1";
    }
    if (const auto z = r.number(def, "ToleranceValue")) c.zone = *z * units.linear;
    if (const auto d = r.number(def, "OuterDisposition")) c.outerDisposition = *d * units.linear;
    for (const long id : r.refList(item, "FeatureItemIds")) {
      const auto it = featureByItem.find(id);
      if (it == featureByItem.end())
        r.invalid(item,
                  Reader::named(item) + ": FeatureItemIds " + std::to_string(id) + " names no FeatureItem");
      c.features.push_back(it->second);
    }
    if (!charByItem.emplace(c.itemId, file.characteristics.size()).second)
      r.invalid(item, "duplicate id " + std::to_string(c.itemId));
    file.characteristics.push_back(std::move(c));
  }

  // ---- Results: one part per MeasurementResults ----------------------------------------------------------
  const pugi::xml_node results = child(root, "Results");
  if (!results) r.invalid(root, "QIFDocument has no Results (not a QIF Results file)");
  std::unordered_map<long, pugi::xml_node> components;
  for (const pugi::xml_node& set : elements(child(results, "ActualComponentSets")))
    for (const pugi::xml_node& comp : elements(set))
      if (localName(comp) == "ActualComponent") {
        const long id = r.id(comp);
        if (!components.emplace(id, comp).second) r.invalid(comp, "duplicate id " + std::to_string(id));
      }
  for (const pugi::xml_node& res : elements(child(results, "MeasurementResultsSet"))) {
    if (localName(res) != "MeasurementResults") continue;
    QifPart part;
    part.resultsId = r.id(res);
    part.line = r.line(res);
    part.status =
        std::string(trimmed(child(child(res, "InspectionStatus"), "InspectionStatusEnum").child_value()));
    for (const long id : r.refList(res, "ActualComponentIds")) {
      const pugi::xml_node comp = lookUp(r, components, id, res, "ActualComponentIds", "ActualComponent");
      if (part.serial.empty()) part.serial = std::string(trimmed(child(comp, "SerialNumber").child_value()));
      if (part.status.empty())
        part.status =
            std::string(trimmed(child(child(comp, "Status"), "InspectionStatusEnum").child_value()));
    }
    std::unordered_map<long, std::size_t> measuredById;
    for (const pugi::xml_node& m : elements(child(res, "MeasuredFeatures"))) {
      QifFeatureMeasurement fm;
      fm.id = r.id(m);
      fm.line = r.line(m);
      const long itemId = r.ref(m, "FeatureItemId");
      const auto item = featureByItem.find(itemId);
      if (item == featureByItem.end())
        r.invalid(m,
                  Reader::named(m) + ": FeatureItemId " + std::to_string(itemId) + " names no FeatureItem");
      fm.feature = item->second;
      if (const pugi::xml_node axis = child(m, "Axis")) {
        fm.location = r.vector3(axis, "AxisPoint");
        fm.direction = r.vector3(axis, "Direction");
      } else {
        fm.location = r.vector3(m, "Location");
        fm.direction = r.vector3(m, "Normal");
      }
      if (fm.location) *fm.location *= units.linear;
      if (const auto d = r.number(m, "Diameter")) fm.diameter = *d * units.linear;
      if (!measuredById.emplace(fm.id, part.features.size()).second)
        r.invalid(m, "duplicate id " + std::to_string(fm.id));
      part.features.push_back(std::move(fm));
    }
    for (const pugi::xml_node& m :
         elements(child(child(res, "MeasuredCharacteristics"), "CharacteristicMeasurements"))) {
      QifCharacteristicMeasurement cm;
      cm.id = r.id(m);
      cm.line = r.line(m);
      const long itemId = r.ref(m, "CharacteristicItemId");
      const auto it = charByItem.find(itemId);
      if (it == charByItem.end())
        r.invalid(m, Reader::named(m) + ": CharacteristicItemId " + std::to_string(itemId) +
                         " names no CharacteristicItem");
      cm.characteristic = it->second;
      const QifCharacteristic& c = file.characteristics[cm.characteristic];
      if (const auto v = r.number(m, "Value")) cm.value = *v * (c.angle ? units.angular : units.linear);
      cm.status = std::string(trimmed(child(child(m, "Status"), "CharacteristicStatusEnum").child_value()));
      for (const long id : r.refList(m, "FeatureMeasurementIds")) {
        const auto f = measuredById.find(id);
        if (f == measuredById.end())
          r.invalid(m, Reader::named(m) + ": FeatureMeasurementIds " + std::to_string(id) +
                           " names no FeatureMeasurement of MeasurementResults " +
                           std::to_string(part.resultsId));
        cm.measured.push_back(f->second);
      }
      part.characteristics.push_back(std::move(cm));
    }
    file.parts.push_back(std::move(part));
  }
  if (file.parts.empty()) r.invalid(results, "Results has no MeasurementResults");
  return file;
}

QifFile readQifFile(const std::string& path) {
  return qifFromText(readFile(path, 256u << 20), displayPath(path));
}

CmmTextReport qifCmmReport(const QifFile& file) {
  CmmTextReport r;
  r.format = CmmReportFormat::Qif;
  r.source = file.source;
  // The feature key of a characteristic measurement: the characteristic's Name; "#<item id>" added when
  // several characteristics share the Name; "@FEAT1+FEAT2" (the measured features) when one
  // characteristic is measured on several sets of features (a pattern), so every key is one series.
  using FeatureSet = std::vector<std::size_t>;
  std::map<std::size_t, std::set<FeatureSet>> setsOf;
  std::map<std::string, std::set<std::size_t>> byName;
  auto measuredFeatures = [&](const QifPart& part, const QifCharacteristicMeasurement& m) {
    FeatureSet s;
    for (const std::size_t k : m.measured) s.push_back(part.features[k].feature);
    return s;
  };
  for (const QifPart& part : file.parts)
    for (const QifCharacteristicMeasurement& m : part.characteristics) {
      setsOf[m.characteristic].insert(measuredFeatures(part, m));
      byName[file.characteristics[m.characteristic].name].insert(m.characteristic);
    }
  auto keyOf = [&](std::size_t ci, const FeatureSet& s) {
    const QifCharacteristic& c = file.characteristics[ci];
    std::string key = c.name.empty() ? "#" + std::to_string(c.itemId) : c.name;
    if (!c.name.empty() && byName[c.name].size() > 1) key += "#" + std::to_string(c.itemId);
    if (setsOf[ci].size() > 1) {
      key += "@";
      for (std::size_t k = 0; k < s.size(); ++k) key += (k ? "+" : "") + file.features[s[k]].name;
    }
    return key;
  };
  for (std::size_t p = 0; p < file.parts.size(); ++p) {
    const QifPart& part = file.parts[p];
    CmmRun run;
    run.number = static_cast<int>(p + 1);
    run.serial = part.serial;
    run.line = part.line;
    std::set<std::string> seen;
    for (const QifCharacteristicMeasurement& m : part.characteristics) {
      if (!m.value) continue;
      const QifCharacteristic& c = file.characteristics[m.characteristic];
      const FeatureSet s = measuredFeatures(part, m);
      const std::string key = keyOf(m.characteristic, s);
      if (!seen.insert(key).second) continue;  // a repeated measurement (point profiles: then 0)
      CmmFeature f;
      f.step = static_cast<int>(m.characteristic + 1);
      f.label = c.name;
      f.type = c.type;
      f.featureName = key;
      if (!s.empty()) f.featureType = file.features[s.front()].type;
      f.line = c.line;
      CmmValue v;
      v.name = "actual";
      v.nominal = c.nominalValue(file.features);
      v.actual = *m.value;
      v.lower = c.lowerLimit(file.features);
      v.upper = c.upperLimit(file.features);
      v.angle = c.angle;
      v.line = m.line;
      f.values.push_back(std::move(v));
      run.features.push_back(std::move(f));
    }
    if (!run.features.empty()) r.runs.push_back(std::move(run));
  }
  return r;
}

}  // namespace metrofit
