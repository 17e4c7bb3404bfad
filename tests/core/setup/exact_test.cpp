// The exact setup correction (core/setup/exact.h) against independent formulations: brute-force
// enumeration of small grids, a second LP (interior point, in mm, on x instead of grid steps),
// direct branch and bound on max t, and hand-solved cases for the least-norm tie-break.
#include <glpk.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/rng.h"
#include "core/optim/coa.h"
#include "core/optim/cripso.h"
#include "core/optim/ga.h"
#include "core/optim/pso.h"
#include "core/setup/exact.h"
#include "core/sim/setup_sim.h"
#include "setup_fixtures.h"

namespace metrofit::setup {
namespace {

using metrofit::test::near;
using nlohmann::json;

/// A random model: 3 setup data on a 9-point grid, 4-6 dimensions, random arcs and tolerances.
struct RandomCase {
  Model model;
  std::vector<double> deviation;
};

RandomCase randomCase(std::uint64_t seed) {
  Rng rng(seed);
  json j{{"step_mm", 0.001}, {"bounds_mm", {-0.004, 0.004}}};
  j["setup"] = {
      {{"id", "W1"}, {"kind", "wks"}}, {{"id", "W2"}, {"kind", "wks"}}, {{"id", "T1"}, {"kind", "tool"}}};
  const char* data[] = {"W1", "W2", "T1"};
  j["features"] = json::array();
  j["dimensions"] = json::array();
  j["arcs"] = json::array();
  auto sign = [&] { return rng.uniform() < 0.5 ? -1 : 1; };
  const int features = 4;
  for (int f = 0; f < features; ++f) {
    const std::string id = "F" + std::to_string(f + 1);
    j["features"].push_back({{"id", id}});
    const auto first = rng.below(3);
    j["arcs"].push_back({{"from", data[first]}, {"to", id}, {"weight", sign()}});
    if (rng.uniform() < 0.6)
      j["arcs"].push_back({{"from", data[(first + 1 + rng.below(2)) % 3]}, {"to", id}, {"weight", sign()}});
  }
  const int dims = 4 + static_cast<int>(rng.below(3));
  RandomCase c;
  for (int d = 0; d < dims; ++d) {
    const std::string id = "D" + std::to_string(d + 1);
    j["dimensions"].push_back(
        {{"id", id}, {"lower", -rng.uniform(0.004, 0.02)}, {"upper", rng.uniform(0.004, 0.02)}});
    const auto first = rng.below(features);
    j["arcs"].push_back({{"from", "F" + std::to_string(first + 1)}, {"to", id}, {"weight", sign()}});
    if (rng.uniform() < 0.5) {
      j["arcs"].push_back(
          {{"from", "F" + std::to_string((first + 1 + rng.below(features - 1)) % features + 1)},
           {"to", id},
           {"weight", sign()}});
    }
    c.deviation.push_back(rng.uniform(-0.012, 0.012));
  }
  c.model = modelFromJson(j, "random-" + std::to_string(seed));
  return c;
}

/// Brute force over every grid point, with f1 computed here from the gain matrix.
struct Brute {
  double f1 = -std::numeric_limits<double>::infinity();
  double f2 = std::numeric_limits<double>::infinity();
};

Brute bruteForce(const Model& m, const std::vector<double>& e) {
  const Eigen::MatrixXd g = gainMatrix(m);
  const std::size_t n = m.setup.size();
  std::vector<long> K(n);
  for (std::size_t i = 0; i < n; ++i) K[i] = std::lround((m.upper(i) - m.lower(i)) / m.stepMm);
  std::vector<std::pair<double, double>> points;  // (f1, |x|)
  std::vector<long> k(n, 0);
  for (;;) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i)
      x(static_cast<Eigen::Index>(i)) = m.lower(i) + static_cast<double>(k[i]) * m.stepMm;
    const Eigen::VectorXd after = g * x;
    double f1 = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < m.dimensions.size(); ++q) {
      const double v = e[q] + after(static_cast<Eigen::Index>(q));
      f1 = std::min({f1, m.dimensions[q].upper - v, v - m.dimensions[q].lower});
    }
    points.emplace_back(f1, x.norm());
    std::size_t i = 0;
    while (i < n && ++k[i] > K[i]) k[i++] = 0;
    if (i == n) break;
  }
  Brute b;
  for (const auto& p : points) b.f1 = std::max(b.f1, p.first);
  for (const auto& p : points)
    if (p.first >= b.f1 - 1e-9) b.f2 = std::min(b.f2, p.second);
  return b;
}

