#include "core/matching/cad_match.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/geometry/point_table.h"
#include "core/io/csv.h"
#include "core/matching/fit_input.h"
#include "core/optim/least_squares.h"

namespace metrofit::matching {
namespace {

/// The posture whose free parameters are those of `start` and whose locked ones keep their values.
PoseParams paramsWithLocks(const Pose& start, const DofLocks& locks) {
  PoseParams x;
  x.angles = eulerZyx(start.rotation);
  x.t = start.translation;
  x.s = start.scale;
  for (int j = 0; j < 3; ++j)
    if (locks.locked[j]) x.angles(j) = locks.value[j] * kRadPerDeg;
  for (int j = 3; j < 6; ++j)
    if (locks.locked[j]) x.t(j - 3) = locks.value[j];
  return x;
}

/// The least-squares step (header, step 2): minimises sum d_i^2 over the free parameters from `start`
/// with the shared Levenberg-Marquardt solver. Adds the residual and Jacobian evaluations to *evals.
Pose pointToPlaneStep(const ProbePointSet& set, const Pose& start, const DofLocks& locks, bool allowScale,
                      int maxIterations, long* evals, std::string* failure) {
  std::vector<int> freeIdx;
  for (int j = 0; j < kDofCount; ++j)
    if (!locks.locked[j]) freeIdx.push_back(j);
  if (allowScale) freeIdx.push_back(6);
  PoseParams x = paramsWithLocks(start, locks);
  const auto k = static_cast<Eigen::Index>(freeIdx.size());
  if (k == 0) return x.pose();
  auto paramsOf = [&](const Eigen::VectorXd& v) {
    PoseParams p = x;
    for (Eigen::Index c = 0; c < k; ++c) {
      const int j = freeIdx[static_cast<std::size_t>(c)];
      if (j < 3)
        p.angles(j) = v(c);
      else if (j < 6)
        p.t(j - 3) = v(c);
      else
        p.s = v(c);
    }
    return p;
  };
  const auto rows = static_cast<Eigen::Index>(set.points.size());
  const optim::Residual f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    const PoseParams q = paramsOf(v);
    const Eigen::Matrix3d R = rotationZyx(q.angles);
    const auto dR = rotationZyxDerivatives(q.angles);
    r.resize(rows);
    if (J) J->resize(rows, k);
    for (Eigen::Index i = 0; i < rows; ++i) {
      const ProbePoint& p = set.points[static_cast<std::size_t>(i)];
      const Eigen::Vector3d Rq = R * p.nominal, Rn = R * p.normal;
      const Eigen::Vector3d u = p.measured - q.s * Rq - q.t;
      r(i) = u.dot(Rn);
      if (!J) continue;
      for (Eigen::Index c = 0; c < k; ++c) {
        const int j = freeIdx[static_cast<std::size_t>(c)];
        if (j < 3) {
          const Eigen::Matrix3d& D = dR[static_cast<std::size_t>(j)];
          (*J)(i, c) = -q.s * (D * p.nominal).dot(Rn) + u.dot(D * p.normal);
        } else if (j < 6) {
          (*J)(i, c) = -Rn(j - 3);
        } else {
          (*J)(i, c) = -p.nominal.dot(p.normal);
        }
      }
    }
  };
  optim::LeastSquaresOptions lo;
  lo.maxIterations = maxIterations;
  lo.initialDamping = 1e-9;  // Gauss-Newton until a step fails (as closed_form.cpp)
  lo.costTolerance = 0.0;
  lo.stepTolerance = 1e-15;
  Eigen::VectorXd v(k);
  for (Eigen::Index c = 0; c < k; ++c) {
    const int j = freeIdx[static_cast<std::size_t>(c)];
    v(c) = j < 3 ? x.angles(j) : j < 6 ? x.t(j - 3) : x.s;
  }
  const optim::LeastSquaresSummary sum = optim::solveLeastSquares(f, v, lo);
  *evals += sum.residualEvaluations + sum.jacobianEvaluations;
  if (optim::toTermination(sum.termination) == Termination::Failed) *failure = sum.message;
  return paramsOf(v).pose();
}

double largestDisplacement(const ProbePointSet& set, const Pose& a, const Pose& b) {
  double m = 0.0;
  for (const ProbePoint& p : set.points) m = std::max(m, (a.apply(p.nominal) - b.apply(p.nominal)).norm());
  return m;
}

}  // namespace

