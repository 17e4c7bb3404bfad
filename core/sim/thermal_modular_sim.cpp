#include "core/sim/thermal_modular_sim.h"

#include <cmath>
#include <numbers>

#include "core/common/rng.h"
#include "core/common/run.h"

namespace metrofit {

const char* toString(ModularTest test) {
  switch (test) {
    case ModularTest::ZHeating:
      return "z";
    case ModularTest::CHeating:
      return "c";
    case ModularTest::Combined:
      return "combined";
  }
  return "?";
}

bool ModularSimOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(durationMin > 0.0) || !std::isfinite(durationMin)) return no("durationMin must be positive");
  if (!(stepMin > 0.0) || stepMin > durationMin)
    return no("stepMin must be positive and at most durationMin");
  if (durationMin / stepMin > 5e6) return no("too many samples (durationMin / stepMin > 5e6)");
  if (!(heatingMin >= 0.0)) return no("heatingMin must be >= 0");
  if (!(zSpeedRef > 0.0) || !(cRpmRef > 0.0)) return no("the reference drive levels must be positive");
  if (zSpeedMpm < 0.0 || cRpm < 0.0 || combinedZSpeedMpm < 0.0 || combinedCRpm < 0.0)
    return no("drive levels must be >= 0");
  for (double tau : {tauZ, tauC, tauRam, tauBeam}) {
    if (!(tau > 0.0) || !std::isfinite(tau)) return no("node time constants must be positive");
  }
  for (double lag : lagT) {
    if (!(lag > 0.0) || !std::isfinite(lag)) return no("sensor lags must be positive");
  }
  if (!(lagFbgMin > 0.0)) return no("the FBG lag must be positive");
  if (shareZ < 0.0 || shareC < 0.0 || shareZ + shareC > 1.0) return no("need shareZ, shareC >= 0, sum <= 1");
  if (shareBeamZ < 0.0 || shareBeamZ > 1.0) return no("shareBeamZ must be in [0, 1]");
  if (noiseTempK < 0.0 || noiseStrainUe < 0.0 || noiseDispUm < 0.0) return no("noise levels must be >= 0");
  return true;
}