/// The continuous optimum by a second formulation: variables x in mm (not grid steps), every
/// dimension's two rows kept (no merging), maximise t with GLPK's interior-point method.
double interiorPointF1(const SetupInstance& inst) {
  glp_term_out(GLP_OFF);
  glp_prob* lp = glp_create_prob();
  const int n = static_cast<int>(inst.variables()), m = static_cast<int>(inst.dimensions());
  glp_set_obj_dir(lp, GLP_MAX);
  glp_add_cols(lp, n + 1);
  for (int i = 0; i < n; ++i) glp_set_col_bnds(lp, i + 1, GLP_DB, inst.xLower(i), inst.xUpper(i));
  glp_set_col_bnds(lp, n + 1, GLP_FR, 0, 0);
  glp_set_obj_coef(lp, n + 1, 1.0);
  glp_add_rows(lp, 2 * m);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (int q = 0; q < m; ++q) {
    // (G x)_q - t >= lo_q - e_q   and   -(G x)_q - t >= e_q - up_q
    glp_set_row_bnds(lp, 2 * q + 1, GLP_LO, inst.lowerLimit(q) - inst.deviation(q), 0);
    glp_set_row_bnds(lp, 2 * q + 2, GLP_LO, inst.deviation(q) - inst.upperLimit(q), 0);
    for (int h = 0; h < 2; ++h) {
      for (int i = 0; i < n; ++i) {
        const double g = inst.gain()(q, i);
        if (g == 0.0) continue;
        ia.push_back(2 * q + 1 + h);
        ja.push_back(i + 1);
        ar.push_back(h == 0 ? g : -g);
      }
      ia.push_back(2 * q + 1 + h);
      ja.push_back(n + 1);
      ar.push_back(-1.0);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_iptcp parm;
  glp_init_iptcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  const int ret = glp_interior(lp, &parm);
  const double t = (ret == 0 && glp_ipt_status(lp) == GLP_OPT) ? glp_ipt_obj_val(lp) : std::nan("");
  glp_delete_prob(lp);
  return t;
}

/// The grid optimum by plain branch and bound on "maximise t" (the formulation exact.h avoids
/// for speed): k integer, t continuous, glp_intopt with presolve.
double branchAndBoundF1(const SetupInstance& inst) {
  glp_term_out(GLP_OFF);
  glp_prob* lp = glp_create_prob();
  const int n = static_cast<int>(inst.variables()), m = static_cast<int>(inst.dimensions());
  const double s = inst.step();
  glp_set_obj_dir(lp, GLP_MAX);
  glp_add_cols(lp, n + 1);
  for (int i = 0; i < n; ++i) {
    glp_set_col_kind(lp, i + 1, GLP_IV);
    glp_set_col_bnds(lp, i + 1, GLP_DB, 0, static_cast<double>(inst.gridPoints(i)));
  }
  glp_set_col_bnds(lp, n + 1, GLP_FR, 0, 0);
  glp_set_obj_coef(lp, n + 1, 1.0);
  glp_add_rows(lp, 2 * m);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (int q = 0; q < m; ++q) {
    double gl = 0.0;  // (G lower)_q in mm
    for (int i = 0; i < n; ++i) gl += inst.gain()(q, i) * inst.xLower(i);
    // t s <= up - e - G(lower + s k)  and  t s <= e + G(lower + s k) - lo, divided by s
    glp_set_row_bnds(lp, 2 * q + 1, GLP_UP, 0, (inst.upperLimit(q) - inst.deviation(q) - gl) / s);
    glp_set_row_bnds(lp, 2 * q + 2, GLP_UP, 0, (inst.deviation(q) + gl - inst.lowerLimit(q)) / s);
    for (int h = 0; h < 2; ++h) {
      for (int i = 0; i < n; ++i) {
        const double g = inst.gain()(q, i);
        if (g == 0.0) continue;
        ia.push_back(2 * q + 1 + h);
        ja.push_back(i + 1);
        ar.push_back(h == 0 ? g : -g);
      }
      ia.push_back(2 * q + 1 + h);
      ja.push_back(n + 1);
      ar.push_back(1.0);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_iocp parm;
  glp_init_iocp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_ON;
  const int ret = glp_intopt(lp, &parm);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[i] = inst.xLower(i) + s * std::round(glp_mip_col_val(lp, i + 1));
  const bool ok = ret == 0 && glp_mip_status(lp) == GLP_OPT;
  glp_delete_prob(lp);
  return ok ? inst.f1(x) : std::nan("");
}

TEST(SetupExact, MatchesBruteForceOnSmallGrids) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const RandomCase c = randomCase(seed);
    const SetupInstance inst(c.model, c.deviation);
    const ExactResult r = solveExact(inst);
    const Brute b = bruteForce(c.model, c.deviation);
    EXPECT_TRUE(near(r.score.f1, b.f1, 1e-12)) << "seed " << seed;
    EXPECT_TRUE(near(r.score.f2, b.f2, 1e-12)) << "seed " << seed;
    EXPECT_TRUE(r.certificate.f1Optimal) << "seed " << seed;
    EXPECT_TRUE(r.certificate.f2Optimal) << "seed " << seed << ": " << r.certificate.normStatus;
    EXPECT_TRUE(near(r.certificate.f2LowerBound, r.score.f2, 1e-12)) << "seed " << seed;
    EXPECT_TRUE(SetupProblem(inst).isFeasible(r.x)) << "seed " << seed;
    EXPECT_GE(r.certificate.lpF1, r.score.f1 - 1e-12) << "seed " << seed;
  }
}

TEST(SetupExact, LpOptimumMatchesASecondFormulation) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const RandomCase c = randomCase(seed);
    const SetupInstance inst(c.model, c.deviation);
    EXPECT_TRUE(near(solveExact(inst).certificate.lpF1, interiorPointF1(inst), 1e-7)) << "seed " << seed;
  }
  const Model paper = readModel(test::paperModelPath());
  SetupSimOptions so;
  for (std::size_t set = 0; set < 10; ++set) {
    const SetupInstance inst(paper, simulateSetupSet(paper, so, set).deviationMm);
    const ExactResult r = solveExact(inst);
    EXPECT_EQ(r.certificate.lpStatus, "optimal");
    EXPECT_TRUE(near(r.certificate.lpF1, interiorPointF1(inst), 1e-7)) << "set " << set;
  }
}

