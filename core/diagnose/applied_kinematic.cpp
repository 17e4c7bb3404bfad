#include "core/diagnose/applied_kinematic.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/common/error.h"
#include "core/diagnose/applied_entries.h"
#include "core/diagnose/kinematic_diagnosis.h"
#include "core/io/csv.h"
#include "core/kinematics/path_variables.h"

namespace metrofit {
namespace {

using diagnose::AppliedEntry;
using diagnose::AppliedEntryMessages;
using diagnose::appliedMessagesKnown;
using diagnose::forEachAppliedEntry;
using diagnose::isAppliedList;

std::string num(double v) {
  return CsvWriter::formatNumber(v, 3);
}

}  // namespace

std::string AxisEffects::text() const {
  std::string s;
  for (const auto& l : labels) s += (s.empty() ? "" : ", ") + l;
  return s;
}

Eigen::Vector2d AxisEffects::effectiveJoints(const Eigen::Vector2d& c, const Eigen::Vector2d& d,
                                             const Eigen::Vector2d& t) const {
  Eigen::Vector2d e = base.effectiveJoints(c, d, t);
  for (const CyclicTerm& y : cyclic)
    e(y.axis) += y.amplitudeMm * std::sin(2.0 * std::numbers::pi * c(y.axis) / y.periodMm +
                                          y.phaseDeg * std::numbers::pi / 180.0);
  return e;
}

std::vector<Eigen::Vector2d> AxisEffects::displacement(const std::vector<Eigen::Vector2d>& commands) const {
  std::vector<Eigen::Vector2d> out(commands.size(), Eigen::Vector2d::Zero());
  if (generic.empty() || commands.empty()) return out;
  const PathVariables v = pathVariables(commands);
  for (const GenericDisplacement& g : generic) {
    const std::vector<double>* values = v.find(g.shape.against);  // checked when read
    if (!values) continue;
    std::vector<double> twice;  // x and y of every point (the basis' two components)
    twice.reserve(2 * values->size());
    for (double x : *values) twice.insert(twice.end(), {x, x});
    const Eigen::MatrixXd B = diagnose::genericBasis(g.shape, twice);
    const Eigen::VectorXd d =
        B * Eigen::Map<const Eigen::VectorXd>(g.coefficients.data(),
                                              static_cast<Eigen::Index>(g.coefficients.size()));
    for (std::size_t k = 0; k < commands.size(); ++k)
      out[k] += Eigen::Vector2d(d(static_cast<Eigen::Index>(2 * k)), d(static_cast<Eigen::Index>(2 * k + 1)));
  }
  return out;
}

AxisEffects axisEffectsFromApplied(const nlohmann::json& applied, double feedMmPerMin,
                                   const std::string& field) {
  AxisEffects out;
  out.base.feedMmPerMin = feedMmPerMin;
  static const std::string kKnown = "backlash, scale, cyclic, servo_lag, unexplained:<variable>";
  const AppliedEntryMessages messages = appliedMessagesKnown(kKnown);
  if (!isAppliedList(applied, field, messages)) return out;
  if (!(feedMmPerMin > 0.0) || !std::isfinite(feedMmPerMin))
    throw ValidationError(ErrorContext{{}, 0, 0, "studies.diagnosis.kinematic.feed_mm_per_min"},
                          "must be a positive feed (mm/min)");
  std::vector<std::string> seen;
  forEachAppliedEntry(applied, field, messages, [&](const AppliedEntry& entry) {
    const nlohmann::json& e = entry.json;
    const std::string& name = entry.name;
    const ErrorContext where{{}, 0, 0, entry.at("name")};
    const nlohmann::json params =
        e.contains("parameters") && e["parameters"].is_object() ? e["parameters"] : nlohmann::json::object();
    auto number = [&](const std::string& key, std::optional<double> fallback = std::nullopt) {
      const auto it = params.find(key);
      if (it == params.end() && fallback) return *fallback;
      if (it == params.end() || !it->is_number() || !std::isfinite(it->get<double>()))
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("parameters." + key)},
                              "'" + name + "' needs a finite number here");
      return it->get<double>();
    };
    std::string key = name;
    if (name == "backlash") {
      out.base.backlashXMm = number("x_mm");
      out.base.backlashYMm = number("y_mm");
      out.labels.push_back("backlash (x " + num(out.base.backlashXMm * 1000.0) + " um, y " +
                           num(out.base.backlashYMm * 1000.0) + " um)");
    } else if (name == "scale") {
      out.base.scaleXPpm = number("x_ppm");
      out.base.scaleYPpm = number("y_ppm");
      out.labels.push_back("scale (x " + num(out.base.scaleXPpm) + " ppm, y " + num(out.base.scaleYPpm) +
                           " ppm)");
    } else if (name == "servo_lag") {
      out.base.servoLagS = number("tau_s");
      out.labels.push_back("servo_lag (" + num(out.base.servoLagS) + " s at " + num(feedMmPerMin) +
                           " mm/min)");
    } else if (name == "cyclic") {
      CyclicTerm y;
      const auto axis = params.find("axis");
      if (axis == params.end() || !axis->is_string() || (*axis != "x" && *axis != "y"))
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("parameters.axis")},
                              "'cyclic' needs the axis \"x\" or \"y\"");
      y.axis = *axis == "x" ? 0 : 1;
      y.periodMm = number("period_mm");
      if (!(y.periodMm > 0.0))
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("parameters.period_mm")},
                              "'cyclic' needs a positive period (mm)");
      y.amplitudeMm = number("amplitude_mm");
      y.phaseDeg = number("phase_deg", 0.0);
      key = "cyclic:" + axis->get<std::string>();
      out.cyclic.push_back(y);
      out.labels.push_back("cyclic (" + axis->get<std::string>() + ", period " + num(y.periodMm) +
                           " mm, amplitude " + num(y.amplitudeMm * 1000.0) + " um)");
    } else if (name.starts_with("unexplained:")) {
      GenericDisplacement g;
      g.shape = diagnose::genericShapeOf(entry);
      if (!PathVariables{}.find(g.shape.against))
        throw ValidationError(where, "'" + name + "': a circular test has no variable '" + g.shape.against +
                                         "' (row, angle, direction, reversal, x, y)");
      if (g.shape.components != 2)
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("shape.components")},
                              "a circular test has two coordinates (components 2)");
      const auto columns = diagnose::genericBasis(g.shape, {0.0, 0.0}).cols();
      const auto c = e.find("coefficients");
      if (c == e.end() || !c->is_array() || static_cast<Eigen::Index>(c->size()) != columns)
        throw ValidationError(ErrorContext{{}, 0, 0, entry.at("coefficients")},
                              "'" + name + "' needs " + std::to_string(columns) +
                                  " coefficients (mm), one per column of its shape's basis");
      for (const auto& x : *c) {
        if (!x.is_number() || !std::isfinite(x.get<double>()))
          throw ValidationError(ErrorContext{{}, 0, 0, entry.at("coefficients")},
                                "must be finite numbers (mm)");
        g.coefficients.push_back(x.get<double>());
      }
      out.labels.push_back(name + " (" + diagnose::formName(g.shape.form) + ")");
      out.generic.push_back(std::move(g));
    } else {
      throw ValidationError(where, "unknown kinematic effect '" + name + "' (known: " + kKnown + ")");
    }
    if (std::find(seen.begin(), seen.end(), key) != seen.end())
      throw ValidationError(where, "the effect '" + key + "' is applied twice");
    seen.push_back(key);
  });
  return out;
}

