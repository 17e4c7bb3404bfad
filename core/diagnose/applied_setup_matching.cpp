#include "core/diagnose/applied_setup_matching.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/diagnose/applied_entries.h"
#include "core/diagnose/matching_diagnosis.h"
#include "core/io/csv.h"
#include "core/project/project.h"

namespace metrofit::diagnose {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& field, const std::string& what) {
  throw ValidationError(ErrorContext{source, 0, 0, field}, what);
}

/// A finite numeric parameter of the entry.
double entryNumber(const nlohmann::json& entry, const char* key, const std::string& source,
                   const std::string& at) {
  const auto p = entry.find("parameters");
  if (p == entry.end()) fail(source, at + ".parameters", "is missing");
  if (!p->is_object()) fail(source, at + ".parameters", "must be an object {name: value}");
  const auto it = p->find(key);
  if (it == p->end()) fail(source, at + ".parameters." + key, "is missing");
  if (!it->is_number() || !std::isfinite(it->get<double>()))
    fail(source, at + ".parameters." + key, "must be a finite number");
  return it->get<double>();
}

std::string fmt(const char* f, double v) {
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

std::string appliedField(const std::string& domain) {
  return std::string("studies.") + study::kDiagnosis + "." + domain + ".applied";
}

nlohmann::json projectAppliedEffects(const Project& project, const std::string& domain,
                                     const std::string& datasetId, const std::string& source) {
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object()) return nlohmann::json::array();
  const auto d = s->find(domain);
  if (d == s->end() || !d->is_object()) return nlohmann::json::array();
  const auto a = d->find("applied");
  if (a == d->end() || !isAppliedList(*a, appliedField(domain), appliedMessagesOf(source)))
    return nlohmann::json::array();
  // Estimated on the diagnosis's dataset: another dataset keeps the declared model.
  if (d->value("dataset", nlohmann::json()) != nlohmann::json(datasetId)) return nlohmann::json::array();
  return *a;
}

std::string appliedEffectsElsewhere(const Project& project, const std::string& domain,
                                    const std::string& datasetId) {
  const auto s = project.studies.find(study::kDiagnosis);
  if (s == project.studies.end() || !s->is_object()) return {};
  const auto d = s->find(domain);
  if (d == s->end() || !d->is_object()) return {};
  const auto a = d->find("applied");
  if (a == d->end() || !a->is_array() || a->empty()) return {};
  const auto dataset = d->find("dataset");
  if (dataset == d->end() || !dataset->is_string() || dataset->get<std::string>() == datasetId) return {};
  return dataset->get<std::string>();
}

// ---- setup ----

