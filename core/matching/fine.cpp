#include "core/matching/fine.h"

#include <cmath>

#include "core/common/error.h"

namespace metrofit::matching {

FineMatchingProblem::FineMatchingProblem(const ProbePointSet& set, const RoughResult& rough,
                                         const DofLocks& locks, bool allowScale, double marginDeg)
    : points_(centredPoints(set)),
      roughAlignment_(rough.alignment),
      locks_(locks),
      allowScale_(allowScale),
      paperMode_(!locks.anyRotation()) {
  if (!(marginDeg > 0.0) || !std::isfinite(marginDeg))
    throw OptionsError(ErrorContext{{}, 0, 0, "bound margin"}, "the angle bound margin k must be > 0 deg");
  roughAnglesDeg_ = rough.posture.anglesDeg();
  if (paperMode_) {
    static const char* const paperNames[3] = {"alpha1", "beta1", "gamma1"};
    for (int j = 0; j < 3; ++j) {
      const double half = std::abs(rough.pe0[static_cast<std::size_t>(j)]) + marginDeg;
      names_.emplace_back(paperNames[j]);
      lower_.push_back(-half);
      upper_.push_back(half);
    }
  } else {
    for (int j = 0; j < 3; ++j) {
      if (locks.locked[j]) continue;
      const double half = std::abs(roughAnglesDeg_(j)) + marginDeg;
      freeAngles_.push_back(j);
      names_.emplace_back(dofName(j));
      lower_.push_back(-half);
      upper_.push_back(half);
    }
  }
}

Eigen::Matrix3d FineMatchingProblem::rotationAt(std::span<const double> x) const {
  if (paperMode_) {
    const Eigen::Matrix3d A1 = rotationZyx(Eigen::Vector3d(x[0], x[1], x[2]) * kRadPerDeg);
    return (A1 * roughAlignment_).transpose();
  }
  Eigen::Vector3d deg(locks_.value[0], locks_.value[1], locks_.value[2]);
  for (std::size_t c = 0; c < freeAngles_.size(); ++c) deg(freeAngles_[c]) = x[c];
  return rotationZyx(deg * kRadPerDeg);
}

double FineMatchingProblem::evaluate(std::span<const double> x, std::span<double>) const {
  double ss = 0.0;
  (void)optimalTranslationScale(points_, rotationAt(x), locks_, allowScale_, &ss);
  return std::sqrt(std::max(ss, 0.0) / static_cast<double>(points_.n));
}

Pose FineMatchingProblem::poseAt(std::span<const double> x) const {
  return optimalTranslationScale(points_, rotationAt(x), locks_, allowScale_);
}

std::vector<double> FineMatchingProblem::roughDecision() const {
  if (paperMode_) return std::vector<double>(3, 0.0);
  std::vector<double> x;
  for (int j : freeAngles_) x.push_back(roughAnglesDeg_(j));
  return x;
}

FineResult fineMatch(const ProbePointSet& set, const RoughResult& rough, const optim::Algorithm& algorithm,
                     const DofLocks& locks, bool allowScale, double marginDeg, Observer* observer) {
  const FineMatchingProblem problem(set, rough, locks, allowScale, marginDeg);
  FineResult res;
  res.paperMode = problem.paperMode();
  res.variables = problem.variableNames();
  for (std::size_t i = 0; i < problem.dimension(); ++i) {
    res.lowerDeg.push_back(problem.lower(i));
    res.upperDeg.push_back(problem.upper(i));
  }
  if (problem.dimension() == 0) {
    res.pose = problem.poseAt({});
    res.objectiveMm = problem.evaluate({}, {});
    res.optimisation.method = algorithm.name();
    res.optimisation.bestObjective = res.objectiveMm;
    res.optimisation.run.message = "every angle is locked: translation from the centroids (Eq. 9)";
    return res;
  }
  res.optimisation = algorithm.optimise(problem, observer);
  res.bestDeg = res.optimisation.bestX;
  res.objectiveMm = res.optimisation.bestObjective;
  res.pose = problem.poseAt(res.bestDeg);
  return res;
}

}  // namespace metrofit::matching
