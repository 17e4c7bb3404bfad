#include "core/diagnose/applied_entries.h"

#include <cmath>

#include "core/common/error.h"

namespace metrofit::diagnose {
namespace {

[[noreturn]] void fail(const AppliedEntryMessages& m, const std::string& field, const std::string& what) {
  throw ValidationError(ErrorContext{m.source, 0, 0, field}, what);
}

}  // namespace

AppliedEntryMessages appliedMessagesKnown(const std::string& known) {
  AppliedEntryMessages m;
  m.notList = "must be a list of {\"name\", \"parameters\"}";
  m.notObject = "must be an object {\"name\", \"parameters\"}";
  m.nameMissing = m.nameInvalid = "must be the effect's name (" + known + ")";
  return m;
}

AppliedEntryMessages appliedMessagesOf(const std::string& source) {
  AppliedEntryMessages m;
  m.source = source;
  m.notList = "must be a list of effects";
  m.notObject = "must be an object {\"name\": ..., \"parameters\": {...}}";
  m.nameMissing = "is missing";
  m.nameInvalid = "must be the name of an effect (text)";
  m.rejectEmptyName = true;
  return m;
}

std::string appliedEntryField(const std::string& field, std::size_t i, const std::string& key) {
  std::string f = field + "[" + std::to_string(i) + "]";
  return key.empty() ? f : f + "." + key;
}

bool isAppliedList(const nlohmann::json& applied, const std::string& field,
                   const AppliedEntryMessages& messages) {
  if (applied.is_null()) return false;
  if (!applied.is_array()) fail(messages, field, messages.notList);
  return true;
}

void forEachAppliedEntry(const nlohmann::json& applied, const std::string& field,
                         const AppliedEntryMessages& messages,
                         const std::function<void(const AppliedEntry&)>& fn) {
  if (!isAppliedList(applied, field, messages)) return;
  for (std::size_t i = 0; i < applied.size(); ++i) {
    const nlohmann::json& e = applied[i];
    const std::string at = appliedEntryField(field, i);
    if (!e.is_object()) fail(messages, at, messages.notObject);
    const auto it = e.find("name");
    if (it == e.end()) fail(messages, at + ".name", messages.nameMissing);
    if (!it->is_string() || (messages.rejectEmptyName && it->get<std::string>().empty()))
      fail(messages, at + ".name", messages.nameInvalid);
    fn(AppliedEntry{i, e, it->get<std::string>(), at});
  }
}

nlohmann::json genericShapeJson(const GenericForm& f) {
  nlohmann::json j = {
      {"against", f.against},      {"form", formName(f.form)}, {"knots", f.knots},
      {"harmonics", f.harmonics},  {"levels", f.levels},       {"centre", f.centre},
      {"scale", f.scale},          {"subset", f.subset},       {"without_linear", f.withoutLinear},
      {"components", f.components}};
  if (!f.projectedOff.empty()) j["projected_off"] = f.projectedOff;
  if (f.period > 0.0) j["period"] = f.period;
  return j;
}

GenericForm genericShapeOf(const AppliedEntry& entry, const std::string& source) {
  static const std::string kPrefix = "unexplained:";
  const auto fail = [&](const std::string& key, const std::string& what) -> void {
    throw ValidationError(ErrorContext{source, 0, 0, entry.at(key.empty() ? "shape" : "shape." + key)}, what);
  };
  const auto it = entry.json.find("shape");
  if (it == entry.json.end() || !it->is_object())
    fail("", "'" + entry.name + "' needs its shape (the form the diagnosis fitted), an object");
  const nlohmann::json& s = *it;
  const auto number = [&](const char* key, double fallback) {
    const auto k = s.find(key);
    if (k == s.end()) return fallback;
    if (!k->is_number() || !std::isfinite(k->get<double>())) fail(key, "must be a finite number");
    return k->get<double>();
  };
  const auto integer = [&](const char* key, int lo, int hi) {
    const auto k = s.find(key);
    if (k == s.end()) return lo;
    if (!k->is_number_integer() || k->get<long long>() < lo || k->get<long long>() > hi)
      fail(key, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    return static_cast<int>(k->get<long long>());
  };
  const auto flag = [&](const char* key) {
    const auto k = s.find(key);
    if (k == s.end()) return false;
    if (!k->is_boolean()) fail(key, "must be true or false");
    return k->get<bool>();
  };
  GenericForm f;
  const auto against = s.find("against");
  if (against == s.end() || !against->is_string()) fail("against", "must be the variable's name (text)");
  f.against = against->get<std::string>();
  if (!entry.name.starts_with(kPrefix) || entry.name.substr(kPrefix.size()) != f.against)
    fail("against", "'" + f.against + "' is not the variable of '" + entry.name + "'");
  const auto form = s.find("form");
  const std::string formText = form != s.end() && form->is_string() ? form->get<std::string>() : "";
  bool known = false;
  for (DependenceForm d : {DependenceForm::Linear, DependenceForm::Smooth, DependenceForm::Step,
                           DependenceForm::Periodic, DependenceForm::Level})
    if (formText == formName(d)) {
      f.form = d;
      known = true;
    }
  if (!known) fail("form", "must be linear, smooth, step, periodic or level");
  if (const auto k = s.find("knots"); k != s.end()) {
    if (!k->is_array()) fail("knots", "must be a list of numbers");
    for (const auto& v : *k) {
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        fail("knots", "must be a list of finite numbers");
      if (!f.knots.empty() && !(v.get<double>() > f.knots.back())) fail("knots", "must be increasing");
      f.knots.push_back(v.get<double>());
    }
  }
  if (f.form == DependenceForm::Smooth && f.knots.size() < 2)
    fail("knots", "a smooth form needs two knots or more");
  if (f.form == DependenceForm::Step && f.knots.size() != 1)
    fail("knots", "a step needs its change point (one knot)");
  f.harmonics = integer("harmonics", 0, 50);
  if (f.form == DependenceForm::Periodic && f.harmonics < 1)
    fail("harmonics", "a periodic form needs 1 harmonic or more");
  f.period = number("period", 0.0);
  if (f.period < 0.0 || (f.period > 0.0 && f.form != DependenceForm::Periodic))
    fail("period", "must be a positive number (the period of a periodic form)");
  f.levels = integer("levels", 0, 100000);
  if (f.form == DependenceForm::Level && f.levels < 2) fail("levels", "a level form needs 2 levels or more");
  f.centre = number("centre", 0.0);
  f.scale = number("scale", 1.0);
  if (!(f.scale > 0.0)) fail("scale", "must be positive");
  f.subset = flag("subset");
  f.withoutLinear = flag("without_linear");
  f.components = integer("components", 1, 3);
  if (const auto k = s.find("projected_off"); k != s.end()) {
    if (!k->is_array()) fail("projected_off", "must be a list of effect names");
    for (const auto& v : *k) {
      if (!v.is_string()) fail("projected_off", "must be a list of effect names (text)");
      f.projectedOff.push_back(v.get<std::string>());
    }
  }
  return f;
}

}  // namespace metrofit::diagnose