std::vector<AppliedSetupEffect> parseAppliedSetupEffects(const nlohmann::json& applied,
                                                         const setup::Model& model, const std::string& source,
                                                         const std::string& field) {
  std::vector<AppliedSetupEffect> out;
  std::set<std::string> seen;
  forEachAppliedEntry(applied, field, appliedMessagesOf(source), [&](const AppliedEntry& entry) {
    const std::string& at = entry.field;
    const std::string& name = entry.name;
    AppliedSetupEffect e;
    e.name = name;
    std::string datum;
    if (name.rfind("unexplained:", 0) == 0) {
      if (!seen.insert(name).second) fail(source, at + ".name", "'" + name + "' is applied twice");
      GenericForm shape = genericShapeOf(entry, source);
      if (!setupGenericPredictsNextPart(shape.against))
        fail(source, at + ".name",
             "'" + name +
                 "' cannot be applied: it says nothing about the next part (only unexplained:time, "
                 "unexplained:datum:<id> and unexplained:dimension:<id> can)");
      if (shape.against.rfind("datum:", 0) == 0) {
        const int index = model.setupIndex(shape.against.substr(6));
        if (index < 0)
          fail(source, at + ".name",
               "'" + name + "': the model has no setup datum '" + shape.against.substr(6) + "'");
        e.datum = static_cast<std::size_t>(index);
      } else if (shape.against.rfind("dimension:", 0) == 0) {
        const std::string id = shape.against.substr(10);
        for (std::size_t q = 0; q < model.dimensions.size(); ++q)
          if (model.dimensions[q].id == id) e.dimension = q;
        if (!e.dimension)
          fail(source, at + ".name", "'" + name + "': the model has no dimension '" + id + "'");
      } else {
        e.perPart = false;  // time
      }
      const auto c = entry.json.find("coefficients");
      if (c == entry.json.end() || !c->is_array())
        fail(source, at + ".coefficients", "'" + name + "' needs its coefficients (mm), a list of numbers");
      for (const auto& x : *c) {
        if (!x.is_number() || !std::isfinite(x.get<double>()))
          fail(source, at + ".coefficients", "must be finite numbers (mm)");
        e.coefficients.push_back(x.get<double>());
      }
      if (static_cast<Eigen::Index>(e.coefficients.size()) != genericBasis(shape, {1.0}).cols())
        fail(source, at + ".coefficients",
             "must be one per column of the shape's basis (" +
                 std::to_string(genericBasis(shape, {1.0}).cols()) + "), got " +
                 std::to_string(e.coefficients.size()));
      e.shape = std::move(shape);
      out.push_back(std::move(e));
      return;
    }
    if (name.rfind("tool_wear:", 0) == 0) {
      e.perPart = true;
      datum = name.substr(10);
    } else if (name.rfind("drift:", 0) == 0) {
      e.perPart = false;
      datum = name.substr(6);
    } else {
      fail(source, at + ".name",
           "'" + name +
               "' is not a setup effect (tool_wear:<tool>, drift:<setup datum> or unexplained:<variable>)");
    }
    if (datum.empty()) fail(source, at + ".name", "'" + name + "' names no setup datum");
    const int index = model.setupIndex(datum);
    if (index < 0) fail(source, at + ".name", "'" + name + "': the model has no setup datum '" + datum + "'");
    if (e.perPart && model.setup[static_cast<std::size_t>(index)].kind != setup::DatumKind::Tool)
      fail(source, at + ".name", "'" + name + "': '" + datum + "' is not a tool");
    if (!seen.insert(name).second) fail(source, at + ".name", "'" + name + "' is applied twice");
    e.datum = static_cast<std::size_t>(index);
    e.rate = entryNumber(entry.json, e.perPart ? "mm_per_part" : "mm_per_min", source, at);
    out.push_back(std::move(e));
  });
  return out;
}

bool setupGenericPredictsNextPart(const std::string& against) {
  return against == "time" || (against.rfind("datum:", 0) == 0 && against.size() > 6) ||
         (against.rfind("dimension:", 0) == 0 && against.size() > 10);
}

std::string describe(const AppliedSetupEffect& e) {
  if (e.shape) return e.name + " (" + formName(e.shape->form) + ")";
  return e.name + (e.perPart ? fmt(" (%.4g mm/part)", e.rate) : fmt(" (%.4g mm/min)", e.rate));
}

std::string describe(const std::vector<AppliedSetupEffect>& effects) {
  std::string out;
  for (const AppliedSetupEffect& e : effects) out += (out.empty() ? "" : ", ") + describe(e);
  return out;
}

