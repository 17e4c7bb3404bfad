#include "core/matching/evaluation.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/common/error.h"
#include "core/io/csv.h"

namespace metrofit::matching {
namespace {

struct Accumulator {
  std::size_t n = 0, out = 0;
  double sumSq = 0.0, maxAbs = 0.0, sumOver = 0.0;

  void add(double distance, double deviation, double tol) {
    ++n;
    sumSq += distance * distance;
    const double a = std::abs(deviation);
    maxAbs = std::max(maxAbs, a);
    if (a > tol) {
      ++out;
      sumOver += a - tol;
    }
  }
  DeviationStats stats() const {
    DeviationStats s;
    s.points = n;
    s.rmseMm = n ? std::sqrt(sumSq / static_cast<double>(n)) : 0.0;
    s.maxAbsMm = maxAbs;
    s.outOfTolerance = out;
    s.meanOverToleranceMm = out ? sumOver / static_cast<double>(out) : 0.0;
    return s;
  }
};

}  // namespace

ToleranceEvaluation evaluateTolerance(const ProbePointSet& set, const Pose& pose, double tol) {
  if (!(tol >= 0.0) || !std::isfinite(tol))
    throw OptionsError(ErrorContext{{}, 0, 0, "tolerance"}, "the tolerance must be a finite number >= 0 mm");
  if (set.points.empty())
    throw ValidationError(ErrorContext{set.source, 0, 0, {}}, "has no probe points to evaluate");
  ToleranceEvaluation ev;
  ev.toleranceMm = tol;
  const std::size_t n = set.points.size();
  ev.deviations.resize(n);
  ev.distances.resize(n);
  ev.residuals.resize(n);
  Accumulator all;
  std::vector<Accumulator> perSurface;
  std::unordered_map<std::string, std::size_t> surfaceIndex;
  double worst = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const ProbePoint& p = set.points[i];
    const Eigen::Vector3d qt = pose.apply(p.nominal);
    const Eigen::Vector3d nt = pose.rotation * p.normal;
    ev.residuals[i] = p.measured - qt;
    ev.distances[i] = ev.residuals[i].norm();
    ev.deviations[i] = set.deviation(i, qt, nt);
    all.add(ev.distances[i], ev.deviations[i], tol);
    auto [it, fresh] = surfaceIndex.emplace(p.surface, perSurface.size());
    if (fresh) {
      perSurface.emplace_back();
      ev.surfaces.push_back({p.surface, {}});
    }
    perSurface[it->second].add(ev.distances[i], ev.deviations[i], tol);
    if (std::abs(ev.deviations[i]) > worst) {
      worst = std::abs(ev.deviations[i]);
      ev.worstPoint = i;
    }
  }
  ev.overall = all.stats();
  for (std::size_t k = 0; k < perSurface.size(); ++k) ev.surfaces[k].stats = perSurface[k].stats();
  return ev;
}

std::string perPointCsv(const ToleranceEvaluation& ev, const ProbePointSet& set) {
  CsvWriter w;
  w.row({"id", "surface", "d_mm", "dx_mm", "dy_mm", "dz_mm"});
  for (std::size_t i = 0; i < set.points.size() && i < ev.residuals.size(); ++i) {
    const Eigen::Vector3d& r = ev.residuals[i];
    w.row({set.points[i].id, set.points[i].surface, CsvWriter::formatNumber(ev.deviations[i]),
           CsvWriter::formatNumber(r.x()), CsvWriter::formatNumber(r.y()), CsvWriter::formatNumber(r.z())});
  }
  return w.text();
}

double maxAbsDeviation(const ProbePointSet& set, const Pose& pose) {
  double m = 0.0;
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    const ProbePoint& p = set.points[i];
    m = std::max(m, std::abs(set.deviation(i, pose.apply(p.nominal), pose.rotation * p.normal)));
  }
  return m;
}

}  // namespace metrofit::matching
