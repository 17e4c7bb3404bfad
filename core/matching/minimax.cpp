#include "core/matching/minimax.h"

#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/common/error.h"
#include "core/common/glpk_quiet.h"
#include "core/matching/evaluation.h"

namespace metrofit::matching {
namespace {

struct LpDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

using Params = PoseParams;

class Model {
 public:
  Model(const ProbePointSet& set, std::vector<int> freeIdx, double lengthScale)
      : set_(set), free_(std::move(freeIdx)), L_(lengthScale) {}

  std::size_t k() const { return free_.size(); }

  /// Exact F = max |d_i|.
  double maxAbs(const Params& x) const { return maxAbsDeviation(set_, x.pose()); }

  /// Deviations and their gradients w.r.t. the scaled free variables (rows of G).
  void linearise(const Params& x, Eigen::VectorXd& d, Eigen::MatrixXd& G) const {
    const std::size_t n = set_.points.size();
    const auto kk = static_cast<Eigen::Index>(k());
    d.resize(static_cast<Eigen::Index>(n));
    G.resize(static_cast<Eigen::Index>(n), kk);
    const Eigen::Matrix3d R = rotationZyx(x.angles);
    const auto dR = rotationZyxDerivatives(x.angles);
    for (std::size_t i = 0; i < n; ++i) {
      const ProbePoint& p = set_.points[i];
      const auto row = static_cast<Eigen::Index>(i);
      if (set_.hasNormals) {
        const Eigen::Vector3d pt = p.measured - x.t;
        const Eigen::Vector3d Rn = R * p.normal;
        d(row) = pt.dot(Rn) - x.s * p.nominal.dot(p.normal);
        for (Eigen::Index c = 0; c < kk; ++c) {
          const int j = free_[static_cast<std::size_t>(c)];
          double g;
          if (j < 3)
            g = pt.dot(dR[static_cast<std::size_t>(j)] * p.normal) / L_;
          else if (j < 6)
            g = -Rn(j - 3);
          else
            g = -p.nominal.dot(p.normal) / L_;
          G(row, c) = g;
        }
      } else {
        const Eigen::Vector3d Rq = R * p.nominal;
        const Eigen::Vector3d r = p.measured - x.s * Rq - x.t;
        const double e = r.norm();
        d(row) = e;
        const Eigen::Vector3d u = e > 0.0 ? Eigen::Vector3d(r / e) : Eigen::Vector3d::Zero();
        for (Eigen::Index c = 0; c < kk; ++c) {
          const int j = free_[static_cast<std::size_t>(c)];
          double g;
          if (j < 3)
            g = -x.s * u.dot(dR[static_cast<std::size_t>(j)] * p.nominal) / L_;
          else if (j < 6)
            g = -u(j - 3);
          else
            g = -u.dot(Rq) / L_;
          G(row, c) = g;
        }
      }
    }
  }

  Params step(const Params& x, const Eigen::VectorXd& dx) const {
    Params y = x;
    for (std::size_t c = 0; c < k(); ++c) {
      const int j = free_[c];
      const double v = dx(static_cast<Eigen::Index>(c));
      if (j < 3)
        y.angles(j) += v / L_;
      else if (j < 6)
        y.t(j - 3) += v;
      else
        y.s += v / L_;
    }
    return y;
  }

