#pragma once
// Simulated heating tests of a gantry machine's ram like the set-up of Abdulshahed et al. 2016 (grey neural
// network thermal model, Section 3 and 4.1-4.3): a Z-axis heating test, a C-axis heating test and the
// combined (helical) test, each 2 h heating + 2 h cooling at 1-min sampling by default, with temperature
// sensors, Fibre Bragg Grating strain sensors and the ram's Z growth. The simulator plays machine and
// sensors; the modular models of Section 4.3 are trained on the first two and validated on the third.
//
// Lumped thermal network (temperatures in degC, explicit Euler with sub-steps of at most 0.25 min):
//   drives           Pz = z_speed / zSpeedRef (Z reciprocation), Pc = c_rpm / cRpmRef (C rotation)
//   Z drive node     dTz/dt = (gainZ Pz + Ta - Tz) / tauZ          (ball screw bearings, nut, Z motor)
//   C drive node     dTc/dt = (gainC Pc + Ta - Tc) / tauC          (C bearings, C motor in the ram)
//   ram body         dTr/dt = (shareZ (Tz - Tr) + shareC (Tc - Tr) + (1 - shareZ - shareC)(Ta - Tr)) / tauRam
//   cross-beam       dTb/dt = (shareBeamZ (Tz - Tb) + (1 - shareBeamZ)(Ta - Tb)) / tauBeam
//   ambient          Ta(t) = ambient0 + offset + ambientAmp sin(2 pi (t + phase) / 1440)
//                    (offset in +-0.5 K and phase in [0, 1440) min drawn from the seed, per test)
//   ram Z growth     disp_z_um = -(kRam dTr + kZ dTz + kC dTc + kBeam dTb)    (d: change since start)
// Sensors: first-order lags (exact for the sample-and-hold update, time constant per sensor) of the
// node mix they sit on, plus white noise:
//   T1 = lag 3 min of Tc (ram, near the C motor)   T2 = lag 10 min of Tr (ram rear; the paper's ~10 min
//   latency, Fig. 9)   T3 = lag 8 of (Tr + Tc)/2 (ram end)   T4 = lag 20 of 0.7 Tr + 0.3 Ta (ram end)
//   T5 = lag 2 of Tz (Z motor)   T6 = lag 6 of 0.6 Tz + 0.4 Tr (Z motor)   T_amb = Ta
// FBG strain sensors (microstrain), each bonded over a part of the structure with local temperature
// Tl, following it with a 1-min lag; the grating reads the structure's thermal strain alpha dTl plus
// its own temperature sensitivity kappa dTl (8.64 ue/K in the paper), which is corrected with a nearby
// temperature sensor Ts (the paper's set-up: "the low-cost temperature sensors ... were used to
// correct for change in the grating temperature"), leaving kappa (dTl - dTs) where Ts lags:
//   FBG1: Tl = 0.6 Tr + 0.4 Tz, corrected by T6     FBG2: Tl = 0.6 Tr + 0.4 Tc, corrected by T3
//   FBG3: Tl = Tr, corrected by T2                    FBG4 (cross-beam): Tl = Tb, corrected by T_amb
// Columns: time_min, z_speed_mpm, c_rpm, T1..T6, T_amb, FBG1_ue..FBG4_ue, disp_z_um.
// Defaults give about -100 um (Z test), -85 um (C test) and -90 um (combined test), the sizes of the
// paper's Sections 4.1-4.3. Deterministic by seed (each test draws from its own stream).
#include <cstdint>
#include <string>

#include "core/thermal/thermal_log.h"

namespace metrofit {

enum class ModularTest { ZHeating, CHeating, Combined };
/// "z", "c", "combined".
const char* toString(ModularTest test);

struct ModularSimOptions {
  double durationMin = 240.0;  ///< 2 h heating + 2 h cooling (Section 4.1)
  double heatingMin = 120.0;   ///< drives run from t = 0 to heatingMin
  double stepMin = 1.0;        ///< sampling step
  double zSpeedMpm = 70.0;     ///< Z test: ram reciprocating at 70 m/min (Section 4.1)
  double cRpm = 2500.0;        ///< C test: C axis at 2500 rpm (Section 4.2)
  double combinedZSpeedMpm = 35.0, combinedCRpm = 1250.0;  ///< helical test: both at once (4.3)
  double zSpeedRef = 70.0, cRpmRef = 2500.0;               ///< drive levels of unit heat input
  double gainZ = 9.0, tauZ = 25.0;                         ///< K at unit input, min
  double gainC = 7.0, tauC = 20.0;
  double shareZ = 0.5, shareC = 0.4, tauRam = 90.0;
  double shareBeamZ = 0.2, tauBeam = 240.0;
  double kRam = 15.0, kZ = 6.0, kC = 8.0, kBeam = 2.0;  ///< um per K
  double lagT[6] = {3.0, 10.0, 8.0, 20.0, 2.0, 6.0};    ///< T1..T6 time constants, min
  double lagFbgMin = 1.0;
  double alphaUePerK = 11.5;  ///< thermal strain of the steel structure
  double kappaUePerK = 8.64;  ///< FBG temperature sensitivity (paper, Section 3)
  double ambient0 = 20.0, ambientAmp = 0.4;
  double noiseTempK = 0.02, noiseStrainUe = 0.2, noiseDispUm = 0.3;
  std::uint64_t seed = 1;

  bool isValid(std::string* why) const;
};

/// Runs one test; throws OptionsError when the options are invalid.
ThermalLog simulateModularTest(ModularTest test, const ModularSimOptions& options);

}  // namespace metrofit
