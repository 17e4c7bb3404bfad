#pragma once
// The remeasure loop of the paper's Step 7 (Jiang et al., Mech. Sci. 9, 2018, Section 2, Fig. 1):
// measure, match, adjust the WCS through the machine, remeasure, until no point is out of tolerance.
//
// The cell is simulated: the workpiece sits with a true posture (R*, t*) relative to the original WCS
// (table coordinates). With the machine's current WCS W = (Rw, tw) (a nominal point q of the program
// lies at Rw q + tw on the table), the CMM / on-machine probe sees the workpiece in WCS coordinates,
// i.e. with the posture W^-1 o (R*, t*): p_i = Rw^T (R* q_i + t* - tw) + noise along the normal.
// Round k: measure in W_k; if every |deviation| <= tolerance, stop; else match (matching.h) giving the
// posture (Rm, tm) in W_k, target WCS W_k o (Rm, tm), adjustment values for it (machine.h, relative to
// the original WCS), rounded to the axis resolution the control accepts, and the WCS the machine
// actually realises with the rounded values (forward chain, machine.h realisedFrame) becomes W_{k+1}.
// A fitted scale is reported by the matcher but cannot be realised by a WCS; only (R, t) is applied.
//
// The simulated workpiece (SimulatedPart) has its own true posture (R*, t*), which the loop never
// sees, and the part's form error f_i (mm, part coordinates): point i of the real part lies at
//   a_i = R* (q_i + f_i) + t*                                         (table coordinates)
// and in WCS W at W^-1 a_i = Rw^T (a_i - tw). The probe adds its noise to that; the true remaining
// error of round k is the noise-free deviation of W_k^-1 a_i from q_i (along n_i where the set has
// normals, else the distance), reported next to what the probe measured.
//
// The loop can fail, and says why (RemeasureOutcome):
//  - FormError: the best fit of a round itself leaves points out of tolerance (after.outOfTolerance
//    > 0): the form error (or the noise) is larger than the tolerance and no WCS can bring those points
//    in. The adjustment is still applied and the part remeasured once; when points are still out, the
//    loop stops there.
//  - BeyondTravel: the adjustment needs a rotary axis outside its travel (machine.h withinTravel);
//    the machine cannot realise it, the WCS stays where it is and the loop stops.
//  - NotConverged: still out of tolerance after maxAdjustments rounds.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/machine/machine.h"
#include "core/matching/matching.h"

namespace metrofit::matching {

/// Measures the workpiece with the machine's current WCS; `round` numbers the measurements from 0.
using MeasureFunction = std::function<ProbePointSet(const Pose& wcs, int round)>;
/// The noise-free part in the WCS (measured = W^-1 a_i): what a perfect probe would see. Only a
/// simulator has it.
using TruthFunction = std::function<ProbePointSet(const Pose& wcs)>;

/// The workpiece of the simulated cell (see above).
struct SimulatedPart {
  ProbePointSet nominal;                     ///< nominal points and normals (the measured points are ignored)
  Pose truePosture;                          ///< (R*, t*) relative to the original WCS; its scale is ignored
  std::vector<Eigen::Vector3d> formErrorMm;  ///< f_i, one per point, or empty (a perfect part)

  /// a_i (table coordinates). OptionsError when formErrorMm has the wrong size.
  std::vector<Eigen::Vector3d> actualPoints() const;
};

/// The part as the probe found it: a_i = p_i, the measured points of `measured` (posture and form
/// together; nothing of a fit goes into the cell). For a readable split, truePosture is the
/// unconstrained least-squares posture (umeyamaFit, scale 1) and f_i = R*^T (p_i - t*) - q_i, so that
/// a_i = p_i exactly; the remaining errors do not depend on the split.
SimulatedPart partAsMeasured(const ProbePointSet& measured);

struct SimulatedCell {
  MeasureFunction measure;
  TruthFunction truth;
};

/// The simulator as machine and CMM for `part`: probing noise (mm, 1 sigma, along the actual normal;
/// along a random direction for position-only points) and a seed (round k uses seed + k).
SimulatedCell simulateCell(const SimulatedPart& part, double noiseMm, std::uint64_t seed);

/// The simulator as machine and CMM: the nominal points and normals of `nominal` (its measured points
/// are ignored), a true posture, probing noise (mm, 1 sigma, along the actual normal; along a random
/// direction for position-only points) and a seed (round k uses seed + k).
MeasureFunction simulatedCell(const ProbePointSet& nominal, const Pose& truePosture, double noiseMm,
                              std::uint64_t seed);

enum class RemeasureOutcome {
  InTolerance,   ///< every measured point within tolerance
  FormError,     ///< the best fit leaves points out of tolerance (see above)
  BeyondTravel,  ///< the adjustment needs an axis outside its travel
  NotConverged,  ///< maxAdjustments used up
  Cancelled,     ///< the observer stopped the loop
};
/// "in_tolerance", "form_error", "beyond_travel", "not_converged", "cancelled".
const char* toString(RemeasureOutcome outcome);

struct RemeasureOptions {
  MatchOptions match;
  machine::MachineDefinition machine;
  int maxAdjustments = 5;              ///< rounds of adjustment before giving up (>= 1)
  double linearResolutionMm = 0.001;   ///< the control accepts SX, SY, SZ in these steps (0: exact)
  double rotaryResolutionDeg = 0.001;  ///< and the rotary values / frame rotation in these (0: exact)

  bool isValid(std::string* why) const;
};

struct RemeasureRound {
  int round = 0;
  Pose wcs;                      ///< WCS in which this round measured
  ToleranceEvaluation measured;  ///< the measurement against the nominal (identity posture in wcs)
  std::optional<ToleranceEvaluation> truth;       ///< the true remaining error in wcs (simulator only)
  std::optional<MatchResult> match;               ///< absent in the final, in-tolerance round
  std::optional<machine::Adjustment> adjustment;  ///< total values from the original WCS
  Pose nextWcs;  ///< WCS realised by the machine after the adjustment (= wcs when none was realised)
};

struct RemeasureResult {
  std::vector<RemeasureRound> rounds;
  bool inTolerance = false;
  RemeasureOutcome outcome = RemeasureOutcome::NotConverged;
  RunInfo run;  ///< one trace entry per round: best = max |deviation| measured in that round;
                ///< termination Converged | Failed (form error, travel) | MaxIterations | Cancelled

  /// The true remaining error after the loop (the last round's truth), when the cell knows it.
  const ToleranceEvaluation* trueRemaining() const;
};

/// Runs the loop; the observer sees every round (and may stop it). With `truth` every round also
/// records the true remaining error.
RemeasureResult remeasureLoop(const MeasureFunction& measure, const RemeasureOptions& options,
                              Observer* observer = nullptr, const TruthFunction& truth = {});
/// The loop on a simulated cell (measure and truth).
RemeasureResult remeasureLoop(const SimulatedCell& cell, const RemeasureOptions& options,
                              Observer* observer = nullptr);

/// {"outcome": "form_error", "in_tolerance": false, "message": "...", "adjustments": k,
///  "rounds": [{"round", "measured": {stats}, "true": {stats}, "fit_out_of_tolerance",
///  "adjustment": {machine.h adjustmentToJson}, "wcs": {"rotation_deg", "translation_mm"}}],
///  "true_remaining": {stats}} (true keys only where the cell knows the truth; stats as
///  toJson(DeviationStats)).
nlohmann::json toJson(const RemeasureResult& result);

}  // namespace metrofit::matching