SetupPrediction predictSetupDeviations(const setup::Model& model, const setup::Measurements& m,
                                       const std::vector<AppliedSetupEffect>& effects) {
  const std::string source = m.sources.empty() ? std::string() : m.sources.front();
  const Eigen::MatrixXd G = setup::gainMatrix(model);
  const std::size_t nq = model.dimensions.size();
  // Part numbers as setup_diagnosis.h: the numbers of the "part" column, else 1, 2, ... in order.
  std::map<std::string, double> partNumber;
  bool numeric = true;
  for (const std::string& part : m.parts) {
    double v = 0.0;
    if (!parseNumber(part, &v) || !std::isfinite(v)) numeric = false;
    partNumber[part] = v;
  }
  if (!numeric)
    for (std::size_t i = 0; i < m.parts.size(); ++i) partNumber[m.parts[i]] = static_cast<double>(i + 1);
  std::map<double, std::pair<double, int>> partTime;  // part number -> (time sum, rows)
  for (const setup::Measurements::Row& row : m.rows) {
    auto& t = partTime[partNumber[row.part]];
    t.first += row.timeMin;
    ++t.second;
  }
  SetupPrediction out;
  out.rows = m.rows.size();
  out.parts = partTime.size();
  if (partTime.empty()) fail(source, {}, "the report has no rows");
  const double firstPart = partTime.begin()->first, lastPart = partTime.rbegin()->first;
  const double firstTime = partTime.begin()->second.first / partTime.begin()->second.second;
  const double lastTime = partTime.rbegin()->second.first / partTime.rbegin()->second.second;
  out.nextPart = lastPart + 1.0;
  out.nextTimeMin =
      lastTime +
      (partTime.size() > 1 ? (lastTime - firstTime) / static_cast<double>(partTime.size() - 1) : 0.0);
  (void)firstPart;

  // The effects' contribution to dimension q at part number p and time t.
  auto effect = [&](std::size_t q, double p, double t) {
    double s = 0.0;
    for (const AppliedSetupEffect& e : effects) {
      const double gain = G(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(e.datum));
      if (!e.shape) {
        s += gain * e.rate * (e.perPart ? p : t);
        continue;
      }
      if (e.dimension && *e.dimension != q) continue;
      const Eigen::RowVectorXd b = genericBasis(*e.shape, {e.perPart ? p : t}).row(0);
      const double f = b.dot(Eigen::Map<const Eigen::VectorXd>(e.coefficients.data(), b.size()));
      s += (e.shape->against.rfind("datum:", 0) == 0 ? gain : 1.0) * f;
    }
    return s;
  };
  // Constant parts, over all rows and over the rows of every part but the last.
  std::vector<double> sum(nq, 0.0), sumHeld(nq, 0.0);
  std::vector<int> count(nq, 0), countHeld(nq, 0);
  for (const setup::Measurements::Row& row : m.rows) {
    if (row.dimension >= nq)
      fail(row.source, "dimension", "the report does not belong to the model (dimension index out of range)");
    const double p = partNumber[row.part];
    const double c = row.deviationMm - effect(row.dimension, p, row.timeMin);
    sum[row.dimension] += c;
    ++count[row.dimension];
    if (p != lastPart) {
      sumHeld[row.dimension] += c;
      ++countHeld[row.dimension];
    }
  }
  std::vector<double> constant(nq, 0.0);
  for (std::size_t q = 0; q < nq; ++q) {
    if (count[q] == 0)
      fail(model.source, "dimensions[" + std::to_string(q) + "]",
           "dimension '" + model.dimensions[q].id + "' has no measurement in the report");
    constant[q] = sum[q] / count[q];
    out.deviationMm.push_back(constant[q] + effect(q, out.nextPart, out.nextTimeMin));
  }
  double ss = 0.0, ssNext = 0.0;
  int nNext = 0;
  for (const setup::Measurements::Row& row : m.rows) {
    const double p = partNumber[row.part];
    const double r = row.deviationMm - constant[row.dimension] - effect(row.dimension, p, row.timeMin);
    ss += r * r;
    out.maxAbsMm = std::max(out.maxAbsMm, std::abs(r));
    if (p == lastPart && countHeld[row.dimension] > 0) {
      const double c = sumHeld[row.dimension] / countHeld[row.dimension];
      const double e = row.deviationMm - c - effect(row.dimension, p, row.timeMin);
      ssNext += e * e;
      ++nNext;
    }
  }
  out.rmseMm = m.rows.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(m.rows.size()));
  if (partTime.size() > 1 && nNext > 0) out.nextPartRmseMm = std::sqrt(ssNext / nNext);
  return out;
}

SetupPrediction applySetupEffects(const setup::Model& model, setup::Measurements& measurements,
                                  const std::vector<AppliedSetupEffect>& effects) {
  SetupPrediction p = predictSetupDeviations(model, measurements, effects);
  if (!effects.empty()) measurements.deviationMm = p.deviationMm;
  return p;
}

// ---- matching ----

std::string AppliedMatchingEffects::describe() const {
  std::string out;
  for (const std::string& d : descriptions) out += (out.empty() ? "" : ", ") + d;
  return out;
}