TEST(SetupExact, GridOptimumMatchesBranchAndBoundOnThePaperExample) {
  const Model paper = readModel(test::paperModelPath());
  SetupSimOptions so;
  so.seed = 3;
  for (std::size_t set = 0; set < 5; ++set) {
    const SetupInstance inst(paper, simulateSetupSet(paper, so, set).deviationMm);
    const ExactResult r = solveExact(inst);
    EXPECT_TRUE(r.certificate.f1Optimal);
    EXPECT_TRUE(r.certificate.f2Optimal);
    EXPECT_TRUE(near(r.score.f1, branchAndBoundF1(inst), 1e-12)) << "set " << set;
    EXPECT_TRUE(near(r.certificate.gridF1, r.score.f1, 0.0));
    // The next candidate value above the optimum was proven unreachable and lies within the LP bound.
    if (!std::isnan(r.certificate.nextF1Infeasible)) {
      EXPECT_GT(r.certificate.nextF1Infeasible, r.score.f1);
      EXPECT_LE(r.certificate.nextF1Infeasible, r.certificate.lpF1 + 1e-12);
    }
  }
}

// Hand-solved: D1 = W1 + T5 must be centred (e'_1 = 0, budget 0.02), D2 = 2 W1 + T5 only needs
// budget 0.02, i.e. W1 + T5 = -0.01 with W1 in [-0.015, 0.025]; the least |x| is W1 = T5 = -0.005.
TEST(SetupExact, LeastNormAmongTheF1Optimal) {
  const SetupInstance inst(test::smallModel(), {0.010, -0.005});
  const ExactResult r = solveExact(inst);
  EXPECT_TRUE(near(r.score.f1, 0.02, 1e-12));
  EXPECT_TRUE(near(r.x[0], -0.005, 1e-12));
  EXPECT_TRUE(near(r.x[1], -0.005, 1e-12));
  EXPECT_TRUE(near(r.score.f2, std::sqrt(50e-6), 1e-12));
  EXPECT_TRUE(near(r.bonus, 0.01, 1e-12));
  EXPECT_EQ(r.certificate.normStatus, "optimal");
  EXPECT_EQ(r.certificate.solver.rfind("GLPK ", 0), 0u);
  // Without stage 3 the f1 is the same, the correction (usually) longer, never shorter.
  ExactOptions o;
  o.leastNorm = false;
  const ExactResult s = solveExact(inst, o);
  EXPECT_TRUE(near(s.score.f1, 0.02, 1e-12));
  EXPECT_GE(s.score.f2, r.score.f2 - 1e-12);
  EXPECT_EQ(s.certificate.normStatus, "skipped");

  // With W1 >= 0 the least |x| moves to the bound: W1 = 0, T5 = -0.01.
  Model m = test::smallModel();
  m.setup[0].boundsMm = std::make_pair(0.0, 0.1);
  const ExactResult b = solveExact(SetupInstance(m, {0.010, -0.005}));
  EXPECT_TRUE(near(b.score.f1, 0.02, 1e-12));
  EXPECT_TRUE(near(b.x[0], 0.0, 1e-12));
  EXPECT_TRUE(near(b.x[1], -0.01, 1e-12));
}

