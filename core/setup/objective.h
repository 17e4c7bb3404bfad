#pragma once
// The objectives of the setup correction, exactly as the paper (Stryczek 2016, J. Intell. Manuf.
// 27:1209, "Formulating the optimization task", Eq. 6-10), on the model of model.h.
//
// Data. For dimension q: the current deviation e_q (mean of measured - nominal over the report,
// report.h), the tolerance limits lo_q < up_q relative to the nominal, the gain row G_q (model.h,
// Eq. 4-5). For the corrections x (mm, one per setup datum) the predicted deviation after
// correction is
//   e'_q(x) = e_q + (G x)_q                                                     (Eq. 4-5)
//
// Unilateral error budget of dimension q (Fig. 7b: the distance from the zero-deviation line,
// here the part's actual value, to the nearer border of the tolerance zone):
//   delta_q(x) = min(up_q - e'_q(x), e'_q(x) - lo_q)      [mm; < 0 when q is out of tolerance]
//
// Our reading of Eq. 6-8. The paper writes the zone relative to the part's actual value: eps_q
// is the shift of the tolerance-zone centre off the zero line and T_q the zone width, so the zone
// is [eps_q - T_q/2, eps_q + T_q/2] with eps_q = (lo_q + up_q)/2 - e'_q. Then
//   dZ^-_q = eps_q - T_q/2 = lo_q - e'_q   (Eq. 6 takes the max over q: the highest lower border)
//   dZ^+_q = eps_q + T_q/2 = up_q - e'_q   (Eq. 7 takes the min over q: the lowest upper border)
//   Delta Z = dZ^+ - dZ^-                  (Eq. 8: the zone common to all dimensions)
// and Eq. 8's f1 = max_p min_q {dZ^-_q, dZ^+_q} only makes sense with the DISTANCES to the two
// borders, |dZ^-_q| = e'_q - lo_q and dZ^+_q (both >= 0 inside the zone), which is delta_q:
//   f1(x) = min_q delta_q(x) = min(-dZ^-, dZ^+)                                 (Eq. 8)
// i.e. docs/file-formats.md#setup-result's "the smallest unilateral error budget over all dimensions after
// correction". The paper's example agrees: b = 0.071 - 0.022 = 0.049 mm is a difference of such
// budgets. f1 is maximised over the solutions p (the max_p of Eq. 8 is the optimisation itself).
//   f2(x) = |x| = sqrt(sum_i x_i^2)        [mm]  (Eq. 9, minimised among the f1-optimal x)
//   f(x)  = 10 f1(x) - f2(x)               [mm]  (Eq. 10, the single-objective surrogate)
//   b(x)  = f1(x) - f1(0)                  [mm]  (bonus error budget)
// Note: the maximiser of f is not always the lexicographic optimum (max f1, then min f2): f
// trades 0.001 mm of f1 for 0.01 mm of |x|. The metaheuristics maximise f (as in the paper); the
// exact method (exact.h) solves the lexicographic problem the paper states in words.
//
// Decision space: x_i = lower_i + k_i * step_mm, k_i integer, lower_i <= x_i <= upper_i (the
// grid anchored at the lower bound, as optim::Problem).
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/optim/problem.h"
#include "core/setup/model.h"

namespace metrofit::setup {
struct Measurements;

struct SetupScore {
  double f1 = 0.0;  ///< smallest unilateral error budget after correction, mm
  double f2 = 0.0;  ///< |x|, mm
  double f = 0.0;   ///< 10 f1 - f2
};

/// A model with its measured deviations: everything the objectives need, in flat arrays.
class SetupInstance {
 public:
  /// `deviationMm` has one value per model dimension (e_q).
  SetupInstance(const Model& model, std::vector<double> deviationMm);
  SetupInstance(const Model& model, const Measurements& measurements);

  std::size_t variables() const { return xLower_.size(); }
  std::size_t dimensions() const { return deviation_.size(); }
  double step() const { return step_; }
  double xLower(std::size_t i) const { return xLower_[i]; }
  double xUpper(std::size_t i) const { return xUpper_[i]; }
  /// Largest k with xLower + k * step <= xUpper (+1e-9 step).
  long gridPoints(std::size_t i) const;
  const std::vector<std::string>& datumIds() const { return datumIds_; }
  const std::vector<DatumKind>& datumKinds() const { return datumKinds_; }
  const std::vector<std::string>& dimensionIds() const { return dimensionIds_; }
  const Eigen::MatrixXd& gain() const { return gain_; }
  /// Non-zeros of row q of G: (variable, coefficient).
  const std::vector<std::pair<std::size_t, double>>& gainRow(std::size_t q) const { return rows_[q]; }
  double deviation(std::size_t q) const { return deviation_[q]; }
  double lowerLimit(std::size_t q) const { return lower_[q]; }
  double upperLimit(std::size_t q) const { return upper_[q]; }

  /// e'_q(x) for every q.
  std::vector<double> deviationsAfter(std::span<const double> x) const;
  /// delta_q(x) for every q.
  std::vector<double> budgets(std::span<const double> x) const;
  double f1(std::span<const double> x) const;
  SetupScore score(std::span<const double> x) const;
  /// f1 at x = 0 (before correction).
  double f1Before() const;
  /// b = f1(x) - f1(0).
  double bonus(std::span<const double> x) const { return f1(x) - f1Before(); }
  /// x_i = xLower_i + k_i * step.
  std::vector<double> fromGrid(std::span<const long> k) const;

 private:
  std::vector<std::string> datumIds_, dimensionIds_;
  std::vector<DatumKind> datumKinds_;
  Eigen::MatrixXd gain_;
  std::vector<std::vector<std::pair<std::size_t, double>>> rows_;
  // rows_ flattened (compressed rows: row q is entries rowStart_[q] .. rowStart_[q + 1]) for f1, the
  // inner loop of every metaheuristic evaluation.
  std::vector<std::size_t> rowStart_, rowIndex_;
  std::vector<double> rowGain_;
  std::vector<double> deviation_, lower_, upper_, xLower_, xUpper_;
  double step_ = 0.001;
};

/// The setup problem for the metaheuristics of core/optim: minimise -f on the grid within the bounds;
/// components {"f1", "f2", "f"}. Holds its own copy of the instance; thread-safe.
class SetupProblem final : public optim::Problem {
 public:
  explicit SetupProblem(SetupInstance instance) : instance_(std::move(instance)) {}
  const SetupInstance& instance() const { return instance_; }

  std::string name() const override { return "setup"; }
  std::size_t dimension() const override { return instance_.variables(); }
  double lower(std::size_t i) const override { return instance_.xLower(i); }
  double upper(std::size_t i) const override { return instance_.xUpper(i); }
  double gridStep() const override { return instance_.step(); }
  std::vector<std::string> componentNames() const override { return {"f1", "f2", "f"}; }
  double evaluate(std::span<const double> x, std::span<double> components) const override;

 private:
  SetupInstance instance_;
};

}  // namespace metrofit::setup