MeasuredPath withEffectiveJoints(const MeasuredPath& path, const AxisEffects& effects) {
  MeasuredPath out = path;
  if (effects.empty()) return out;
  const PathMotion motion = pathMotion(path.command);
  const std::vector<Eigen::Vector2d> shift = effects.displacement(path.command);
  for (std::size_t k = 0; k < path.size(); ++k) {
    out.command[k] = effects.effectiveJoints(path.command[k], motion.direction[k], motion.tangent[k]);
    out.measured[k] -= shift[k];
  }
  return out;
}

std::vector<Eigen::Vector2d> runPathWithEffects(const CartesianMachine2& machine, const AxisEffects& effects,
                                                const std::vector<Eigen::Vector2d>& commands,
                                                const std::vector<Eigen::Vector2d>& motionOf) {
  std::vector<Eigen::Vector2d> out;
  if (commands.empty()) return out;
  const std::vector<Eigen::Vector2d>& along = motionOf.empty() ? commands : motionOf;
  const PathMotion motion = pathMotion(along);
  const std::vector<Eigen::Vector2d> shift = effects.displacement(along);
  out.reserve(commands.size());
  for (std::size_t k = 0; k < commands.size(); ++k) {
    const std::size_t m = std::min(k, motion.direction.size() - 1);
    out.push_back(
        machine.forward(effects.effectiveJoints(commands[k], motion.direction[m], motion.tangent[m])) +
        shift[m]);
  }
  return out;
}

std::vector<Eigen::Vector2d> compensatePathWithEffects(const CartesianMachine2& machine,
                                                       const AxisEffects& effects,
                                                       const std::vector<Eigen::Vector2d>& nominal) {
  if (effects.empty()) return compensatePath(machine, nominal);
  // The joint targets q: the machine must reach N_k - D_k so that the displacement D_k lands on N_k.
  std::vector<Eigen::Vector2d> aim = nominal;
  const std::vector<Eigen::Vector2d> shift = effects.displacement(nominal);
  for (std::size_t k = 0; k < aim.size(); ++k) aim[k] -= shift[k];
  std::vector<Eigen::Vector2d> refs = compensatePath(machine, aim);
  const PathMotion motion = pathMotion(nominal);
  for (std::size_t k = 0; k < refs.size(); ++k) {
    const Eigen::Vector2d q = refs[k];
    Eigen::Vector2d r = q;
    for (int it = 0; it < 100; ++it) {
      const Eigen::Vector2d step = q - effects.effectiveJoints(r, motion.direction[k], motion.tangent[k]);
      r += step;
      if (step.norm() <= 1e-13 * (1.0 + q.norm())) break;
    }
    refs[k] = r;
  }
  return refs;
}

}  // namespace metrofit