ThermalLog simulateModularTest(ModularTest test, const ModularSimOptions& o) {
  requireValid(o, "modular thermal simulation");
  const auto testIndex = static_cast<std::uint64_t>(test);
  Rng rng(o.seed * 0x9E3779B97F4A7C15ULL + testIndex + 1);
  const double offset = rng.uniform(-0.5, 0.5);
  const double phase = rng.uniform(0.0, 1440.0);
  double zSpeed = 0.0, cSpeed = 0.0;
  switch (test) {
    case ModularTest::ZHeating:
      zSpeed = o.zSpeedMpm;
      break;
    case ModularTest::CHeating:
      cSpeed = o.cRpm;
      break;
    case ModularTest::Combined:
      zSpeed = o.combinedZSpeedMpm;
      cSpeed = o.combinedCRpm;
      break;
  }
  const auto n = static_cast<std::size_t>(std::floor(o.durationMin / o.stepMin + 1e-9)) + 1;
  ThermalLog log;
  log.source = std::string("simulated ") + toString(test) + " test";
  log.timeColumn = "time_min";
  log.timeMin.resize(n);
  const char* names[] = {"z_speed_mpm", "c_rpm", "T1",      "T2",      "T3",      "T4",      "T5",
                         "T6",          "T_amb", "FBG1_ue", "FBG2_ue", "FBG3_ue", "FBG4_ue", "disp_z_um"};
  const char* units[] = {"", "rpm", "", "", "", "", "", "", "", "ue", "ue", "ue", "ue", "um"};
  for (int c = 0; c < 14; ++c) log.channels.push_back({names[c], units[c], std::vector<double>(n)});

  auto ambient = [&](double t) {
    return o.ambient0 + offset + o.ambientAmp * std::sin(2.0 * std::numbers::pi * (t + phase) / 1440.0);
  };
  const double ta0 = ambient(0.0);
  double tz = ta0, tc = ta0, tr = ta0, tb = ta0;
  // What each temperature sensor sits on, and the FBGs' local structure temperature.
  auto seenT = [&](double ta, double out[6]) {
    out[0] = tc;
    out[1] = tr;
    out[2] = 0.5 * (tr + tc);
    out[3] = 0.7 * tr + 0.3 * ta;
    out[4] = tz;
    out[5] = 0.6 * tz + 0.4 * tr;
  };
  auto localF = [&](double out[4]) {
    out[0] = 0.6 * tr + 0.4 * tz;
    out[1] = 0.6 * tr + 0.4 * tc;
    out[2] = tr;
    out[3] = tb;
  };
  double sensT[6], fbgT[4];
  seenT(ta0, sensT);
  localF(fbgT);
  double sensT0[6], fbgT0[4];
  for (int i = 0; i < 6; ++i) sensT0[i] = sensT[i];
  for (int i = 0; i < 4; ++i) fbgT0[i] = fbgT[i];
  const double tr0 = tr, tz0 = tz, tc0 = tc, tb0 = tb;
  const int sub = std::max(1, static_cast<int>(std::ceil(o.stepMin / 0.25)));
  const double dt = o.stepMin / sub;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * o.stepMin;
    if (i > 0) {
      // Advance the nodes over (t - step, t]; drives are on during [0, heatingMin).
      for (int s = 0; s < sub; ++s) {
        const double ts = t - o.stepMin + s * dt;
        const bool on = ts < o.heatingMin;
        const double pz = on ? zSpeed / o.zSpeedRef : 0.0;
        const double pc = on ? cSpeed / o.cRpmRef : 0.0;
        const double ta = ambient(ts);
        const double dTz = (o.gainZ * pz + ta - tz) / o.tauZ;
        const double dTc = (o.gainC * pc + ta - tc) / o.tauC;
        const double dTr =
            (o.shareZ * (tz - tr) + o.shareC * (tc - tr) + (1.0 - o.shareZ - o.shareC) * (ta - tr)) /
            o.tauRam;
        const double dTb = (o.shareBeamZ * (tz - tb) + (1.0 - o.shareBeamZ) * (ta - tb)) / o.tauBeam;
        tz += dt * dTz;
        tc += dt * dTc;
        tr += dt * dTr;
        tb += dt * dTb;
      }
      // Sensors follow what they sit on (sample-and-hold first-order lags).
      double seen[6], local[4];
      seenT(ambient(t), seen);
      localF(local);
      for (int k = 0; k < 6; ++k) sensT[k] += (1.0 - std::exp(-o.stepMin / o.lagT[k])) * (seen[k] - sensT[k]);
      const double aF = 1.0 - std::exp(-o.stepMin / o.lagFbgMin);
      for (int k = 0; k < 4; ++k) fbgT[k] += aF * (local[k] - fbgT[k]);
    }
    const bool on = t < o.heatingMin;
    const double ta = ambient(t);
    log.timeMin[i] = t;
    log.channels[0].values[i] = on ? zSpeed : 0.0;
    log.channels[1].values[i] = on ? cSpeed : 0.0;
    double measT[7];
    for (int k = 0; k < 6; ++k) measT[k] = sensT[k] + rng.normal(0.0, o.noiseTempK);
    measT[6] = ta + rng.normal(0.0, o.noiseTempK);
    for (int k = 0; k < 7; ++k) log.channels[2 + static_cast<std::size_t>(k)].values[i] = measT[k];
    // FBG k corrected by the temperature sensor next to it: T6, T3, T2, T_amb (true sensor states).
    const double corr[4] = {sensT[5] - sensT0[5], sensT[2] - sensT0[2], sensT[1] - sensT0[1], ta - ta0};
    for (int k = 0; k < 4; ++k) {
      const double dl = fbgT[k] - fbgT0[k];
      log.channels[9 + static_cast<std::size_t>(k)].values[i] =
          o.alphaUePerK * dl + o.kappaUePerK * (dl - corr[k]) + rng.normal(0.0, o.noiseStrainUe);
    }
    log.channels[13].values[i] =
        -(o.kRam * (tr - tr0) + o.kZ * (tz - tz0) + o.kC * (tc - tc0) + o.kBeam * (tb - tb0)) +
        rng.normal(0.0, o.noiseDispUm);
  }
  return log;
}

}  // namespace metrofit