bool CadMatchOptions::isValid(std::string* why) const {
  auto no = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (method != MatchMethod::ClosedForm && method != MatchMethod::Minimax)
    return no(std::string("matching to a CAD surface takes closed-form (least squares) or minimax, not ") +
              toString(method) + " (it needs nominal point pairs for its rough matching)");
  if (!(toleranceMm >= 0.0) || !std::isfinite(toleranceMm))
    return no("the tolerance must be a finite number >= 0 mm");
  if (maxIterations < 1) return no("the iteration limit must be >= 1");
  if (fitIterations < 1) return no("the least-squares iteration limit must be >= 1");
  if (!(convergenceMm > 0.0) || !std::isfinite(convergenceMm))
    return no("the convergence limit must be a finite number > 0 mm");
  std::string w;
  if (!locks.isValid(&w)) return no(w);
  if (!minimax.isValid(&w)) return no(w);
  return true;
}

ProbePointSet projectToCad(const ProbePointSet& measured, const geometry::MeshSearch& cad, const Pose& pose,
                           std::vector<geometry::MeshPoint>* answers) {
  ProbePointSet set;
  set.source = measured.source;
  set.hasNormals = true;
  set.planar = false;
  set.points.reserve(measured.points.size());
  if (answers) answers->clear();
  const Pose inverse = pose.inverse();
  for (const ProbePoint& m : measured.points) {
    const geometry::MeshPoint c = cad.closest(inverse.apply(m.measured));
    ProbePoint p;
    p.id = m.id;
    p.surface = m.surface;
    p.nominal = c.point;
    p.normal = c.direction;
    p.measured = m.measured;
    set.points.push_back(std::move(p));
    if (answers) answers->push_back(c);
  }
  return set;
}

CadMatchResult matchToCad(const ProbePointSet& measured, const geometry::MeshSearch& cad,
                          const CadMatchOptions& o, Observer* observer) {
  requireValid(o, "CAD matching options");
  if (measured.points.empty())
    throw ValidationError(ErrorContext{measured.source, 0, 0, {}}, "has no measured points");
  CadMatchResult res;
  res.cadSource = cad.mesh().source;
  res.triangles = cad.mesh().triangles.size();
  res.windingDisagreements = cad.mesh().windingDisagreements;
  MatchResult& mr = res.match;
  mr.method = o.method;
  mr.allowScale = o.allowScale;
  mr.locks = o.locks;

  res.before = projectToCad(measured, cad, Pose{});
  const std::string label = o.method == MatchMethod::Minimax ? "minimax fit to the CAD surface"
                                                             : "least-squares fit to the CAD surface";
  requireDeterminable(res.before, mr.locks, o.allowScale,
                      o.method == MatchMethod::Minimax ? FitKind::Minimax : FitKind::PointToPlane, label);
  mr.before = evaluateTolerance(res.before, Pose{}, o.toleranceMm);

  Pose pose = paramsWithLocks(Pose{}, mr.locks).pose();
  ProbePointSet current = projectToCad(measured, cad, pose);
  mr.run.termination = Termination::MaxIterations;
  mr.run.message = "iteration limit reached (" + std::to_string(o.maxIterations) + ")";
  long evaluations = 0;
  std::vector<MinimaxResult> minimaxRuns;
  for (int k = 0; k < o.maxIterations; ++k) {
    Pose next;
    std::string failure;
    if (o.method == MatchMethod::ClosedForm) {
      next = pointToPlaneStep(current, pose, mr.locks, o.allowScale, o.fitIterations, &evaluations, &failure);
    } else {
      MinimaxOptions mo = o.minimax;
      mo.allowScale = o.allowScale;
      mo.locks = mr.locks;
      mo.keepTrace = false;
      MinimaxResult m = minimaxFit(current, pose, mo);
      evaluations += m.run.evaluations;
      next = m.pose;
      mr.minimax = std::move(m);
    }
    const double change = largestDisplacement(current, pose, next);
    pose = next;
    const ToleranceEvaluation step = evaluateTolerance(current, pose, o.toleranceMm);
    IterationSummary s;
    s.iteration = k;
    s.evaluations = evaluations;
    s.best = o.method == MatchMethod::Minimax ? step.overall.maxAbsMm : step.overall.rmseMm;
    s.components = {
        {"rmse_mm", step.overall.rmseMm}, {"max_abs_mm", step.overall.maxAbsMm}, {"pose_change_mm", change}};
    const Eigen::Vector3d a = pose.anglesDeg();
    s.bestX = {a.x(), a.y(), a.z(), pose.translation.x(), pose.translation.y(), pose.translation.z()};
    s.progress = static_cast<double>(k + 1) / o.maxIterations;
    if (!failure.empty()) {
      mr.run.iterations = k + 1;
      mr.run.termination = Termination::Failed;
      mr.run.message = "least-squares step failed: " + failure;
      break;
    }
    if (notify(observer, mr.run, s, o.keepTrace)) break;
    current = projectToCad(measured, cad, pose);
    if (change <= o.convergenceMm) {
      mr.run.termination = Termination::Converged;
      mr.run.message = "converged after " + std::to_string(k + 1) +
                       " iterations (posture change <= " + num::general(o.convergenceMm, 3) + " mm)";
      break;
    }
  }
  mr.run.evaluations = evaluations;
  mr.pose = pose;
  res.after = projectToCad(measured, cad, pose, &res.closestAfter);
  mr.after = evaluateTolerance(res.after, pose, o.toleranceMm);
  for (const double d : mr.after.distances) res.maxDistanceMm = std::max(res.maxDistanceMm, d);
  return res;
}

