#include "core/kinematics/spc_actuator.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "core/common/numformat.h"
#include "core/common/run.h"
#include "core/io/dfq.h"

namespace metrofit {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kRoundingSigmaMm = 1e-9;  ///< residual sigma below any measuring resolution

std::string fmt(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

AxisFeatureFit fitFeature(const AxisFeatureSeries& f, const char* axis, const SpcActuatorOptions& o) {
  const ErrorContext where{f.source, 0, 0, {}};
  if (f.positionMm.size() != f.deviationMm.size()) {
    throw ValidationError(where, "has " + std::to_string(f.positionMm.size()) + " positions for " +
                                     std::to_string(f.deviationMm.size()) + " deviations");
  }
  if (f.positionMm.size() < 3) {
    throw ValidationError(where, std::string("the ") + axis + " feature has " +
                                     std::to_string(f.positionMm.size()) +
                                     " points, at least 3 are needed for a regression line with a scatter");
  }
  if (!std::isfinite(f.nominalCrossMm)) throw ValidationError(where, "nominal cross coordinate not finite");
  AxisFeatureFit fit;
  fit.source = f.source;
  fit.line = fitLine(f.positionMm, f.deviationMm, where);
  const double n = static_cast<double>(f.positionMm.size());
  double ubar = 0.0, dbar = 0.0;
  for (std::size_t i = 0; i < f.positionMm.size(); ++i) {
    ubar += f.positionMm[i] / n;
    dbar += f.deviationMm[i] / n;
  }
  double sxx = 0.0, sse = 0.0;
  std::vector<double> residuals(f.positionMm.size());
  for (std::size_t i = 0; i < f.positionMm.size(); ++i) {
    sxx += (f.positionMm[i] - ubar) * (f.positionMm[i] - ubar);
    residuals[i] = f.deviationMm[i] - (fit.line.intercept + fit.line.slope * f.positionMm[i]);
    sse += residuals[i] * residuals[i];
  }
  const double s2 = sse / (n - 2.0);
  fit.residualSigmaMm = std::sqrt(s2);
  fit.interceptStdErr = std::sqrt(s2 * (1.0 / n + ubar * ubar / sxx));
  fit.slopeSignificant = std::abs(fit.line.slope) > o.coverageFactor * fit.line.slopeStdErr;
  fit.interceptSignificant = std::abs(fit.line.intercept) > o.coverageFactor * fit.interceptStdErr;
  fit.systematicErrorMm = 0.0 - dbar;  // Eq. 20 with the desired deviation V = 0
  if (std::abs(fit.line.angleDeg) > ActuatorErrors2::kMaxAngleDeg) {
    throw ValidationError(where,
                          std::string("offset angle of the ") + axis + " feature " + fmt(fit.line.angleDeg) +
                              " deg is beyond +-45 deg: are the position and deviation columns swapped?");
  }
  if (fit.residualSigmaMm < kRoundingSigmaMm) {
    // Noise-free (simulated) edges: limits from rounding noise would flag rounding noise.
    fit.chartNote = "residuals at the rounding level (sigma below 1e-9 mm): not charted";
  } else if (residuals.size() >= 2 * static_cast<std::size_t>(o.subgroupSize)) {
    try {
      fit.residualChart = xbarRChart(residuals, o.subgroupSize, where);
    } catch (const ValidationError& e) {
      fit.chartNote = e.detail();
    }
  } else {
    fit.chartNote = "fewer than 2 subgroups of " + std::to_string(o.subgroupSize) + " residuals: not charted";
  }
  return fit;
}

nlohmann::json featureJson(const AxisFeatureFit& f, const AxisFeatureSeries& s) {
  nlohmann::json j = {{"source", f.source},
                      {"points", f.line.points},
                      {"slope", f.line.slope},
                      {"intercept", f.line.intercept},
                      {"r2", f.line.r2},
                      {"slope_std_err", f.line.slopeStdErr},
                      {"intercept_std_err", f.interceptStdErr},
                      {"offset_angle_deg", f.line.angleDeg},
                      {"slope_significant", f.slopeSignificant},
                      {"intercept_significant", f.interceptSignificant},
                      {"systematic_error_mm", f.systematicErrorMm},
                      {"residual_sigma_mm", f.residualSigmaMm},
                      {"nominal_cross_mm", s.nominalCrossMm}};
  if (f.residualChart) {
    j["residual_chart"] = {{"in_control", f.residualChart->inControl()},
                           {"subgroups", f.residualChart->subgroups()}};
  } else {
    j["chart_note"] = f.chartNote;
  }
  return j;
}

}  // namespace

AxisFeatureSeries axisFeatureFromCsv(const CsvTable& t, const std::string& positionColumn,
                                     const std::string& deviationColumn) {
  const std::size_t pc = t.requireColumn(positionColumn), dc = t.requireColumn(deviationColumn);
  AxisFeatureSeries s;
  s.source = t.source();
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    s.positionMm.push_back(t.number(r, pc));
    s.deviationMm.push_back(t.number(r, dc));
    s.lines.push_back(t.lineOf(r));
  }
  return s;
}

