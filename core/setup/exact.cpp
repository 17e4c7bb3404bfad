#include "core/setup/exact.h"

#include <glpk.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <set>

#include "core/common/glpk_quiet.h"

namespace metrofit::setup {
namespace {

constexpr double kEps = 1e-9;  ///< grid units: rounding guard for integer bounds and candidates
constexpr double kTau = 1e-6;  ///< grid units: "f1-optimal" means f1 >= f1* - 1e-6 s

/// Owns a GLPK problem object.
class GlpProblem {
 public:
  GlpProblem() : p_(glp_create_prob()) {}
  ~GlpProblem() { glp_delete_prob(p_); }
  GlpProblem(const GlpProblem&) = delete;
  GlpProblem& operator=(const GlpProblem&) = delete;
  glp_prob* get() const { return p_; }

 private:
  glp_prob* p_;
};

const char* statusName(int status) {
  switch (status) {
    case GLP_OPT:
      return "optimal";
    case GLP_FEAS:
      return "feasible";
    case GLP_INFEAS:
      return "infeasible";
    case GLP_NOFEAS:
      return "no feasible solution";
    case GLP_UNBND:
      return "unbounded";
    default:
      return "undefined";
  }
}

std::string failureName(int ret) {
  switch (ret) {
    case GLP_ETMLIM:
      return "time limit";
    case GLP_EITLIM:
      return "iteration limit";
    case GLP_EBADB:
      return "invalid basis";
    case GLP_ESING:
      return "singular basis";
    case GLP_ECOND:
      return "ill-conditioned basis";
    case GLP_EROOT:
      return "no optimal LP relaxation";
    case GLP_EFAIL:
      return "solver failure";
    case GLP_ESTOP:
      return "stopped";
    case GLP_ENOPFS:
      return "no primal feasible solution";
    default:
      return "error " + std::to_string(ret);
  }
}

/// A heuristic solution handed to glp_intopt at the first GLP_IHEUR call (1-based column values).
struct Incumbent {
  std::vector<double> values;
  bool given = false;
};

void intoptCallback(glp_tree* tree, void* info) {
  auto* inc = static_cast<Incumbent*>(info);
  if (glp_ios_reason(tree) == GLP_IHEUR && !inc->given && !inc->values.empty()) {
    inc->given = true;
    glp_ios_heur_sol(tree, inc->values.data());
  }
}

/// A distinct gain row with its merged right-hand sides (grid units).
struct Row {
  std::vector<std::pair<std::size_t, double>> g;
  double bp = std::numeric_limits<double>::infinity();
  double bm = std::numeric_limits<double>::infinity();
};

/// Loads rows into `lp` (columns 1..n are k); with `tCol` > 0 every row gets +t / -t (the max-min form: 2
/// rows per gain row), else one row per gain row (bounds set later).
void loadRows(glp_prob* lp, const std::vector<Row>& rows, int tCol) {
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  const int per = tCol > 0 ? 2 : 1;
  glp_add_rows(lp, static_cast<int>(rows.size()) * per);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const int row0 = static_cast<int>(r) * per + 1;
    for (int h = 0; h < per; ++h) {
      const int row = row0 + h;
      const double sign = h == 0 ? 1.0 : -1.0;
      if (tCol > 0) {
        glp_set_row_bnds(lp, row, GLP_UP, 0.0, h == 0 ? rows[r].bp : rows[r].bm);
        ia.push_back(row);
        ja.push_back(tCol);
        ar.push_back(1.0);
      }
      for (const auto& [i, g] : rows[r].g) {
        ia.push_back(row);
        ja.push_back(static_cast<int>(i) + 1);
        ar.push_back(sign * g);
      }
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
}

}  // namespace

bool ExactOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(timeLimitSeconds >= 0.0) || !std::isfinite(timeLimitSeconds))
    return no("the time limit must be >= 0 seconds");
  if (timeLimitSeconds > 2.0e6) return no("the time limit must be below 2e6 seconds");
  if (maxNormRounds < 1) return no("the least-norm stage needs at least one round");
  return true;
}