nlohmann::json toJson(const CadMatchResult& r) {
  nlohmann::json j = toJson(r.match, r.after);
  j["cad"] = {{"file", r.cadSource},
              {"triangles", r.triangles},
              {"max_distance_mm", r.maxDistanceMm},
              {"winding_disagreements", r.windingDisagreements},
              {"fit", r.match.method == MatchMethod::Minimax
                          ? "minimax point-to-plane, iterated closest points"
                          : "least-squares point-to-plane, iterated closest points"}};
  return j;
}

ProbePointSet measuredPointsFromCsv(const CsvTable& t) {
  // The columns and their checks: one owner (core/geometry/point_table.h).
  const geometry::PointSet points = geometry::pointsFromTable(t);
  ProbePointSet set;
  set.source = t.source();
  set.hasNormals = false;
  set.planar = false;
  const int surface = t.columnIndex("surface");
  for (std::size_t r = 0; r < points.points.size(); ++r) {
    ProbePoint p;
    p.id = points.ids.empty() ? std::to_string(r + 1) : points.ids[r];
    if (surface >= 0) p.surface = t.cell(r, static_cast<std::size_t>(surface));
    p.measured = points.points[r];
    set.points.push_back(std::move(p));
  }
  if (set.points.empty()) throw ValidationError(ErrorContext{t.source(), 0, 0, {}}, "has no measured points");
  return set;
}

ProbePointSet readMeasuredPoints(const std::string& path, const CsvReadOptions& csv) {
  return measuredPointsFromCsv(readCsvFile(path, csv));
}

std::vector<double> triangleDeviations(const geometry::TriangleMesh& mesh, const ProbePointSet& closest,
                                       const std::vector<double>& deviations, double radiusMm) {
  const std::size_t n = std::min(closest.points.size(), deviations.size());
  std::vector<double> out(mesh.triangles.size(), std::numeric_limits<double>::quiet_NaN());
  if (n == 0 || mesh.triangles.empty()) return out;
  const double size = (mesh.boxMax() - mesh.boxMin()).norm();
  if (!(radiusMm > 0.0)) {
    // 1.5 x the median nearest-neighbour distance of the points (n is a probing program's points:
    // tens to thousands, so the quadratic search is cheap).
    std::vector<double> nearest;
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) best = std::min(best, (closest.points[i].nominal - closest.points[j].nominal).norm());
      if (std::isfinite(best)) nearest.push_back(best);
    }
    double median = size;
    if (!nearest.empty()) {
      std::nth_element(nearest.begin(), nearest.begin() + static_cast<long>(nearest.size() / 2),
                       nearest.end());
      median = nearest[nearest.size() / 2];
    }
    radiusMm = std::max(1.5 * median, 1e-3 * size);
  }
  if (!(radiusMm > 0.0)) radiusMm = 1.0;
  // A grid of cells of the radius: a centroid's nearest point within the radius is in its cell or a
  // neighbouring one.
  const Eigen::Vector3d origin = mesh.boxMin();
  const auto cellOf = [&](const Eigen::Vector3d& x) {
    return std::array<long, 3>{static_cast<long>(std::floor((x.x() - origin.x()) / radiusMm)),
                               static_cast<long>(std::floor((x.y() - origin.y()) / radiusMm)),
                               static_cast<long>(std::floor((x.z() - origin.z()) / radiusMm))};
  };
  std::map<std::array<long, 3>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < n; ++i) grid[cellOf(closest.points[i].nominal)].push_back(i);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const geometry::Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d c = (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0;
    const std::array<long, 3> k = cellOf(c);
    double best = radiusMm;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (std::size_t i : it->second) {
            const double d = (closest.points[i].nominal - c).norm();
            if (d <= best) {
              best = d;
              out[t] = deviations[i];
            }
          }
        }
  }
  return out;
}

}  // namespace metrofit::matching
