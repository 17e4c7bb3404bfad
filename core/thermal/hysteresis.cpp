#include "core/thermal/hysteresis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/error.h"
#include "core/common/run.h"
#include "core/thermal/lag_regression.h"

namespace metrofit::thermal {

namespace {

struct LineFit {
  double r2 = 0.0, gain = 0.0, offset = 0.0;
};

LineFit fitLine(std::span<const double> x, std::span<const double> y) {
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    mx += x[k];
    my += y[k];
  }
  mx /= n;
  my /= n;
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    syy += (y[k] - my) * (y[k] - my);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  LineFit f;
  if (sxx > 0.0 && syy > 0.0) {
    f.gain = sxy / sxx;
    f.offset = my - f.gain * mx;
    f.r2 = sxy * sxy / (sxx * syy);
  } else {
    f.offset = my;
  }
  return f;
}

}  // namespace

LagFit fitLag(std::span<const double> t, std::span<const double> driver, std::span<const double> response,
              double tauMax) {
  if (t.size() != driver.size() || t.size() != response.size() || t.size() < 3)
    throw std::invalid_argument("fitLag: need >= 3 samples of equal length");
  auto eval = [&](double tau) { return fitLine(firstOrderLagMin(driver, t, tau), response); };
  LagFit out;
  const LineFit s = eval(0.0);
  out.r2Static = s.r2;
  out.r2 = s.r2;
  out.gain = s.gain;
  out.offset = s.offset;
  const double step = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  const double tauMin = step / 10.0;
  if (!(tauMax > tauMin)) return out;
  constexpr int kGrid = 48;
  std::vector<double> grid(kGrid), r2(kGrid);
  int best = -1;
  double bestR2 = s.r2;
  for (int i = 0; i < kGrid; ++i) {
    grid[i] = tauMin * std::pow(tauMax / tauMin, static_cast<double>(i) / (kGrid - 1));
    r2[i] = eval(grid[i]).r2;
    if (r2[i] > bestR2) {
      bestR2 = r2[i];
      best = i;
    }
  }
  if (best < 0) return out;  // no lag explains more than the static fit
  // Golden-section search on log tau between the grid neighbours of the best point.
  double lo = std::log(best > 0 ? grid[best - 1] : tauMin * 0.5);
  double hi = std::log(best + 1 < kGrid ? grid[best + 1] : tauMax);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = eval(std::exp(x1)).r2, f2 = eval(std::exp(x2)).r2;
  for (int it = 0; it < 40; ++it) {
    if (f1 > f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = eval(std::exp(x1)).r2;
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = eval(std::exp(x2)).r2;
    }
  }
  double tau = std::exp(0.5 * (lo + hi));
  LineFit f = eval(tau);
  if (f.r2 < bestR2) {
    tau = grid[best];
    f = eval(tau);
  }
  out.tauMin = tau;
  out.r2 = f.r2;
  out.gain = f.gain;
  out.offset = f.offset;
  return out;
}

bool HysteresisOptions::isValid(std::string* why) const {
  if (!(smoothingMin >= 0.0) || !std::isfinite(smoothingMin)) {
    if (why) *why = "smoothingMin must be >= 0";
    return false;
  }
  if (!(maxLagMin >= 0.0) || !std::isfinite(maxLagMin)) {
    if (why) *why = "maxLagMin must be >= 0";
    return false;
  }
  return true;
}

HysteresisAnalysis analyseHysteresis(const ThermalSeries& s, const HysteresisOptions& o) {
  requireValid(o, "hysteresis options");
  if (!s.hasTarget())
    throw ValidationError(ErrorContext{s.source, 0, 0, s.targetName}, "the log has no target column");
  const std::size_t n = s.rows();
  if (n < 3) throw ValidationError(ErrorContext{s.source, 0, 0, {}}, "hysteresis needs at least 3 rows");
  auto requireVarying = [&](const std::vector<double>& v, const std::string& name) {
    if (std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); })) {
      throw ValidationError(ErrorContext{s.source, 0, 0, name}, "is constant; there is no loop to analyse");
    }
  };
  requireVarying(s.target, s.targetName);
  for (std::size_t j = 0; j < s.inputs.size(); ++j) requireVarying(s.inputs[j], s.inputNames[j]);

  HysteresisAnalysis a;
  a.target = s.targetName;
  const std::vector<double> y = change(s.target);
  const double duration = s.timeMin.back() - s.timeMin.front();
  const double step = duration / static_cast<double>(n - 1);
  // Phases from the smoothed magnitude of the target's change.
  const auto half = static_cast<std::size_t>(std::llround(0.5 * o.smoothingMin / step));
  std::vector<double> mag(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k >= half ? k - half : 0, hi = std::min(n - 1, k + half);
    double sum = 0.0;
    for (std::size_t i = lo; i <= hi; ++i) sum += y[i];
    mag[k] = std::abs(sum / static_cast<double>(hi - lo + 1));
  }
  a.phase.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double d = mag[std::min(n - 1, k + 1)] - mag[k > 0 ? k - 1 : 0];
    a.phase[k] = d >= 0.0 ? 1 : -1;
    (a.phase[k] > 0 ? a.heatingRows : a.coolingRows)++;
  }
  const double tauMax = o.maxLagMin > 0.0 ? o.maxLagMin : 0.5 * duration;
  const auto [yMin, yMax] = std::minmax_element(y.begin(), y.end());
  for (std::size_t j = 0; j < s.inputs.size(); ++j) {
    SensorHysteresis h;
    h.sensor = s.inputNames[j];
    const std::vector<double> x = change(s.inputs[j]);
    double twice = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t k1 = (k + 1) % n;
      twice += x[k] * y[k1] - x[k1] * y[k];
    }
    h.loopArea = 0.5 * std::abs(twice);
    const auto [xMin, xMax] = std::minmax_element(x.begin(), x.end());
    h.normalisedLoopArea = h.loopArea / ((*xMax - *xMin) * (*yMax - *yMin));
    const LagFit sensorLags = fitLag(s.timeMin, y, x, tauMax);
    const LagFit targetLags = fitLag(s.timeMin, x, y, tauMax);
    const bool sensorLagging = sensorLags.r2 >= targetLags.r2;
    const LagFit& f = sensorLagging ? sensorLags : targetLags;
    h.tauMin = sensorLagging ? f.tauMin : -f.tauMin;
    h.gain = f.gain;
    h.r2 = f.r2;
    h.r2Static = f.r2Static;
    a.sensors.push_back(h);
  }
  return a;
}

nlohmann::json hysteresisToJson(const HysteresisAnalysis& a) {
  nlohmann::json j;
  j["target"] = a.target;
  j["heating_rows"] = a.heatingRows;
  j["cooling_rows"] = a.coolingRows;
  nlohmann::json sensors = nlohmann::json::array();
  for (const auto& h : a.sensors) {
    sensors.push_back({{"sensor", h.sensor},
                       {"loop_area", h.loopArea},
                       {"normalised_loop_area", h.normalisedLoopArea},
                       {"tau_min", h.tauMin},
                       {"lagging", h.tauMin > 0.0   ? "sensor lags the displacement"
                                   : h.tauMin < 0.0 ? "displacement lags the sensor"
                                                    : "no lag"},
                       {"gain", h.gain},
                       {"r2", h.r2},
                       {"r2_static", h.r2Static}});
  }
  j["sensors"] = sensors;
  return j;
}

}  // namespace metrofit::thermal
