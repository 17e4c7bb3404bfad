#include "core/spc/spc.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <nlohmann/json.hpp>

#include "core/common/numformat.h"
#include "core/common/run.h"

namespace metrofit {
namespace {

std::string fmt(double v) {
  char buf[32];
  metrofit::c_snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string indexList(const std::vector<std::size_t>& idx) {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(idx.size(), 8);
  for (std::size_t i = 0; i < shown; ++i) out += (i ? ", " : "") + std::to_string(idx[i] + 1);
  if (idx.size() > shown) out += ", ...";
  return out;
}

nlohmann::json indices1(const std::vector<std::size_t>& idx) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto i : idx) a.push_back(i + 1);
  return a;
}

}  // namespace

bool SpcOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (subgroupSize < 1 || subgroupSize > kMaxSubgroupSize) {
    return no(
        "subgroup size must be between 1 (individuals and moving range) and 25 (the range of the A2/D3/D4 "
        "table), got " +
        std::to_string(subgroupSize));
  }
  if (baseSubgroups == 1) return no("the base of the control limits must be 2 or more subgroups, got 1");
  if (lsl.has_value() != usl.has_value())
    return no("give both specification limits (LSL and USL) or neither");
  if (lsl && (!std::isfinite(*lsl) || !std::isfinite(*usl))) return no("specification limits must be finite");
  if (lsl && !(*lsl < *usl)) return no("LSL " + fmt(*lsl) + " must be below USL " + fmt(*usl));
  if (nominal && !std::isfinite(*nominal)) return no("nominal must be finite");
  if (!(coverageFactor > 0.0) || !std::isfinite(coverageFactor))
    return no("coverage factor must be positive");
  if (!(minCorrection >= 0.0) || !std::isfinite(minCorrection)) return no("smallest correction must be >= 0");
  return true;
}

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y, const ErrorContext& where) {
  if (x.size() != y.size()) {
    throw ValidationError(
        where, "has " + std::to_string(x.size()) + " x values for " + std::to_string(y.size()) + " y values");
  }
  if (x.size() < 2) throw ValidationError(where, "at least 2 points are needed for a regression line");
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw ValidationError(where, "point " + std::to_string(i + 1) + " is not finite");
    }
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0)) throw ValidationError(where, "all x values are equal: no regression line");
  LineFit f;
  f.points = x.size();
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  const double sse = std::max(0.0, syy - f.slope * sxy);
  f.r2 = syy > 0.0 ? std::clamp(1.0 - sse / syy, 0.0, 1.0) : 0.0;
  f.slopeStdErr = x.size() > 2 ? std::sqrt(sse / (n - 2.0) / sxx) : 0.0;
  f.angleDeg = std::atan(f.slope) * 180.0 / std::numbers::pi;
  return f;
}

Capability capability(const XbarRChart& chart, const std::vector<double>& used, const SpcOptions& o) {
  const ControlChartConstants& c = controlChartConstants(chart.rangeSpan());
  Capability cap;
  cap.sigmaWithin = chart.meanRange / c.d2;
  double ss = 0.0;
  for (const double v : used) ss += (v - chart.meanOfAll) * (v - chart.meanOfAll);
  cap.sigmaOverall = used.size() > 1 ? std::sqrt(ss / static_cast<double>(used.size() - 1)) : 0.0;
  cap.naturalTolerance =
      (chart.xbarUcl - chart.xbarLcl) * std::sqrt(static_cast<double>(chart.subgroupSize));  // Eq. 17
  if (o.lsl && o.usl) {
    const double lsl = *o.lsl, usl = *o.usl, m = chart.meanOfAll;
    cap.cp = (usl - lsl) / (6.0 * cap.sigmaWithin);  // Eq. 16
    cap.cpk = std::min(usl - m, m - lsl) / (3.0 * cap.sigmaWithin);
    if (cap.sigmaOverall > 0.0) {
      cap.pp = (usl - lsl) / (6.0 * cap.sigmaOverall);
      cap.ppk = std::min(usl - m, m - lsl) / (3.0 * cap.sigmaOverall);
    }
  }
  return cap;
}

SystematicError systematicError(const XbarRChart& chart, double sigmaWithin, std::size_t valuesUsed,
                                double nominal, double coverageFactor) {
  SystematicError s;
  s.nominal = nominal;
  s.mean = chart.meanOfAll;
  s.error = nominal - chart.meanOfAll;  // Eq. 20
  s.standardError = sigmaWithin / std::sqrt(static_cast<double>(valuesUsed));
  s.halfWidth = coverageFactor * s.standardError;
  s.significant = std::abs(s.error) > s.halfWidth;
  return s;
}

