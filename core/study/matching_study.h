#pragma once
// The matching study of a project end to end, shared by the GUI page and the report:
// every method on the study's probe points (rough + SADE, rough + GA-simplex, closed form,
// minimax), the machine adjustment values of the primary method's posture for the study's machine,
// and the remeasure loop of Step 7 with the simulator as machine and CMM.
//
// Project keys (studies.matching, all optional): "dataset" (a probe_points dataset id; default the
// first of that kind), "tolerance_mm" (>= 0, default 0.05), "method" (sade | ga-simplex |
// closed-form | minimax, the primary method, default sade), "allow_scale" (bool), "seed" (>= 0),
// "machine" (project.h matchingMachine; default the XFYZBA preset), "frame" (heidenhain | siemens |
// fanuc: the control of the page's controller frame and of the report's frame listing, default
// heidenhain) and "frame_decimals" (0..12, default 4; no effect on the run). The effects added to the model
// with the diagnosis page's Apply (studies.diagnosis.matching.applied: scale, surface_offset:<s>,
// distortion; core/diagnose/applied_setup_matching.h) are part of the study's model when the
// diagnosis ran on the study's dataset (studies.diagnosis.matching.dataset): the nominal
// points are deformed by them before every method runs (studyModelSet), so the residual, the
// tolerance evaluation, the machine adjustments and the remeasure loop include them.
//
// The remeasure loop's cell: the workpiece is where the probe found it (remeasure.h partAsMeasured:
// true posture and form error together, a_i = p_i; nothing of the primary fit goes into the cell), the
// probe repeats the nominal points with `remeasureNoiseMm` noise. The loop therefore fails (form_error)
// when the data's form error is larger than the tolerance; see remeasure.h.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnose/applied_setup_matching.h"
#include "core/geometry/mesh_search.h"
#include "core/machine/controller_frame.h"
#include "core/machine/machine.h"
#include "core/matching/matching.h"
#include "core/matching/remeasure.h"

namespace metrofit {
class Project;
}

namespace metrofit::matching {

struct MatchingStudyOptions {
  double toleranceMm = matching::kDefaultToleranceMm;
  bool allowScale = false;
  DofLocks locks;  ///< user locks
  std::uint64_t seed = 1;
  MatchMethod primary = MatchMethod::Sade;
  /// Methods to run, in the order of the results table (the primary one is always run).
  std::vector<MatchMethod> methods{MatchMethod::Sade, MatchMethod::GaSimplex, MatchMethod::ClosedForm,
                                   MatchMethod::Minimax};
  machine::MachineDefinition machine;
  bool remeasure = true;
  double remeasureNoiseMm = 0.006;
  /// Effects added to the model (studies.diagnosis.matching.applied); empty = the declared rigid model.
  diagnose::AppliedMatchingEffects applied;
  /// The CAD part the points' nominals come from (a dataset's nominals {"from": "cad"},
  /// core/project/nominals.h); null for nominal point pairs. With it the closed-form and minimax runs
  /// re-project the measured points onto the part at each posture (core/matching/cad_match.h) and the
  /// other methods (which need fixed point pairs) are not run; a primary method other than those two
  /// is refused.
  std::shared_ptr<const geometry::MeshSearch> cad;
};

/// The point set the study matches: `set` with the applied effects on its nominal points (a copy of
/// `set` without effects). ValidationError naming the applied entry for an unknown surface.
ProbePointSet studyModelSet(const ProbePointSet& set, const MatchingStudyOptions& options,
                            const std::string& source = {});

struct MatchingStudyResult {
  std::vector<MatchResult> runs;  ///< in the order of options.methods
  std::vector<double> seconds;    ///< wall time per run
  MatchMethod primary = MatchMethod::Sade;
  machine::MachineDefinition machine;
  machine::Adjustment adjustment;  ///< for the primary run's posture
  std::optional<RemeasureResult> remeasure;
  /// With a CAD part (options.cad): each run's closest points of the part at its final posture, in the
  /// order of `runs` (the nominals its `after` evaluation is of).
  std::vector<ProbePointSet> cadAfter;

  /// The run of a method, or nullptr when it was not run.
  const MatchResult* of(MatchMethod method) const;
  /// The primary run (always present).
  const MatchResult& primaryRun() const;
};

/// Runs the study on studyModelSet(set, options). InputError on bad data or options (as
/// matchPosture). The observer sees the iterations of every run and may stop the study.
MatchingStudyResult runMatchingStudy(const ProbePointSet& set, const MatchingStudyOptions& options,
                                     Observer* observer = nullptr);

/// The study's dataset id and options from the project's studies.matching (see above); an empty id
/// when the project has no probe_points dataset. ValidationError naming `source` and the field.
struct MatchingStudySettings {
  std::string datasetId;
  MatchingStudyOptions options;
  /// The controller frame of the posture (studies.matching.frame, .frame_decimals).
  machine::FrameFormat frame = machine::FrameFormat::Heidenhain;
  int frameDecimals = machine::FrameOptions{}.decimals;
};
MatchingStudySettings matchingStudySettings(const Project& project, const std::string& source = {});

/// The magnification of the deviation vectors in the before/after views of the page and the report:
/// the largest deviation before matching drawn at about 15 % of the part's largest extent (of the
/// nominal points, at least 1 mm), rounded down to 1, 2 or 5 x 10^n and kept in [1, 1e5]; 100 when
/// there is no deviation.
double deviationMagnification(const ProbePointSet& set, double maxAbsDeviationBeforeMm);

}  // namespace metrofit::matching
