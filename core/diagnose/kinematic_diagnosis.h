#pragma once
// The closed loop in the kinematic domain (docs/file-formats.md#the-declared-models and #diagnose-result).
//
// Declared model: the Cartesian machine of cartesian_model.h, P = o + ir(a) x + jr(b) y, identified
// by core/kinematics/identification.h (actuator origin and orientation errors, nothing else).
//
// Candidate effects (docs/file-formats.md#effect-catalogue names) act on the joint coordinates exactly as the
// simulator's (core/sim/effects_kinematic.h, pathMotion for directions and tangents), and are estimated
// jointly with o, a, b by Levenberg-Marquardt on the sum of squared residual distances:
//   `backlash`   bx, by (full lost motion, mm)               2 parameters
//   `scale`      sx, sy (ppm)                                 2 parameters
//   `cyclic`     on x or y: amplitude, phase, period (mm)     3 parameters; the period from a
//                search over a frequency grid (step 1 / (8 travel), periods from 3 sampling steps
//                of the axis to half its travel), the better axis is the candidate
//   `servo_lag`  tau (s), with the feed rate (mm/min) the test ran at: lag distance tau feed / 60
// Standard errors from s^2 (J^T J)^-1 at the solution, s^2 = S / (2N - p).
//
// Acceptance on evidence: with n = 2N residual coordinates and BIC = n ln(S / n) + p ln(n), a
// candidate is accepted only when dBIC = BIC_after - BIC_before < -bicMargin (10: "very strong"
// evidence; the cyclic search adds 2 ln(independent frequencies searched = grid points / 8) to
// its penalty) *and* the fit rmse falls by at least minRmseGain (5 %). The passing candidate with
// the lowest dBIC is accepted, the model refitted with it and the others tried again, until none
// passes.
//
// The open world (docs/file-formats.md#residual_check, residual_check.h): points whose declared-model
// residual has a robust z above the outlier threshold are excluded before the loop (residualCheck->outliers,
// with row). The residual check works on the residual vectors (x and y as two components) against row (path
// order), the path angle about the centroid, the loop direction (CCW / CW), the samples since an
// axis reversed and the commanded x and y. Every round also tries the generic effects of the
// strongest structures as displacements with one set of coefficients per coordinate, estimated
// jointly by the same Levenberg-Marquardt fit, under the same dBIC decision plus the search penalty
// 2 ln(tests); the lowest dBIC wins the round, named or generic (so a drift is not backlash).
#include "core/common/run.h"
#include "core/diagnose/diagnosis.h"
#include "core/kinematics/effects.h"
#include "core/kinematics/measured_path.h"

namespace metrofit::diagnose {

struct KinematicDiagnosisOptions {
  double feedMmPerMin = kDefaultFeedMmPerMin;  ///< the feed rate of the test (for servo_lag's tau_s)
  double bicMargin = 10.0;                     ///< accept when dBIC < -bicMargin
  double minRmseGain = 0.05;                   ///< relative fit rmse reduction needed
  int maxRounds = 6;
  double minPeriodMm = 0.0;  ///< cyclic search range; 0: automatic (see the header comment)
  double maxPeriodMm = 0.0;

  bool isValid(std::string* why) const;
};

/// Runs the loop on a measured path / circular test. InputError naming the file and field when the
/// path cannot identify the declared model (identification.h's checks); OptionsError for invalid
/// options. The observer sees one step per candidate (best = current rmse, mm); when it stops the
/// loop the diagnosis so far is returned with the note "cancelled".
Diagnosis diagnoseKinematic(const MeasuredPath& path, const KinematicDiagnosisOptions& options,
                            Observer* observer = nullptr);

}  // namespace metrofit::diagnose
