#include "core/sim/thermal_sim.h"

#include <cmath>
#include <numbers>

#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

bool ThermalSimOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(durationMin > 0.0)) return no("durationMin must be positive");
  if (!(stepMin > 0.0) || stepMin > durationMin)
    return no("stepMin must be positive and at most durationMin");
  if (durationMin / stepMin > 5e6) return no("too many samples (durationMin / stepMin > 5e6)");
  if (!(tauS > stepMin) || !(tauC > stepMin)) return no("time constants must exceed the step");
  for (double lag : sensorLagMin) {
    if (!(lag > 0.0)) return no("sensor lags must be positive");
  }
  if (noiseTempK < 0.0 || noiseDispUm < 0.0) return no("noise levels must not be negative");
  if (shareC < 0.0 || shareC > 1.0) return no("shareC must be in [0, 1]");
  for (std::size_t i = 1; i < programme.size(); ++i) {
    if (!(programme[i].startMin > programme[i - 1].startMin))
      return no("programme steps must be in increasing time");
  }
  return true;
}

ThermalLog simulateThermalTest(const ThermalSimOptions& o) {
  requireValid(o, "thermal simulation");
  Rng rng(o.seed);
  const auto n = static_cast<std::size_t>(std::floor(o.durationMin / o.stepMin)) + 1;
  ThermalLog log;
  log.source = "simulated thermal test";
  log.timeColumn = "time_min";
  log.timeMin.resize(n);
  const char* names[] = {"spindle_rpm", "T1", "T2", "T3", "T4", "T_amb", "disp_z_um"};
  const char* units[] = {"rpm", "", "", "", "", "", "um"};
  for (int c = 0; c < 7; ++c) log.channels.push_back({names[c], units[c], std::vector<double>(n)});

  auto ambient = [&](double t) {
    return o.ambient0 + o.ambientAmp * std::sin(2.0 * std::numbers::pi * t / 1440.0);
  };
  double ts = ambient(0.0), tc = ambient(0.0);
  const double ts0 = ts, tc0 = tc;
  double sensor[4] = {ts, ts, tc, tc};
  std::size_t step = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * o.stepMin;
    while (step + 1 < o.programme.size() && o.programme[step + 1].startMin <= t) ++step;
    const double rpm = o.programme.empty() || t < o.programme.front().startMin ? 0.0 : o.programme[step].rpm;
    const double ta = ambient(t);
    log.timeMin[i] = t;
    log.channels[0].values[i] = rpm;
    log.channels[1].values[i] = sensor[0] + rng.normal(0.0, o.noiseTempK);
    log.channels[2].values[i] = sensor[1] + rng.normal(0.0, o.noiseTempK);
    log.channels[3].values[i] = sensor[2] + rng.normal(0.0, o.noiseTempK);
    log.channels[4].values[i] = sensor[3] + rng.normal(0.0, o.noiseTempK);
    log.channels[5].values[i] = ta + rng.normal(0.0, o.noiseTempK);
    log.channels[6].values[i] = -(o.kS * (ts - ts0) + o.kC * (tc - tc0)) + rng.normal(0.0, o.noiseDispUm);
    // Advance the nodes and the sensors by one step.
    const double q = rpm / 1000.0;
    const double dts = (o.gainS * q - (ts - ta)) / o.tauS;
    const double dtc = (o.shareC * (ts - tc) + (1.0 - o.shareC) * (ta - tc)) / o.tauC;
    ts += o.stepMin * dts;
    tc += o.stepMin * dtc;
    const double seen[4] = {ts, ts, tc, tc};
    for (int k = 0; k < 4; ++k) {
      const double a = 1.0 - std::exp(-o.stepMin / o.sensorLagMin[k]);
      sensor[k] += a * (seen[k] - sensor[k]);
    }
  }
  return log;
}

}  // namespace metrofit
