// Minimum-zone (Chebyshev) element fit: sequential linear programming and its certificate
// (element_fit.h explains the method and what the certificate means).
#include <glpk.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/common/glpk_quiet.h"
#include "core/common/numformat.h"
#include "core/geometry/element_model.h"

namespace metrofit::geometry::detail {
namespace {

struct LpDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

struct LpSolution {
  Eigen::VectorXd dx;
  double z = 0.0;
  Eigen::VectorXd rowDual;  ///< GLPK's row duals, rows in the order (i, +), (i, -)
};

/// minimise t  s.t.  s (d_i + G_i dx) - t <= 0 (s = +1, and -1 when twoSided), |dx_j| <= box.
bool solveZoneLp(const Eigen::VectorXd& d, const Eigen::MatrixXd& G, bool twoSided, double box,
                 LpSolution& out) {
  const int n = static_cast<int>(d.size());
  const int k = static_cast<int>(G.cols());
  std::unique_ptr<glp_prob, LpDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MIN);
  glp_add_cols(lp.get(), k + 1);
  for (int c = 1; c <= k; ++c) glp_set_col_bnds(lp.get(), c, GLP_DB, -box, box);
  glp_set_col_bnds(lp.get(), k + 1, GLP_FR, 0.0, 0.0);
  glp_set_obj_coef(lp.get(), k + 1, 1.0);
  const int rows = twoSided ? 2 * n : n;
  glp_add_rows(lp.get(), rows);
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  int r = 0;
  for (int i = 0; i < n; ++i) {
    for (int sign : {1, -1}) {
      if (sign < 0 && !twoSided) continue;
      ++r;
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
  const GlpkQuiet quiet;  // core never prints
  if (glp_simplex(lp.get(), &parm) != 0 || glp_get_status(lp.get()) != GLP_OPT) {
    glp_std_basis(lp.get());
    parm.presolve = GLP_ON;
    if (glp_simplex(lp.get(), &parm) != 0 || glp_get_status(lp.get()) != GLP_OPT) return false;
  }
  out.z = glp_get_obj_val(lp.get());
  out.dx.resize(k);
  for (int c = 0; c < k; ++c) out.dx(c) = glp_get_col_prim(lp.get(), c + 1);
  out.rowDual.resize(rows);
  for (int i = 0; i < rows; ++i) out.rowDual(i) = glp_get_row_dual(lp.get(), i + 1);
  return std::isfinite(out.z) && out.dx.allFinite() && out.rowDual.allFinite();
}

class Zone {
 public:
  Zone(const ElementModel& m, const std::vector<std::size_t>& idx) : m_(m), idx_(idx) {}

  double maxAbs(const Eigen::VectorXd& x) const {
    double f = 0.0;
    for (std::size_t i : idx_) {
      const double d = m_.residual(x, i);
      f = std::max(f, m_.oneSided() ? d : std::abs(d));
    }
    return f;
  }

  /// Residuals and their gradients with respect to the parameters in mm (central differences).
  void linearise(const Eigen::VectorXd& x, Eigen::VectorXd& d, Eigen::MatrixXd& G) const {
    const auto n = static_cast<Eigen::Index>(idx_.size());
    const int k = m_.size();
    d.resize(n);
    G.resize(n, k);
    for (Eigen::Index r = 0; r < n; ++r) d(r) = m_.residual(x, idx_[static_cast<std::size_t>(r)]);
    const double h = 1e-6 * std::max(1.0, m_.lengthScale());
    for (int j = 0; j < k; ++j) {
      Eigen::VectorXd xp = x, xm = x;
      xp(j) += h / m_.scale(j);
      xm(j) -= h / m_.scale(j);
      for (Eigen::Index r = 0; r < n; ++r) {
        const std::size_t i = idx_[static_cast<std::size_t>(r)];
        G(r, j) = (m_.residual(xp, i) - m_.residual(xm, i)) / (2.0 * h);
      }
    }
  }

  Eigen::VectorXd step(const Eigen::VectorXd& x, const Eigen::VectorXd& dxMm) const {
    Eigen::VectorXd y = x;
    for (int j = 0; j < m_.size(); ++j) y(j) += dxMm(j) / m_.scale(j);
    return y;
  }

 private:
  const ElementModel& m_;
  const std::vector<std::size_t>& idx_;
};

MinimaxCertificate certify(const ElementModel& m, const Zone& zone, const Eigen::VectorXd& x,
                           const std::vector<std::size_t>& idx, int& lpSolves) {
  MinimaxCertificate c;
  const bool twoSided = !m.oneSided();
  c.maxAbsMm = zone.maxAbs(x);
  Eigen::VectorXd d;
  Eigen::MatrixXd G;
  zone.linearise(x, d, G);
  LpSolution lp;
  // A box of the points' own size: it does not bind at a stationary point (then t* = max |d| for any
  // box); a binding bound shows as a non-zero stationarity below.
  const double box = std::max(1.0, m.lengthScale());
  ++lpSolves;
  const double tolPred = 1e-8 * (1.0 + c.maxAbsMm);
  const double tolStat = 1e-6;
  c.meaning =
      "first-order minimum-zone optimality at the final linearisation (GLPK simplex): the LP "
      "'minimise t, -t <= d_i + g_i.dx <= t' has optimum t* = max|d| (no improving direction), with "
      "dual multipliers lambda_i >= 0, sum 1, on the contact points and sum lambda_i s_i g_i = 0 "
      "(s_i = +1 outer, -1 inner contact); tolerances: max|d| - t* <= " +
      num::general(tolPred, 3) + " mm, stationarity <= " + num::general(tolStat, 3);
  if (!solveZoneLp(d, G, twoSided, box, lp)) {
    c.meaning = "no certificate: GLPK found no optimum of the final linear programme";
    return c;
  }
  c.lpOptimumMm = lp.z;
  c.predictedDecreaseMm = c.maxAbsMm - lp.z;
  Eigen::VectorXd s = Eigen::VectorXd::Zero(G.cols());
  c.minMultiplier = 0.0;
  bool first = true;
  for (Eigen::Index r = 0; r < lp.rowDual.size(); ++r) {
    const double lambda = -lp.rowDual(r);
    c.multiplierSum += lambda;
    const Eigen::Index i = twoSided ? r / 2 : r;
    const int side = twoSided && (r % 2 == 1) ? -1 : 1;
    s += lambda * side * G.row(i).transpose();
    if (std::abs(lambda) > 1e-12) {
      c.contacts.push_back({idx[static_cast<std::size_t>(i)], side, lambda});
      c.minMultiplier = first ? lambda : std::min(c.minMultiplier, lambda);
      first = false;
    }
  }
  c.stationarity = s.size() ? s.lpNorm<Eigen::Infinity>() : 0.0;
  c.holds = c.predictedDecreaseMm <= tolPred && c.stationarity <= tolStat && c.minMultiplier >= -1e-9 &&
            std::abs(c.multiplierSum - 1.0) <= 1e-6 && !c.contacts.empty();
  return c;
}

}  // namespace

MinimumZoneOutcome minimumZone(const ElementModel& m, Eigen::VectorXd x, const std::vector<std::size_t>& idx,
                               int maxIterations, Observer* observer) {
  MinimumZoneOutcome out;
  const Zone zone(m, idx);
  const bool twoSided = !m.oneSided();
  const double L = std::max(1.0, m.lengthScale());
  double F = zone.maxAbs(x);
  double delta = std::max(F, 1e-6 * L);
  out.termination = Termination::MaxIterations;
  out.message = "minimum zone: LP iteration limit reached";
  Eigen::VectorXd d;
  Eigen::MatrixXd G;
  RunInfo scratch;
  for (int it = 0; it < maxIterations; ++it) {
    zone.linearise(x, d, G);
    LpSolution lp;
    ++out.lpSolves;
    if (!solveZoneLp(d, G, twoSided, delta, lp)) {
      out.termination = Termination::Failed;
      out.message = "minimum zone: the linear programme of iteration " + std::to_string(it + 1) +
                    " has no optimum (GLPK)";
      break;
    }
    const double predicted = F - lp.z;
    if (predicted <= 1e-13 * (1.0 + F)) {
      out.termination = Termination::Converged;
      out.message = "minimum zone: no descent direction within the trust region";
      break;
    }
    const Eigen::VectorXd y = zone.step(x, lp.dx);
    const double Fy = zone.maxAbs(y);
    const double ratio = (F - Fy) / predicted;
    const double stepLen = lp.dx.lpNorm<Eigen::Infinity>();
    if (std::isfinite(Fy) && ratio >= 0.01) {
      x = y;
      F = Fy;
      if (ratio > 0.75 && stepLen > 0.99 * delta) delta *= 2.0;
    } else {
      delta = 0.25 * stepLen;
    }
    IterationSummary s;
    s.iteration = it;
    s.evaluations = out.lpSolves;
    s.best = F;
    s.components = {{"max_abs_mm", F}, {"trust_mm", delta}};
    s.progress = static_cast<double>(it + 1) / maxIterations;
    if (observer && observer->onIteration(s) == ObserverDecision::Stop) {
      out.termination = Termination::Cancelled;
      out.message = "stopped by observer";
      break;
    }
    if (delta < 1e-13 * L) {
      out.termination = Termination::Converged;
      out.message = "minimum zone: the trust region shrank below 1e-13 of the element's size";
      break;
    }
  }
  out.x = x;
  out.certificate = certify(m, zone, x, idx, out.lpSolves);
  return out;
}

}  // namespace metrofit::geometry::detail