AppliedMatchingEffects parseAppliedMatchingEffects(const nlohmann::json& applied, const std::string& source,
                                                   const std::string& field) {
  AppliedMatchingEffects out;
  std::set<std::string> seen;
  forEachAppliedEntry(applied, field, appliedMessagesOf(source), [&](const AppliedEntry& entry) {
    const std::string& at = entry.field;
    const std::string& name = entry.name;
    if (!seen.insert(name).second) fail(source, at + ".name", "'" + name + "' is applied twice");
    if (name == "scale") {
      out.effects.scalePpm = entryNumber(entry.json, "ppm", source, at);
      out.descriptions.push_back(fmt("scale (%+.4g ppm)", out.effects.scalePpm));
    } else if (name == "distortion") {
      out.effects.distortionPpm = entryNumber(entry.json, "ppm", source, at);
      out.effects.distortionAngleDeg = entryNumber(entry.json, "angle_deg", source, at);
      out.descriptions.push_back(fmt("distortion (%.4g ppm", out.effects.distortionPpm) +
                                 fmt(" at %.3g deg)", out.effects.distortionAngleDeg));
    } else if (name.rfind("surface_offset:", 0) == 0) {
      const std::string surface = name.substr(15);
      const double mm = entryNumber(entry.json, "mm", source, at);
      out.effects.surfaceOffsetsMm.emplace_back(surface, mm);
      out.surfaceEntry.push_back(entry.index);
      out.descriptions.push_back(name + fmt(" (%+.4g mm)", mm));
    } else if (name.starts_with("unexplained:")) {
      AppliedMatchingGeneric g;
      g.shape = genericShapeOf(entry, source);
      g.entry = entry.index;
      const auto c = entry.json.find("coefficients");
      if (c == entry.json.end() || !c->is_array() || c->empty())
        fail(source, at + ".coefficients", "'" + name + "' needs its coefficients (mm), a list of numbers");
      for (const auto& x : *c) {
        if (!x.is_number() || !std::isfinite(x.get<double>()))
          fail(source, at + ".coefficients", "must be finite numbers (mm)");
        g.coefficients.push_back(x.get<double>());
      }
      out.descriptions.push_back(name + " (" + formName(g.shape.form) + ")");
      out.generic.push_back(std::move(g));
    } else {
      fail(source, at + ".name",
           "'" + name +
               "' is not a matching effect (scale, surface_offset:<surface>, distortion or "
               "unexplained:<variable>)");
    }
    out.names.push_back(name);
  });
  return out;
}

ProbePointSet applyMatchingEffects(const ProbePointSet& set, const AppliedMatchingEffects& applied,
                                   const std::string& source, const std::string& field) {
  if (applied.empty() || set.points.empty()) return set;
  std::set<std::string> surfaces;
  for (const ProbePoint& p : set.points) surfaces.insert(p.surface);
  for (std::size_t k = 0; k < applied.effects.surfaceOffsetsMm.size(); ++k) {
    const std::string& surface = applied.effects.surfaceOffsetsMm[k].first;
    const std::string at =
        appliedEntryField(field, k < applied.surfaceEntry.size() ? applied.surfaceEntry[k] : 0, "name");
    if (!set.hasNormals) fail(source, at, "surface_offset:" + surface + ": the probe points have no normals");
    if (!surfaces.count(surface))
      fail(source, at, "surface_offset:" + surface + ": the probe points have no surface '" + surface + "'");
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const ProbePoint& p : set.points) centroid += p.nominal;
  centroid /= static_cast<double>(set.points.size());
  ProbePointSet out = set;
  for (ProbePoint& p : out.points) {
    ProbePoint centred = p;
    centred.nominal -= centroid;  // scale and distortion about the centroid, as the diagnosis fits them
    Eigen::Vector3d d = effectDisplacement(applied.effects, centred);
    if (set.planar) d.z() = 0.0;
    p.nominal += d;
  }
  for (const AppliedMatchingGeneric& g : applied.generic) {
    const std::vector<Eigen::Vector3d> d = matchingGenericDisplacement(set, g.shape, g.coefficients);
    if (d.size() != set.points.size())
      fail(source, appliedEntryField(field, g.entry, "name"),
           "unexplained:" + g.shape.against + ": the probe points have no variable '" + g.shape.against +
               "', or the coefficients are not one per column of its shape");
    for (std::size_t i = 0; i < d.size(); ++i)
      out.points[i].nominal += set.planar ? Eigen::Vector3d(d[i].x(), d[i].y(), 0.0) : d[i];
  }
  return out;
}

}  // namespace metrofit::diagnose