CompensationDecision gateCompensation(const XbarRChart& chart, const std::optional<SystematicError>& sys,
                                      const SpcOptions& o) {
  CompensationDecision d;
  const auto decide = [&d](Phrases parts) {
    d.reasonParts = std::move(parts);
    d.reason = english(d.reasonParts);
    return d;
  };
  if (!sys) return decide({Phrase("no nominal value given: nothing to compensate against")});
  if (!chart.inControl()) {
    Phrases where;
    if (!chart.xbarOutOfControl.empty()) {
      where.emplace_back(chart.xbarOutOfControl.size() == 1 ? "subgroup %1 beyond the X-bar limits"
                                                            : "subgroups %1 beyond the X-bar limits",
                         std::vector{PhraseArg::name(indexList(chart.xbarOutOfControl))});
    }
    if (!chart.rOutOfControl.empty()) {
      const bool one = chart.rOutOfControl.size() == 1;
      where.emplace_back(
          where.empty() ? (one ? "subgroup %1 beyond the R limits" : "subgroups %1 beyond the R limits")
                        : (one ? "; subgroup %1 beyond the R limits" : "; subgroups %1 beyond the R limits"),
          std::vector{PhraseArg::name(indexList(chart.rOutOfControl))});
    }
    return decide(
        {Phrase("not compensated: the process is out of control (%1); remove the special causes first, "
                "a correction would chase them",
                {PhraseArg::text(std::move(where))})});
  }
  const PhraseArg error = PhraseArg::signedNumber(sys->error, 6);
  const PhraseArg halfWidth = PhraseArg::number(sys->halfWidth, 6);
  const PhraseArg k = PhraseArg::number(o.coverageFactor, 6);
  if (!sys->significant) {
    return decide(
        {Phrase("not compensated: the systematic error %1 is within its interval +-%2 (k = %3): random "
                "scatter, not a systematic error",
                {error, halfWidth, k})});
  }
  if (std::abs(sys->error) < o.minCorrection) {
    return decide({Phrase("not compensated: the systematic error %1 is below the smallest correction %2",
                          {error, PhraseArg::number(o.minCorrection, 6)})});
  }
  d.apply = true;
  d.correction = sys->error;
  return decide(
      {Phrase("compensate %1: the systematic error (nominal - mean, Eq. 20) is beyond its interval +-%2 "
              "(k = %3) and the process is in control (%4 subgroups of %5)",
              {error, halfWidth, k, PhraseArg::integer(static_cast<long long>(chart.subgroups())),
               PhraseArg::integer(static_cast<long long>(chart.subgroupSize))})});
}

SpcResult analyseSpc(const std::vector<double>& values, const SpcOptions& o, const ErrorContext& where) {
  requireValid(o, "SPC options");
  SpcResult r;
  r.options = o;
  r.chart = controlChart(values, o.subgroupSize, o.baseSubgroups, where);
  r.constants = controlChartConstants(r.chart.rangeSpan());
  r.valuesUsed = r.chart.subgroups() * static_cast<std::size_t>(o.subgroupSize);
  r.valuesIgnored = values.size() - r.valuesUsed;
  const std::vector<double> used(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(r.valuesUsed));
  r.capability = capability(r.chart, used, o);
  if (o.nominal) {
    r.systematic =
        systematicError(r.chart, r.capability.sigmaWithin, r.valuesUsed, *o.nominal, o.coverageFactor);
  }
  std::vector<double> index(used.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<double>(i + 1);
  r.trend = fitLine(index, used, where);
  r.decision = gateCompensation(r.chart, r.systematic, o);
  r.rules = nelsonRules(r.chart);
  return r;
}

nlohmann::json spcResultToJson(const SpcResult& r) {
  using nlohmann::json;
  json j;
  j["subgroup_size"] = r.options.subgroupSize;
  j["subgroups"] = r.chart.subgroups();
  j["values_used"] = r.valuesUsed;
  j["values_ignored"] = r.valuesIgnored;
  j["chart_type"] = chartTypeName(r.chart.type);
  j["base_subgroups"] = r.chart.baseSubgroups;
  j["constants"] = {{"A2", r.constants.A2},
                    {"D3", r.constants.D3},
                    {"D4", r.constants.D4},
                    {"d2", r.constants.d2},
                    {"d3", r.constants.d3}};
  if (r.chart.type == ChartType::IndividualsMR) j["constants"]["E2"] = r.constants.E2;
  j["xbar_chart"] = {{"center", r.chart.grandMean},
                     {"ucl", r.chart.xbarUcl},
                     {"lcl", r.chart.xbarLcl},
                     {"points", r.chart.means},
                     {"out_of_control", indices1(r.chart.xbarOutOfControl)}};
  j["r_chart"] = {{"center", r.chart.meanRange},
                  {"ucl", r.chart.rUcl},
                  {"lcl", r.chart.rLcl},
                  {"points", r.chart.ranges},
                  {"out_of_control", indices1(r.chart.rOutOfControl)},
                  {"first_subgroup", r.chart.rangeSubgroup(0) + 1}};
  j["rules"] = json::array();
  for (const RuleBreak& b : r.rules) {
    j["rules"].push_back({{"chart", ruleChartName(b.chart)},
                          {"rule", ruleName(b.rule)},
                          {"subgroups", indices1(b.subgroups)}});
  }
  j["in_control"] = r.chart.inControl();
  j["mean"] = r.chart.meanOfAll;
  j["sigma_within"] = r.capability.sigmaWithin;
  j["sigma_overall"] = r.capability.sigmaOverall;
  j["natural_tolerance"] = r.capability.naturalTolerance;
  if (r.options.lsl) {
    j["lsl"] = *r.options.lsl;
    j["usl"] = *r.options.usl;
    j["cp"] = *r.capability.cp;
    j["cpk"] = *r.capability.cpk;
    if (r.capability.pp) {
      j["pp"] = *r.capability.pp;
      j["ppk"] = *r.capability.ppk;
    }
  }
  if (r.systematic) {
    j["nominal"] = r.systematic->nominal;
    j["systematic_error"] = {{"value", r.systematic->error},
                             {"standard_error", r.systematic->standardError},
                             {"half_width", r.systematic->halfWidth},
                             {"coverage_factor", r.options.coverageFactor},
                             {"significant", r.systematic->significant}};
  }
  j["trend"] = {{"slope", r.trend.slope},
                {"intercept", r.trend.intercept},
                {"r2", r.trend.r2},
                {"slope_std_err", r.trend.slopeStdErr},
                {"angle_deg", r.trend.angleDeg},
                {"x", "sample number"}};
  j["compensation"] = {
      {"apply", r.decision.apply}, {"correction", r.decision.correction}, {"reason", r.decision.reason}};
  return j;
}

}  // namespace metrofit
