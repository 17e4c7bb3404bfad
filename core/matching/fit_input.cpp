#include "core/matching/fit_input.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/common/error.h"

namespace metrofit::matching {
namespace {

/// Names of the free parameters (rx..z, then "scale").
std::vector<std::string> freeNames(const DofLocks& locks, bool scale) {
  std::vector<std::string> names;
  for (int j = 0; j < kDofCount; ++j)
    if (!locks.locked[j]) names.emplace_back(dofName(j));
  if (scale) names.emplace_back("scale");
  return names;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

DofLocks implicitLocks(const ProbePointSet& set) {
  DofLocks l;
  if (set.planar) {
    l.lock(Dof::Rx);
    l.lock(Dof::Ry);
    l.lock(Dof::Z);
  }
  return l;
}

DofLocks effectiveLocks(const ProbePointSet& set, const DofLocks& userLocks) {
  // Implicit locks win: a planar set has z = 0, so a user value for z there would be meaningless.
  return userLocks.merged(implicitLocks(set));
}

void requireDeterminable(const ProbePointSet& set, const DofLocks& locks, bool allowScale, FitKind kind,
                         const std::string& method) {
  const ErrorContext ctx{set.source, 0, 0, {}};
  const std::vector<std::string> names = freeNames(locks, allowScale);
  const std::size_t k = names.size();
  const std::size_t n = set.points.size();
  const bool rotationFree = !locks.locked[0] || !locks.locked[1] || !locks.locked[2];
  const bool alongNormals = (kind == FitKind::Minimax || kind == FitKind::PointToPlane) && set.hasNormals;

  std::size_t minPoints = 1;
  std::string why;
  if (alongNormals && kind == FitKind::PointToPlane) {
    minPoints = k;
    why = "one deviation per point along its normal, " + std::to_string(k) + " free parameters (" +
          joined(names) + ")";
  } else if (alongNormals) {
    minPoints = k + 1;
    why = "one deviation per point along its normal, " + std::to_string(k) + " free parameters (" +
          joined(names) + ") and one for the largest deviation";
  } else if (rotationFree) {
    minPoints = set.planar ? 2 : 3;
    why = set.planar ? "two distinct points fix an in-plane posture"
                     : "three non-collinear points fix a rotation";
  } else if (allowScale) {
    minPoints = 2;
    why = "two distinct points fix a scale";
  } else {
    why = "a translation needs one point";
  }
  if (n < minPoints) {
    throw ValidationError(ctx, "has " + std::to_string(n) + " point" + (n == 1 ? "" : "s") + ", the " +
                                   method + " needs at least " + std::to_string(minPoints) + " (" + why +
                                   ")");
  }
  if (k == 0) return;

  // Centroid and spread of the nominal points.
  Eigen::Vector3d qMean = Eigen::Vector3d::Zero();
  for (const auto& p : set.points) qMean += p.nominal;
  qMean /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  double extent = 0.0;
  for (const auto& p : set.points) {
    const Eigen::Vector3d d = p.nominal - qMean;
    scatter += d * d.transpose();
    extent = std::max(extent, d.norm());
  }
  const double scaleRef = std::max(1.0, qMean.norm() + extent);
  const bool coincident = extent <= 1e-9 * scaleRef;
  if (coincident && (rotationFree || allowScale)) {
    throw ValidationError(ctx,
                          "all " + std::to_string(n) + " nominal points coincide: the " + method +
                              " cannot determine a rotation or scale from them; probe distinct points or "
                              "lock rx, ry, rz");
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spread(scatter);
  const Eigen::Vector3d ev = spread.eigenvalues();               // ascending
  const bool collinear = !coincident && ev(1) <= 1e-14 * ev(2);  // spread across the line < 1e-7 along it

  // Normal matrix of the Jacobian at the nominal posture; rotation columns about the centroid when
  // all translations are free (a reparametrisation that keeps the rank and improves conditioning).
  const bool allTranslationsFree = !locks.locked[3] && !locks.locked[4] && !locks.locked[5];
  const Eigen::Vector3d origin = allTranslationsFree ? qMean : Eigen::Vector3d::Zero();
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  Eigen::MatrixXd rows(alongNormals ? 1 : 3, static_cast<Eigen::Index>(k));
  for (const auto& p : set.points) {
    const Eigen::Vector3d q = p.nominal - origin;
    Eigen::Index c = 0;
    for (int j = 0; j < kDofCount; ++j) {
      if (locks.locked[j]) continue;
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(j % 3);
      if (alongNormals) {
        rows(0, c) = j < 3 ? q.cross(p.normal)(j) : p.normal(j - 3);
      } else {
        rows.col(c) = j < 3 ? Eigen::Vector3d(e.cross(q)) : e;
      }
      ++c;
    }
    if (allowScale) {
      if (alongNormals)
        rows(0, c) = q.dot(p.normal);
      else
        rows.col(c) = q;
    }
    N.noalias() += rows.transpose() * rows;
  }
  Eigen::Index zeroColumn = -1;
  Eigen::VectorXd d(k);
  for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(k); ++c) {
    if (!(N(c, c) > 0.0)) zeroColumn = c;
    d(c) = N(c, c) > 0.0 ? 1.0 / std::sqrt(N(c, c)) : 1.0;
  }
  Eigen::Index undetermined = zeroColumn;
  if (undetermined < 0) {
    const Eigen::MatrixXd Ns = d.asDiagonal() * N * d.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Ns);
    const Eigen::VectorXd lambda = es.eigenvalues();
    if (lambda(0) <= 1e-14 * lambda(lambda.size() - 1))
      es.eigenvectors().col(0).cwiseAbs().maxCoeff(&undetermined);
  }
  if (undetermined >= 0) {
    const std::string param = names[static_cast<std::size_t>(undetermined)];
    // The parameter as a Dof index (6: the scale), for locksToDetermine.
    int dof = kDofCount;
    for (int j = 0; j < kDofCount; ++j)
      if (param == dofName(j)) dof = j;
    if (collinear && rotationFree && !set.planar) {
      throw UndeterminedParameterError(
          ctx,
          "the nominal points are collinear (all on one line): the " + method +
              " cannot determine the rotation about that line; probe at least one "
              "point off the line or lock that rotation",
          dof);
    }
    if (alongNormals) {
      throw UndeterminedParameterError(ctx,
                                       "the normals leave " + param + " undetermined in the " + method +
                                           " (deviations are measured along the normals, e.g. all normals "
                                           "parallel); probe surfaces facing other directions or lock " +
                                           param,
                                       dof);
    }
    throw UndeterminedParameterError(ctx,
                                     "the probe points leave " + param + " undetermined in the " + method +
                                         "; add points that constrain it or lock " + param,
                                     dof);
  }

  // The measured points must carry the rotation too (a fit to collinear measurements is arbitrary).
  const int freeRotations = !locks.locked[0] + !locks.locked[1] + !locks.locked[2];
  if (!alongNormals && !set.planar && !collinear && freeRotations >= 2) {
    const CentredPoints c = centredPoints(set);
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(c.crossCovariance);
    const Eigen::Vector3d sv = svd.singularValues();
    if (!(sv(1) > 1e-9 * sv(0))) {
      throw ValidationError(ctx,
                            "the measured points are collinear or coincide although the nominal ones "
                            "are not: the " +
                                method + " cannot determine the rotation; check the measurement");
    }
  }
}

namespace {
bool determinable(const ProbePointSet& set, const DofLocks& locks, bool allowScale, FitKind kind) {
  try {
    requireDeterminable(set, effectiveLocks(set, locks), allowScale, kind, "fit");
    return true;
  } catch (const ValidationError&) {
    return false;
  }
}
}  // namespace

std::optional<DofLocks> locksToDetermine(const ProbePointSet& set, const DofLocks& locks, bool allowScale,
                                         FitKind kind) {
  // How many locks are missing: lock the parameter each refusal names until the fit is determinable.
  // The null direction often mixes a rotation with translations (a sphere cap rotated about its centre,
  // not about the centroid), so the named parameter may be a translation.
  DofLocks greedy = locks;
  int missing = 0;
  for (;;) {
    try {
      requireDeterminable(set, effectiveLocks(set, greedy), allowScale, kind, "fit");
      break;
    } catch (const UndeterminedParameterError& e) {
      if (e.parameter() >= kDofCount || greedy.locked[e.parameter()]) return std::nullopt;
      greedy.lock(static_cast<Dof>(e.parameter()), 0.0);
      ++missing;
    } catch (const ValidationError&) {
      return std::nullopt;  // too few points, measured points collinear: no lock helps
    }
  }
  if (missing == 0) return locks;
  // As many locks on rotations instead, when some choice of them is enough: a shop holds the part's
  // orientation from its fixture and measures its position.
  std::vector<int> freeRotations;
  for (int j = 0; j < 3; ++j)
    if (!effectiveLocks(set, locks).locked[j]) freeRotations.push_back(j);
  if (missing <= static_cast<int>(freeRotations.size())) {
    const int n = static_cast<int>(freeRotations.size());
    for (int mask = 0; mask < (1 << n); ++mask) {
      DofLocks candidate = locks;
      int chosen = 0;
      for (int b = 0; b < n; ++b) {
        if ((mask & (1 << b)) == 0) continue;
        candidate.lock(static_cast<Dof>(freeRotations[static_cast<std::size_t>(b)]), 0.0);
        ++chosen;
      }
      if (chosen == missing && determinable(set, candidate, allowScale, kind)) return candidate;
    }
  }
  return greedy;
}

CentredPoints centredPoints(const ProbePointSet& set) {
  CentredPoints c;
  c.n = set.points.size();
  const auto n = static_cast<Eigen::Index>(c.n);
  c.qc.resize(3, n);
  c.pc.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    c.qMean += set.points[static_cast<std::size_t>(i)].nominal;
    c.pMean += set.points[static_cast<std::size_t>(i)].measured;
  }
  if (n > 0) {
    c.qMean /= static_cast<double>(n);
    c.pMean /= static_cast<double>(n);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    c.qc.col(i) = set.points[static_cast<std::size_t>(i)].nominal - c.qMean;
    c.pc.col(i) = set.points[static_cast<std::size_t>(i)].measured - c.pMean;
  }
  c.crossCovariance.noalias() = c.pc * c.qc.transpose();
  c.sqq = c.qc.squaredNorm();
  c.spp = c.pc.squaredNorm();
  return c;
}

Pose optimalTranslationScale(const CentredPoints& c, const Eigen::Matrix3d& R, const DofLocks& locks,
                             bool allowScale, double* sumSquares) {
  // With t = F (mean(p) - s R mean(q)) + (I - F) v (F: free translation components, v: locked values)
  // the residuals are r_i = pc_i - s R qc_i + (u - s w), u = (I-F)(mean(p) - v), w = (I-F) R mean(q),
  // and the centred sums vanish, so  SS(s) = sum |pc_i - s R qc_i|^2 + n |u - s w|^2, minimal at
  //   s = (tr(R K^T) + n w.u) / (sum |qc|^2 + n |w|^2).
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), free = Eigen::Vector3d::Ones();
  for (int j = 0; j < 3; ++j) {
    if (locks.locked[3 + j]) {
      free(j) = 0.0;
      v(j) = locks.value[3 + j];
    }
  }
  const Eigen::Vector3d Rq = R * c.qMean;
  const Eigen::Vector3d u = (Eigen::Vector3d::Ones() - free).cwiseProduct(c.pMean - v);
  const Eigen::Vector3d w = (Eigen::Vector3d::Ones() - free).cwiseProduct(Rq);
  const double nd = static_cast<double>(c.n);
  double s = 1.0;
  if (allowScale) {
    const double a = (R.array() * c.crossCovariance.array()).sum();
    const double den = c.sqq + nd * w.squaredNorm();
    if (den > 0.0) s = (a + nd * w.dot(u)) / den;
  }
  Pose pose;
  pose.rotation = R;
  pose.scale = s;
  pose.translation = free.cwiseProduct(c.pMean - s * Rq) + (Eigen::Vector3d::Ones() - free).cwiseProduct(v);
  if (sumSquares) {
    *sumSquares = (c.pc - s * (R * c.qc)).squaredNorm() + nd * (u - s * w).squaredNorm();
  }
  return pose;
}

}  // namespace metrofit::matching