 private:
  const ProbePointSet& set_;
  std::vector<int> free_;
  double L_;
};

/// Solves the trust-region LP; returns false when GLPK does not report an optimum.
bool solveLp(const Eigen::VectorXd& d, const Eigen::MatrixXd& G, bool twoSided, double delta,
             Eigen::VectorXd& dx, double& z) {
  const int n = static_cast<int>(d.size());
  const int k = static_cast<int>(G.cols());
  std::unique_ptr<glp_prob, LpDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MIN);
  glp_add_cols(lp.get(), k + 1);
  for (int c = 1; c <= k; ++c) glp_set_col_bnds(lp.get(), c, GLP_DB, -delta, delta);
  glp_set_col_bnds(lp.get(), k + 1, GLP_FR, 0.0, 0.0);
  glp_set_obj_coef(lp.get(), k + 1, 1.0);
  const int rows = twoSided ? 2 * n : n;
  glp_add_rows(lp.get(), rows);
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  const std::size_t nnz = static_cast<std::size_t>(rows) * static_cast<std::size_t>(k + 1);
  ia.reserve(nnz + 1);
  ja.reserve(nnz + 1);
  ar.reserve(nnz + 1);
  int r = 0;
  for (int i = 0; i < n; ++i) {
    for (int sign : {1, -1}) {
      if (sign < 0 && !twoSided) continue;
      ++r;
      // sign (d_i + g_i dx) - z <= 0
      glp_set_row_bnds(lp.get(), r, GLP_UP, 0.0, -sign * d(i));
      for (int c = 0; c < k; ++c) {
        ia.push_back(r);
        ja.push_back(c + 1);
        ar.push_back(sign * G(i, c));
      }
      ia.push_back(r);
      ja.push_back(k + 1);
      ar.push_back(-1.0);
    }
  }
  glp_load_matrix(lp.get(), static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;
  parm.tol_bnd = 1e-10;
  parm.tol_dj = 1e-10;
  // Rows are already scaled (gradients O(1) in mm per mm, rotations and scale times L), so GLPK's own
  // scaling (which prints) is not used. Core never prints: GLPK's terminal output is off meanwhile.
  const GlpkQuiet quiet;
  if (glp_simplex(lp.get(), &parm) != 0 || glp_get_status(lp.get()) != GLP_OPT) {
    // Retry with a presolved problem before giving up.
    glp_std_basis(lp.get());
    parm.presolve = GLP_ON;
    if (glp_simplex(lp.get(), &parm) != 0 || glp_get_status(lp.get()) != GLP_OPT) return false;
  }
  z = glp_get_obj_val(lp.get());
  dx.resize(k);
  for (int c = 0; c < k; ++c) dx(c) = glp_get_col_prim(lp.get(), c + 1);
  return std::isfinite(z) && dx.allFinite();
}

}  // namespace

bool MinimaxOptions::isValid(std::string* why) const {
  if (maxIterations < 1) {
    if (why) *why = "the minimax iteration limit must be >= 1";
    return false;
  }
  if (!(initialTrustMm >= 0.0) || !std::isfinite(initialTrustMm)) {
    if (why) *why = "the initial trust region must be >= 0 mm";
    return false;
  }
  return locks.isValid(why);
}

MinimaxResult minimaxFit(const ProbePointSet& set, const Pose& start, const MinimaxOptions& o,
                         Observer* observer) {
  requireValid(o, "minimax options");
  if (set.points.empty())
    throw ValidationError(ErrorContext{set.source, 0, 0, {}}, "has no probe points to fit");
  for (const auto& p : set.points) {
    if (!p.nominal.allFinite() || !p.measured.allFinite() || !p.normal.allFinite())
      throw ValidationError(ErrorContext{set.source, 0, 0, p.id}, "non-finite coordinate");
  }
  std::vector<int> freeIdx;
  for (int j = 0; j < kDofCount; ++j)
    if (!o.locks.locked[j]) freeIdx.push_back(j);
  if (o.allowScale) freeIdx.push_back(6);

  // RMS radius of the nominal points about their centroid.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : set.points) mean += p.nominal;
  mean /= static_cast<double>(set.points.size());
  double r2 = 0.0;
  for (const auto& p : set.points) r2 += (p.nominal - mean).squaredNorm();
  const double L = std::max(1.0, std::sqrt(r2 / static_cast<double>(set.points.size())));

  Params x;
  x.angles = eulerZyx(start.rotation);
  x.t = start.translation;
  x.s = o.allowScale ? start.scale : 1.0;
  for (int j = 0; j < kDofCount; ++j) {
    if (!o.locks.locked[j]) continue;
    if (j < 3)
      x.angles(j) = o.locks.value[j] * kRadPerDeg;
    else
      x.t(j - 3) = o.locks.value[j];
  }
  const Model model(set, freeIdx, L);

  MinimaxResult res;
  double F = model.maxAbs(x);
  res.startMaxAbsMm = F;
  double delta = o.initialTrustMm > 0.0 ? o.initialTrustMm : std::max(F, 1e-3);
  res.run.termination = Termination::MaxIterations;
  res.run.message = "minimax iteration limit reached";
  Eigen::VectorXd d, dx;
  Eigen::MatrixXd G;
  if (model.k() == 0) {
    res.run.termination = Termination::Converged;
    res.run.message = "every parameter is locked";
  } else {
    for (int it = 0; it < o.maxIterations; ++it) {
      model.linearise(x, d, G);
      double z = 0.0;
      ++res.lpSolves;
      if (!solveLp(d, G, set.hasNormals, delta, dx, z)) {
        res.run.termination = Termination::Failed;
        res.run.message =
            "the linear program of iteration " + std::to_string(it + 1) + " has no optimum (GLPK)";
        break;
      }
      const double predicted = F - z;
      res.lastPredictedDecreaseMm = predicted;
      bool stop = false;
      if (predicted <= 1e-12 * (1.0 + F)) {
        res.run.termination = Termination::Converged;
        res.run.message = "no descent direction within the trust region (first-order minimax optimum)";
        stop = true;
      } else {
        const Params y = model.step(x, dx);
        const double Fy = model.maxAbs(y);
        const double ratio = (F - Fy) / predicted;
        const double stepLen = dx.lpNorm<Eigen::Infinity>();
        if (ratio >= 0.01) {
          x = y;
          F = Fy;
          if (ratio > 0.75 && stepLen >= 0.99 * delta) delta *= 2.0;
          if (ratio < 0.25) delta = std::max(stepLen / 4.0, 1e-300);
        } else {
          delta = std::max(stepLen / 4.0, 1e-300);
        }
        if (delta < 1e-12 * (1.0 + L)) {
          res.run.termination = Termination::Converged;
          res.run.message = "trust region below 1e-12 mm: no further decrease possible";
          stop = true;
        }
      }
      IterationSummary s;
      s.iteration = it;
      s.evaluations = res.lpSolves;
      s.best = F;
      s.components = {{"trust_region_mm", delta}, {"predicted_decrease_mm", predicted}};
      if (notify(observer, res.run, s, o.keepTrace)) break;
      if (stop) break;
    }
  }
  res.pose = x.pose();
  res.finalTrustMm = delta;
  res.maxAbsMm = maxAbsDeviation(set, res.pose);
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    const ProbePoint& p = set.points[i];
    const double di = std::abs(set.deviation(i, res.pose.apply(p.nominal), res.pose.rotation * p.normal));
    if (di >= res.maxAbsMm - 1e-9) res.active.push_back(i);
  }
  res.run.evaluations = res.lpSolves;
  return res;
}

}  // namespace metrofit::matching