void releaseExactSolverThread() {
  glp_free_env();
}

ExactResult solveExact(const SetupInstance& inst, const ExactOptions& options, Observer* observer) {
  requireValid(options, "exact options");
  const GlpkQuiet quiet;  // core never prints

  const std::size_t n = inst.variables();
  const double s = inst.step();
  const int tmLim = options.timeLimitSeconds > 0.0
                        ? std::max(1, static_cast<int>(std::lround(options.timeLimitSeconds * 1000.0)))
                        : INT_MAX;

  ExactResult result;
  ExactCertificate& cert = result.certificate;
  cert.solver = std::string("GLPK ") + glp_version();
  result.run.termination = Termination::Converged;

  std::vector<double> c(n);
  std::vector<long> K(n);
  for (std::size_t i = 0; i < n; ++i) {
    c[i] = inst.xLower(i) / s;
    K[i] = inst.gridPoints(i);
  }
  // Distinct gain rows, right-hand sides in grid units (merged: the tighter one counts).
  std::vector<Row> rows;
  {
    std::map<std::vector<std::pair<std::size_t, double>>, std::size_t> index;
    for (std::size_t q = 0; q < inst.dimensions(); ++q) {
      double gc = 0.0;
      for (const auto& [i, g] : inst.gainRow(q)) gc += g * c[i];
      const double bp = (inst.upperLimit(q) - inst.deviation(q)) / s - gc;
      const double bm = (inst.deviation(q) - inst.lowerLimit(q)) / s + gc;
      const auto [it, added] = index.emplace(inst.gainRow(q), rows.size());
      if (added) rows.push_back(Row{inst.gainRow(q)});
      Row& row = rows[it->second];
      row.bp = std::min(row.bp, bp);
      row.bm = std::min(row.bm, bm);
    }
  }
  auto gk = [&](const Row& row, const std::vector<long>& k) {
    double v = 0.0;
    for (const auto& [i, g] : row.g) v += g * static_cast<double>(k[i]);
    return v;
  };
  // t of a grid point (grid units), exactly as the rows compute it.
  auto tOf = [&](const std::vector<long>& k) {
    double t = std::numeric_limits<double>::infinity();
    for (const Row& row : rows) {
      const double y = gk(row, k);
      t = std::min({t, row.bp - y, row.bm + y});
    }
    return t;
  };
  auto phi = [&](std::size_t i, double k) { return (c[i] + k) * (c[i] + k); };

  glp_smcp smcp;
  glp_init_smcp(&smcp);
  smcp.msg_lev = GLP_MSG_OFF;
  smcp.meth = GLP_DUALP;
  smcp.tm_lim = tmLim;
  glp_iocp iocp;
  glp_init_iocp(&iocp);
  iocp.msg_lev = GLP_MSG_OFF;
  iocp.mip_gap = 0.0;
  iocp.br_tech = GLP_BR_MFV;  // stage 2 looks for any grid point: dive on the most fractional variable
  iocp.bt_tech = GLP_BT_DFS;
  iocp.tm_lim = tmLim;

  std::vector<double> bestX(n, 0.0);
  long iteration = 0;
  auto report = [&](const std::vector<double>& x) {
    const SetupScore sc = inst.score(x);
    IterationSummary sum;
    sum.iteration = iteration++;
    sum.evaluations = cert.solverCalls;
    sum.best = -sc.f;
    sum.components = {{"f1", sc.f1}, {"f2", sc.f2}, {"f", sc.f}};
    sum.bestX = x;
    return notify(observer, result.run, sum, options.keepTrace);
  };
  auto finish = [&](const std::vector<double>& x) {
    result.x = x;
    result.score = inst.score(x);
    result.bonus = result.score.f1 - inst.f1Before();
    cert.gridF1 = result.score.f1;
    result.run.evaluations = cert.solverCalls;
    if (result.run.termination == Termination::Converged)
      result.run.message = "f1 " + cert.milpStatus + " on the grid; least norm " + cert.normStatus;
    return result;
  };

  // ---- stage 1: continuous LP, maximise t ----
  std::vector<long> k(n, 0);
  std::vector<double> xLp(n, 0.0);
  double tLp = std::numeric_limits<double>::infinity();
  {
    GlpProblem holder;
    glp_prob* lp = holder.get();
    const int tCol = static_cast<int>(n) + 1;
    glp_set_obj_dir(lp, GLP_MAX);
    glp_add_cols(lp, tCol);
    for (std::size_t i = 0; i < n; ++i) {
      const double kReal = (inst.xUpper(i) - inst.xLower(i)) / s;
      if (kReal > 0.0)
        glp_set_col_bnds(lp, static_cast<int>(i) + 1, GLP_DB, 0.0, kReal);
      else
        glp_set_col_bnds(lp, static_cast<int>(i) + 1, GLP_FX, 0.0, 0.0);
    }
    glp_set_col_bnds(lp, tCol, GLP_FR, 0.0, 0.0);
    glp_set_obj_coef(lp, tCol, 1.0);
    loadRows(lp, rows, tCol);
    ++cert.solverCalls;
    smcp.presolve = GLP_ON;
    const int ret = glp_simplex(lp, &smcp);
    smcp.presolve = GLP_OFF;
    if (ret != 0 || glp_get_status(lp) != GLP_OPT) {
      cert.lpStatus = ret != 0 ? failureName(ret) : statusName(glp_get_status(lp));
    } else {
      cert.lpStatus = "optimal";
      tLp = glp_get_obj_val(lp);
      cert.lpF1 = tLp * s;
      for (std::size_t i = 0; i < n; ++i) {
        const double kv = glp_get_col_prim(lp, static_cast<int>(i) + 1);
        xLp[i] = inst.xLower(i) + kv * s;
        k[i] = std::clamp(std::lround(kv), 0L, K[i]);
      }
    }
  }
  bestX = inst.fromGrid(k);
  if (report(xLp)) {
    cert.milpStatus = cert.normStatus = "cancelled";
    return finish(bestX);
  }

  // ---- stage 2: the largest f1 on the grid, by bisection over its candidate values ----
  GlpProblem feasHolder;
  glp_prob* feas = feasHolder.get();
  glp_add_cols(feas, static_cast<int>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const int col = static_cast<int>(i) + 1;
    glp_set_col_kind(feas, col, GLP_IV);
    if (K[i] > 0)
      glp_set_col_bnds(feas, col, GLP_DB, 0.0, static_cast<double>(K[i]));
    else
      glp_set_col_bnds(feas, col, GLP_FX, 0.0, 0.0);
  }
  loadRows(feas, rows, 0);
  // Row bounds for "f1 >= t s": integer intervals of y = G k. False when one is empty.
  auto setLevel = [&](double t) {
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double lo = std::ceil(t - rows[r].bm - kEps), up = std::floor(rows[r].bp - t + kEps);
      if (lo > up) return false;
      glp_set_row_bnds(feas, static_cast<int>(r) + 1, lo == up ? GLP_FX : GLP_DB, lo, up);
    }
    return true;
  };
  enum class Probe { Feasible, Infeasible, Unknown, Fractional };
  auto readPoint = [&](std::vector<long>* found, bool mip) {
    found->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int col = static_cast<int>(i) + 1;
      (*found)[i] =
          std::clamp(std::lround(mip ? glp_mip_col_val(feas, col) : glp_get_col_prim(feas, col)), 0L, K[i]);
    }
  };
  // The LP relaxation at level t, warm-started from the previous probe's basis: only row bounds change
  // and the objective is zero (every basis stays dual feasible), so the dual simplex re-solves it in a
  // few pivots. No LP point: no grid point either (Infeasible). An integral vertex is a grid point
  // (Feasible, in *found). Otherwise Fractional (or Unknown when the solver fails).
  auto lpProbe = [&](double t, std::vector<long>* found) {
    if (!setLevel(t)) return Probe::Infeasible;
    ++cert.solverCalls;
    int ret = glp_simplex(feas, &smcp);
    if (ret == GLP_EBADB || ret == GLP_ESING || ret == GLP_ECOND) {
      glp_std_basis(feas);
      ++cert.solverCalls;
      ret = glp_simplex(feas, &smcp);
    }
    if (ret != 0) return Probe::Unknown;
    const int st = glp_get_status(feas);
    if (st == GLP_NOFEAS) return Probe::Infeasible;
    if (st != GLP_OPT) return Probe::Unknown;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = glp_get_col_prim(feas, static_cast<int>(i) + 1);
      if (std::abs(v - std::round(v)) > kEps) return Probe::Fractional;
    }
    readPoint(found, false);
    return Probe::Feasible;
  };
  // The MILP at level t: the LP first, branch and bound (depth first, most fractional variable, from
  // the LP's basis) only for a fractional vertex.
  auto probe = [&](double t, std::vector<long>* found) {
    ++cert.feasibilityProbes;
    const Probe lp = lpProbe(t, found);
    if (lp == Probe::Feasible || lp == Probe::Infeasible) return lp;
    ++cert.solverCalls;
    iocp.presolve = lp == Probe::Fractional ? GLP_OFF : GLP_ON;
    iocp.cb_func = nullptr;
    const int ret = glp_intopt(feas, &iocp);
    const int st = glp_mip_status(feas);
    if (st == GLP_OPT || st == GLP_FEAS) {
      readPoint(found, true);
      return Probe::Feasible;
    }
    if ((ret == 0 && st == GLP_NOFEAS) || ret == GLP_ENOPFS) return Probe::Infeasible;
    cert.milpStatus = failureName(ret == 0 ? GLP_EFAIL : ret);
    return Probe::Unknown;
  };

  // The values f1 / s can take on the grid: the union over rows of bp_r + Z and bm_r + Z.
  auto atOrAbove = [&](double v) {  // smallest such value >= v (within kEps)
    double best = std::numeric_limits<double>::infinity();
    for (const Row& row : rows)
      for (const double a : {row.bp, row.bm}) best = std::min(best, a + std::ceil(v - a - kEps));
    return best;
  };
  auto above = [&](double v) {  // smallest such value > v (by more than kEps)
    double best = std::numeric_limits<double>::infinity();
    for (const Row& row : rows)
      for (const double a : {row.bp, row.bm}) best = std::min(best, a + std::floor(v - a + kEps) + 1.0);
    return best;
  };
  double tInc = tOf(k);
  bool proven = true;
  if (std::isfinite(tLp)) {
    // Bisection: every value <= lo is reached (by k), every value >= hi is not (LP bound or probe).
    double lo = tInc, hi = tLp + 2.0 * kEps;
    bool hiProbed = false;
    std::vector<long> found;
    // Phase A, LP relaxations only (a millisecond each): the largest level whose integer-rounded
    // polytope has an LP point. Every level above it has no grid point. An integral vertex on the way
    // raises lo like a MILP probe does.
    double lpTop = lo;
    for (;;) {
      const double next = above(lpTop);
      if (!(next < hi - kEps)) break;
      double tp = atOrAbove(0.5 * (lpTop + hi));
      if (!(tp < hi - kEps)) tp = next;
      ++cert.feasibilityProbes;
      const Probe p = lpProbe(tp, &found);
      if (p == Probe::Infeasible) {
        hi = tp;
        hiProbed = true;
        continue;
      }
      lpTop = tp;
      if (p == Probe::Feasible) {
        const double tFound = tOf(found);
        if (tFound > tInc) {
          k = found;
          tInc = tFound;
        }
        lo = std::max(tInc, tp);
        lpTop = std::max(lpTop, lo);
      }
    }
    // Phase B, MILP probes: the grid optimum is usually the LP's top level itself (probed first), else
    // bisection below it.
    bool first = true;
    for (;;) {
      const double next = above(lo);
      if (!(next < hi - kEps)) break;
      double tp = first && lpTop > lo + kEps ? lpTop : atOrAbove(0.5 * (lo + hi));
      first = false;
      if (!(tp < hi - kEps)) tp = next;
      const Probe p = probe(tp, &found);
      if (p == Probe::Feasible) {
        const double tFound = tOf(found);
        if (tFound > tInc) {
          k = found;
          tInc = tFound;
        }
        lo = std::max(tInc, tp);
      } else {
        if (p == Probe::Unknown) proven = false;
        hi = tp;
        hiProbed = true;
      }
    }
    if (hiProbed) cert.nextF1Infeasible = hi * s;
  }
  cert.f1Optimal = proven && cert.lpStatus == "optimal";
  if (cert.milpStatus.empty()) cert.milpStatus = cert.f1Optimal ? "optimal" : "not proven";
  bestX = inst.fromGrid(k);
  if (report(bestX)) {
    cert.normStatus = "cancelled";
    return finish(bestX);
  }
  if (!options.leastNorm) {
    cert.normStatus = "skipped";
    return finish(bestX);
  }

  // ---- stage 3: least |x| among the f1-optimal grid points (outer approximation) ----
  const double tStar = tInc;
  setLevel(tStar - kTau);
  glp_set_obj_dir(feas, GLP_MIN);
  const int zCol0 = static_cast<int>(n) + 1;
  glp_add_cols(feas, static_cast<int>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const int col = zCol0 + static_cast<int>(i);
    glp_set_obj_coef(feas, col, 1.0);
    if (K[i] > 0)
      glp_set_col_bnds(feas, col, GLP_LO, 0.0, 0.0);
    else
      glp_set_col_bnds(feas, col, GLP_FX, phi(i, 0.0), phi(i, 0.0));
  }
  std::set<std::pair<std::size_t, long>> secants;
  auto addSecant = [&](std::size_t i, long j) {
    if (j < 0 || j >= K[i] || !secants.insert({i, j}).second) return false;
    // z_i >= phi(j) + (phi(j+1) - phi(j)) (k_i - j), slope 2 (c_i + j) + 1.
    const double slope = 2.0 * (c[i] + static_cast<double>(j)) + 1.0;
    const int row = glp_add_rows(feas, 1);
    int idx[3] = {0, zCol0 + static_cast<int>(i), static_cast<int>(i) + 1};
    double val[3] = {0.0, 1.0, -slope};
    glp_set_mat_row(feas, row, 2, idx, val);
    glp_set_row_bnds(feas, row, GLP_LO, phi(i, static_cast<double>(j)) - slope * static_cast<double>(j), 0.0);
    ++cert.cuts;
    return true;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const long k0 = std::clamp(std::lround(-c[i]), 0L, K[i]);
    for (const long j : {k0 - 1, k0, k[i] - 1, k[i]}) addSecant(i, j);
  }
  iocp.presolve = GLP_OFF;
  iocp.cb_func = intoptCallback;
  glp_iocp defaults;
  glp_init_iocp(&defaults);
  iocp.br_tech = defaults.br_tech;  // least norm: a real objective, GLPK's default branching
  iocp.bt_tech = defaults.bt_tech;
  // The stage-2 basis stays valid (new rows basic, new columns at a bound): warm start from it.
  auto lpSolve = [&]() {
    ++cert.solverCalls;
    int ret = glp_simplex(feas, &smcp);
    if (ret == GLP_EBADB || ret == GLP_ESING || ret == GLP_ECOND) {
      glp_std_basis(feas);
      ++cert.solverCalls;
      ret = glp_simplex(feas, &smcp);
    }
    return ret;
  };
  // Cheap LP rounds first: cut the continuous relaxation down to the piecewise-linear interpolation of phi
  // between integers (adding the secant under each fractional k_i), so that the MILP rounds below start from
  // a nearly complete set of cuts.
  for (int round = 0; round < options.maxNormRounds; ++round) {
    if (lpSolve() != 0 || glp_get_status(feas) != GLP_OPT) break;
    bool added = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double kv = glp_get_col_prim(feas, static_cast<int>(i) + 1);
      const double z = glp_get_col_prim(feas, zCol0 + static_cast<int>(i));
      const double j = std::clamp(std::floor(kv + kEps), 0.0, static_cast<double>(std::max(0L, K[i] - 1)));
      const double pwl = phi(i, j) + (2.0 * (c[i] + j) + 1.0) * (kv - j);
      if (z < pwl - 1e-7 * std::max(1.0, pwl)) added = addSecant(i, static_cast<long>(j)) || added;
    }
    if (!added) break;
  }
  cert.normStatus = "round limit";
  for (int round = 0; round < options.maxNormRounds; ++round) {
    Incumbent inc;
    inc.values.assign(2 * n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      inc.values[i + 1] = static_cast<double>(k[i]);
      inc.values[static_cast<std::size_t>(zCol0) + i] = phi(i, static_cast<double>(k[i]));
    }
    iocp.cb_info = &inc;
    int ret = lpSolve();
    if (ret != 0 || glp_get_status(feas) != GLP_OPT) {
      cert.normStatus =
          "LP relaxation: " + (ret != 0 ? failureName(ret) : std::string(statusName(glp_get_status(feas))));
      break;
    }
    ++cert.solverCalls;
    ret = glp_intopt(feas, &iocp);
    ++cert.normRounds;
    const int st = glp_mip_status(feas);
    if (st != GLP_OPT && st != GLP_FEAS) {
      cert.normStatus = ret != 0 ? failureName(ret) : statusName(st);
      break;
    }
    std::vector<long> kn(n);
    for (std::size_t i = 0; i < n; ++i)
      kn[i] = std::clamp(std::lround(glp_mip_col_val(feas, static_cast<int>(i) + 1)), 0L, K[i]);
    const bool optimal = ret == 0 && st == GLP_OPT;
    // Keep the new point only when it is f1-optimal (recomputed) and not longer.
    double normNew = 0.0, normOld = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      normNew += phi(i, static_cast<double>(kn[i]));
      normOld += phi(i, static_cast<double>(k[i]));
    }
    if (tOf(kn) >= tStar - kTau && normNew <= normOld) k = kn;
    bestX = inst.fromGrid(k);
    if (!optimal) {
      cert.normStatus = failureName(ret == 0 ? GLP_EFAIL : ret);
      report(bestX);
      break;
    }
    cert.f2LowerBound = std::max(cert.f2LowerBound, s * std::sqrt(std::max(0.0, glp_mip_obj_val(feas))));
    bool added = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double z = glp_mip_col_val(feas, zCol0 + static_cast<int>(i));
      const double p = phi(i, static_cast<double>(kn[i]));
      if (z < p - 1e-7 * std::max(1.0, p)) {
        added = addSecant(i, kn[i] - 1) || added;
        added = addSecant(i, kn[i]) || added;
      }
    }
    if (!added) {
      cert.f2Optimal = k == kn;
      cert.normStatus = cert.f2Optimal ? "optimal" : "optimal within solver tolerances";
      cert.f2LowerBound = std::min(cert.f2LowerBound, inst.score(bestX).f2);
      report(bestX);
      break;
    }
    if (report(bestX)) {
      cert.normStatus = "cancelled";
      break;
    }
  }
  return finish(bestX);
}

}  // namespace metrofit::setup
