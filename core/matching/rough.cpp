#include "core/matching/rough.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/common/error.h"

namespace metrofit::matching {
namespace {

/// Twice the triangle area.
double area2(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a).norm();
}

/// True when three points are collinear relative to their size (sin of the smallest angle ~ 0).
bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return !(longest > 0.0) || area2(a, b, c) <= 1e-9 * longest * longest;
}

/// Orders a triangle so that X0-X2 is the longest side and X1 the opposite vertex.
std::array<std::size_t, 3> ordered(const ProbePointSet& set, std::array<std::size_t, 3> t) {
  auto q = [&](std::size_t i) -> const Eigen::Vector3d& { return set.points[i].nominal; };
  const double d01 = (q(t[0]) - q(t[1])).norm(), d12 = (q(t[1]) - q(t[2])).norm(),
               d02 = (q(t[0]) - q(t[2])).norm();
  if (d01 >= d12 && d01 >= d02) return {t[0], t[2], t[1]};
  if (d12 >= d01 && d12 >= d02) return {t[1], t[0], t[2]};
  return t;
}

}  // namespace

bool localFrame(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                LocalFrame* frame) {
  if (collinear(x0, x1, x2)) return false;
  const Eigen::Vector3d i = (x2 - x0).normalized();
  const Eigen::Vector3d k = (x1 - x0).cross(i).normalized();
  const Eigen::Vector3d j = i.cross(k);
  frame->origin = x0;
  frame->axes.col(0) = i;
  frame->axes.col(1) = j;
  frame->axes.col(2) = k;
  return true;
}

std::array<std::size_t, 3> chooseReferencePoints(const ProbePointSet& set) {
  const std::size_t n = set.points.size();
  const ErrorContext ctx{set.source, 0, 0, {}};
  if (n < 3) {
    throw ValidationError(ctx, "has " + std::to_string(n) +
                                   " points, rough matching needs three non-collinear reference points");
  }
  auto q = [&](std::size_t i) -> const Eigen::Vector3d& { return set.points[i].nominal; };
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : set.points) mean += p.nominal;
  mean /= static_cast<double>(n);
  auto farthestFrom = [&](const Eigen::Vector3d& x) {
    std::size_t best = 0;
    double d = -1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double di = (q(i) - x).squaredNorm();
      if (di > d) {
        d = di;
        best = i;
      }
    }
    return best;
  };
  std::array<std::size_t, 3> t{};
  t[0] = farthestFrom(mean);
  t[1] = farthestFrom(q(t[0]));
  double best = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = area2(q(t[0]), q(t[1]), q(i));
    if (a > best) {
      best = a;
      t[2] = i;
    }
  }
  // Vertex exchange until the area is locally maximal (each accepted exchange enlarges it strictly).
  for (int sweep = 0; sweep < 100; ++sweep) {
    bool improved = false;
    for (int v = 0; v < 3; ++v) {
      const Eigen::Vector3d& a = q(t[(v + 1) % 3]);
      const Eigen::Vector3d& b = q(t[(v + 2) % 3]);
      for (std::size_t i = 0; i < n; ++i) {
        const double ai = area2(a, b, q(i));
        if (ai > best * (1.0 + 1e-12)) {
          best = ai;
          t[static_cast<std::size_t>(v)] = i;
          improved = true;
        }
      }
    }
    if (!improved) break;
  }
  if (collinear(q(t[0]), q(t[1]), q(t[2]))) {
    throw ValidationError(ctx,
                          "all nominal points are collinear: rough matching needs three non-collinear "
                          "reference points");
  }
  return ordered(set, t);
}

std::array<std::size_t, 3> referencePointsById(const ProbePointSet& set,
                                               const std::vector<std::string>& ids) {
  const ErrorContext ctx{set.source, 0, 0, "reference"};
  if (ids.size() != 3) {
    throw ValidationError(ctx, "rough matching takes exactly three reference point ids, " +
                                   std::to_string(ids.size()) + " given");
  }
  std::array<std::size_t, 3> t{};
  for (std::size_t k = 0; k < 3; ++k) {
    auto it = std::find_if(set.points.begin(), set.points.end(),
                           [&](const ProbePoint& p) { return p.id == ids[k]; });
    if (it == set.points.end()) throw ValidationError(ctx, "no point with id '" + ids[k] + "'");
    t[k] = static_cast<std::size_t>(it - set.points.begin());
    for (std::size_t m = 0; m < k; ++m) {
      if (t[m] == t[k]) throw ValidationError(ctx, "reference point '" + ids[k] + "' is given twice");
    }
  }
  const auto& P = set.points;
  if (collinear(P[t[0]].nominal, P[t[1]].nominal, P[t[2]].nominal)) {
    throw ValidationError(ctx, "the nominal reference points " + ids[0] + ", " + ids[1] + ", " + ids[2] +
                                   " are collinear: they do not span a local frame (Eq. 3)");
  }
  if (collinear(P[t[0]].measured, P[t[1]].measured, P[t[2]].measured)) {
    throw ValidationError(ctx, "the measured reference points " + ids[0] + ", " + ids[1] + ", " + ids[2] +
                                   " are collinear: they do not span a local frame (Eq. 3)");
  }
  return t;
}

RoughResult roughMatch(const ProbePointSet& set, const std::array<std::size_t, 3>& ref) {
  const auto& P = set.points;
  for (std::size_t r : ref) {
    if (r >= P.size()) throw std::out_of_range("rough matching: reference index out of range");
  }
  RoughResult res;
  res.reference = ref;
  if (!localFrame(P[ref[0]].nominal, P[ref[1]].nominal, P[ref[2]].nominal, &res.theoretical)) {
    throw ValidationError(ErrorContext{set.source, 0, 0, "reference"},
                          "the nominal reference points " + P[ref[0]].id + ", " + P[ref[1]].id + ", " +
                              P[ref[2]].id + " are collinear: they do not span a local frame (Eq. 3)");
  }
  if (!localFrame(P[ref[0]].measured, P[ref[1]].measured, P[ref[2]].measured, &res.actual)) {
    throw ValidationError(ErrorContext{set.source, 0, 0, "reference"},
                          "the measured reference points " + P[ref[0]].id + ", " + P[ref[1]].id + ", " +
                              P[ref[2]].id + " are collinear: they do not span a local frame (Eq. 3)");
  }
  // Eq. (4): A0 F_a = F_t.
  res.alignment = res.theoretical.axes * res.actual.axes.transpose();
  // Eq. (6): centroids of all points.
  Eigen::Vector3d qMean = Eigen::Vector3d::Zero(), pMean = Eigen::Vector3d::Zero();
  for (const auto& p : P) {
    qMean += p.nominal;
    pMean += p.measured;
  }
  qMean /= static_cast<double>(P.size());
  pMean /= static_cast<double>(P.size());
  res.alignmentTranslation = qMean - res.alignment * pMean;
  // Eq. (5) and (7).
  const Eigen::Vector3d angles = eulerZyxDeg(res.alignment);
  res.pe0 = {angles.x(),
             angles.y(),
             angles.z(),
             res.alignmentTranslation.x(),
             res.alignmentTranslation.y(),
             res.alignmentTranslation.z()};
  res.posture.rotation = res.alignment.transpose();
  res.posture.translation = -(res.alignment.transpose() * res.alignmentTranslation);
  return res;
}

RoughResult roughMatch(const ProbePointSet& set, const std::vector<std::string>& referenceIds) {
  return roughMatch(
      set, referenceIds.empty() ? chooseReferencePoints(set) : referencePointsById(set, referenceIds));
}

}  // namespace metrofit::matching