// A tie: W1 + T5 = -0.011 has two least-norm grid points, (-0.005, -0.006) and (-0.006, -0.005).
TEST(SetupExact, TiesInTheNormReturnOneOfTheTiedPoints) {
  json j = test::smallModelJson();
  j["dimensions"] = json::array({j["dimensions"][0]});
  j["arcs"] = json::array({j["arcs"][0], j["arcs"][1], j["arcs"][3]});  // W1 -> F1, T5 -> F1, F1 -> D1
  const Model m = modelFromJson(j, "tie.json");
  ASSERT_EQ(gainMatrix(m).rows(), 1);
  const ExactResult r = solveExact(SetupInstance(m, {0.011}));
  EXPECT_TRUE(near(r.score.f1, 0.02, 1e-12));
  EXPECT_TRUE(near(r.x[0] + r.x[1], -0.011, 1e-12));
  EXPECT_TRUE(near(std::abs(r.x[0] - r.x[1]), 0.001, 1e-12));
  EXPECT_TRUE(near(r.score.f2, std::sqrt(61e-6), 1e-12));
  EXPECT_TRUE(r.certificate.f2Optimal);
}

TEST(SetupExact, FixedVariablesAndSilence) {
  Model m = test::smallModel();
  m.setup[1].boundsMm = std::make_pair(0.003, 0.003);  // T5 may not move
  const SetupInstance inst(m, {0.010, -0.005});
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const ExactResult r = solveExact(inst);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");  // core never prints (GLPK silenced)
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(r.x[1], 0.003);
  EXPECT_TRUE(near(r.score.f1, bruteForce(m, {0.010, -0.005}).f1, 1e-12));
}

TEST(SetupExact, TraceObserverAndCancellation) {
  const SetupInstance inst(test::smallModel(), {0.010, -0.005});
  const ExactResult r = solveExact(inst);
  ASSERT_GE(r.run.trace.size(), 3u);  // lp, grid, least-norm round(s)
  EXPECT_EQ(r.run.trace.front().components[0].name, "f1");
  EXPECT_EQ(r.run.trace.back().components[1].value, r.score.f2);
  EXPECT_EQ(r.run.evaluations, r.certificate.solverCalls);
  EXPECT_EQ(r.run.termination, Termination::Converged);

  int calls = 0;
  FunctionObserver stopAtOnce([&](const IterationSummary&) {
    ++calls;
    return ObserverDecision::Stop;
  });
  const ExactResult c = solveExact(inst, {}, &stopAtOnce);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(c.run.termination, Termination::Cancelled);
  EXPECT_EQ(c.certificate.milpStatus, "cancelled");
  EXPECT_FALSE(c.certificate.f1Optimal);
  EXPECT_TRUE(SetupProblem(inst).isFeasible(c.x));  // the rounded LP point

  ExactOptions bad;
  bad.maxNormRounds = 0;
  EXPECT_THROW(solveExact(inst, bad), OptionsError);
}

// The exact f1 bounds every metaheuristic from above on the paper's example (a metaheuristic
// "beating" it would expose a wrong exact solution); their best points are on the grid.
TEST(SetupExact, NoMetaheuristicBeatsTheExactOptimum) {
  const Model paper = readModel(test::paperModelPath());
  SetupSimOptions so;
  const SetupInstance inst(paper, simulateSetupSet(paper, so, 0).deviationMm);
  const SetupProblem problem(inst);
  const ExactResult exact = solveExact(inst);
  optim::CommonOptions common;
  common.maxEvaluations = 2000;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    common.seed = seed;
    optim::Cripso::Options co;
    co.common = common;
    optim::Pso::Options po = optim::Pso::Options::stryczek2016();
    po.common = common;
    optim::Ga::Options go;
    go.common = common;
    optim::Coa::Options ko;
    ko.common = common;
    const optim::Result results[] = {optim::Cripso(co).optimise(problem), optim::Pso(po).optimise(problem),
                                     optim::Ga(go).optimise(problem), optim::Coa(ko).optimise(problem)};
    for (const auto& res : results) {
      EXPECT_TRUE(problem.isFeasible(res.bestX)) << res.method;
      EXPECT_LE(inst.f1(res.bestX), exact.score.f1 + 1e-12) << res.method << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace metrofit::setup