bool SpcActuatorOptions::isValid(std::string* why) const {
  // The residual chart is an X-bar/R chart: subgroups of 2..25 (the SPC options also take 1, for
  // individuals). The other checks (positive coverage factor) are the SPC options' own.
  if (subgroupSize < kMinSubgroupSize || subgroupSize > kMaxSubgroupSize) {
    if (why) {
      *why = "subgroup size must be between 2 and 25 (the range of the A2/D3/D4 table), got " +
             std::to_string(subgroupSize);
    }
    return false;
  }
  SpcOptions spc;
  spc.subgroupSize = subgroupSize;
  spc.coverageFactor = coverageFactor;
  return spc.isValid(why);
}

SpcActuatorResult actuatorErrorsFromSpc(const AxisFeatureSeries& xf, const AxisFeatureSeries& yf,
                                        const SpcActuatorOptions& o) {
  requireValid(o, "SPC to actuator options");
  SpcActuatorResult r;
  r.options = o;
  r.x = fitFeature(xf, "X", o);
  r.y = fitFeature(yf, "Y", o);

  const double sX = r.x.slopeSignificant ? r.x.line.slope : 0.0;
  const double sY = r.y.slopeSignificant ? r.y.line.slope : 0.0;
  const double cX = r.x.interceptSignificant ? r.x.line.intercept : 0.0;
  const double cY = r.y.interceptSignificant ? r.y.line.intercept : 0.0;
  const double a = std::atan(sX), b = -std::atan(sY);
  const double ta = std::tan(a), tb = std::tan(b);
  const double y0 = xf.nominalCrossMm, x0 = yf.nominalCrossMm;
  Eigen::Matrix2d A;
  A << -ta, 1.0, 1.0, tb;
  const Eigen::Vector2d rhs(cX - y0 * (std::cos(b) - 1.0) - ta * y0 * std::sin(b),
                            cY - x0 * (std::cos(a) - 1.0) - tb * x0 * std::sin(a));
  r.errors.originMm = A.partialPivLu().solve(rhs);
  r.errors.xAxisAngleDeg = a / kDeg;
  r.errors.yAxisAngleDeg = b / kDeg;

  std::string bad;
  for (const auto* f : {&r.x, &r.y}) {
    if (f->residualChart && !f->residualChart->inControl()) {
      bad += (bad.empty() ? "" : ", ") + f->source;
    }
  }
  if (!bad.empty()) {
    r.apply = false;
    r.reason = "not compensated: the residuals about the regression line are out of control (" + bad +
               "); remove the special causes first, a correction would chase them";
  } else if (!r.x.slopeSignificant && !r.y.slopeSignificant && !r.x.interceptSignificant &&
             !r.y.interceptSignificant) {
    r.apply = false;
    r.reason = "not compensated: no slope or intercept is beyond its interval (k = " + fmt(o.coverageFactor) +
               "): random scatter, not an actuator error";
  } else {
    r.apply = true;
    const int taken = int(r.x.slopeSignificant) + int(r.y.slopeSignificant) + int(r.x.interceptSignificant) +
                      int(r.y.interceptSignificant);
    const bool charted = r.x.residualChart && r.y.residualChart;
    r.reason = "compensate (Eq. 15): " + std::to_string(taken) +
               " of 4 line parameters beyond their interval (k = " + fmt(o.coverageFactor) + "), " +
               (charted ? std::string("residuals in control") : std::string("residuals not all charted"));
  }
  return r;
}

nlohmann::json spcActuatorResultToJson(const SpcActuatorResult& r, const AxisFeatureSeries& xf,
                                       const AxisFeatureSeries& yf) {
  nlohmann::json j;
  j["origin_mm"] = {r.errors.originMm.x(), r.errors.originMm.y()};
  j["x_axis_angle_deg"] = r.errors.xAxisAngleDeg;
  j["y_axis_angle_deg"] = r.errors.yAxisAngleDeg;
  j["squareness_deg"] = r.errors.squarenessDeg();
  j["features"] = {{"x", featureJson(r.x, xf)}, {"y", featureJson(r.y, yf)}};
  j["coverage_factor"] = r.options.coverageFactor;
  j["subgroup_size"] = r.options.subgroupSize;
  j["compensation"] = {{"apply", r.apply}, {"reason", r.reason}};
  j["model"] =
      "X feature: dev_y = c_X + tan(a) x_meas; Y feature: dev_x = c_Y - tan(b) y_meas; "
      "P = origin + x_cmd (cos a, sin a) + y_cmd (-sin b, cos b) (IEEE Access kinematic compensation paper, "
      "Eq. 9, compensation Eq. 15)";
  return j;
}

std::string edgesDfq(const AxisFeatureSeries& xFeature, const AxisFeatureSeries& yFeature,
                     const std::string& deviationColumn, const std::string& xName, const std::string& yName) {
  DfqPart part;
  part.number = "from-spc";
  part.description = "Edges machined along X (" + xName + ") and along Y (" + yName + ")";
  const AxisFeatureSeries* series[2] = {&xFeature, &yFeature};
  const char* names[2] = {"X edge", "Y edge"};
  for (int i = 0; i < 2; ++i) {
    DfqCharacteristic c;
    c.number = std::string(names[i]) + " " + deviationColumn;
    c.description = std::string(names[i]) + ": deviation across the axis (measured - nominal)";
    c.nominal = 0.0;
    c.unit = "mm";
    c.values = series[i]->deviationMm;
    part.characteristics.push_back(std::move(c));
  }
  return writeDfq(part);
}

}  // namespace metrofit
