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
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/machine/machine.h"
#include "core/matching/matching.h"

namespace metrofit::matching {

/// Measures the workpiece with the machine's current WCS; `round` numbers the measurements from 0.
using MeasureFunction = std::function<ProbePointSet(const Pose& wcs, int round)>;

/// The simulator as machine and CMM: the nominal points and normals of `nominal` (its measured points
/// are ignored), a true posture, probing noise (mm, 1 sigma, along the actual normal; along a random
/// direction for position-only points) and a seed (round k uses seed + k).
MeasureFunction simulatedCell(const ProbePointSet& nominal, const Pose& truePosture, double noiseMm,
                              std::uint64_t seed);

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
  Pose wcs;                          ///< WCS in which this round measured
  ToleranceEvaluation measured;      ///< the measurement against the nominal (identity posture in wcs)
  std::optional<MatchResult> match;  ///< absent in the final, in-tolerance round
  std::optional<machine::Adjustment> adjustment;  ///< total values from the original WCS
  Pose nextWcs;                                   ///< WCS realised by the machine after the adjustment
};

struct RemeasureResult {
  std::vector<RemeasureRound> rounds;
  bool inTolerance = false;
  RunInfo run;  ///< one trace entry per round: best = max |deviation| measured in that round
};

/// Runs the loop; the observer sees every round (and may stop it).
RemeasureResult remeasureLoop(const MeasureFunction& measure, const RemeasureOptions& options,
                              Observer* observer = nullptr);

}  // namespace metrofit::matching
