// metrofit-bench --nist (bench_nist.h). The models and derivatives are tests/nist_strd.h's (written from
// the NIST files, shared with tests/core/optim/nist_strd_nls_test.cpp). Ceres runs its trust-region
// Levenberg-Marquardt with a dense QR solver, the iteration limit of ours and tolerances at the rounding
// level; "converged" is Ceres' CONVERGENCE. LRE: the smallest over the parameters, clipped to the
// certified digits, 0 when the solver does not report convergence (CONTRACT.md). Time: the median of
// `repeat` solves from the start (the solve only, no LRE or standard deviations).
#include "bench_nist.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <ceres/ceres.h>

#include "core/optim/least_squares.h"
#include "nist_strd.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// All residuals of a problem as one Ceres cost function with one parameter block.
class NistCost final : public ceres::CostFunction {
 public:
  NistCost(const nist::Problem& p, const nist::Model& f, const Eigen::VectorXd& yt) : p_(p), f_(f), yt_(yt) {
    set_num_residuals(static_cast<int>(p.y.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(p.parameters()));
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Index m = p_.y.size(), n = static_cast<Eigen::Index>(p_.parameters());
    const bool wantJ = jacobians != nullptr && jacobians[0] != nullptr;
    std::vector<double> g(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < m; ++i) {
      residuals[i] = f_(parameters[0], p_.x.row(i), wantJ ? g.data() : nullptr) - yt_(i);
      if (!std::isfinite(residuals[i])) return false;
      if (wantJ) {
        for (Eigen::Index k = 0; k < n; ++k) {
          if (!std::isfinite(g[static_cast<std::size_t>(k)])) return false;
          jacobians[0][i * n + k] = g[static_cast<std::size_t>(k)];
        }
      }
    }
    return true;
  }

 private:
  const nist::Problem& p_;
  const nist::Model& f_;
  const Eigen::VectorXd& yt_;
};

struct Run {
  bool converged = false;
  Eigen::VectorXd b;
  double seconds = 0.0;
  long iterations = 0;
};

template <class F>
Run timed(int repeat, F&& once) {
  std::vector<double> t;
  Run last;
  for (int k = 0; k < repeat; ++k) {
    const auto a = Clock::now();
    last = once();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  last.seconds = t[t.size() / 2];
  return last;
}

}  // namespace

nlohmann::json benchNist(const std::string& folder, int repeat) {
  nlohmann::json out = nlohmann::json::array();
  std::printf(
      "NIST StRD nonlinear regression: LRE (certified digits of the parameters, min over b) and time\n");
  std::printf("%-9s %5s | %-4s %5s %5s %10s | %-4s %5s %5s %10s | %6s\n", "problem", "start", "ours", "LRE",
              "it", "time us", "cere", "LRE", "it", "time us", "ratio");
  int oursOk = 0, ceresOk = 0, oursWrong = 0, ceresWrong = 0;
  double oursTotal = 0.0, ceresTotal = 0.0;
  for (const std::string& name : nist::problemNames()) {
    const std::string path = folder + "/" + name + ".dat";
    if (!std::filesystem::exists(path)) throw std::runtime_error("no NIST StRD file " + path);
    nist::Problem p = nist::readProblem(path);
    nist::applyErrata(p);  // Roszman1's b1 as NIST certifies it (tests/nist_strd.h)
    const nist::Model f = nist::model(name);
    const Eigen::VectorXd yt = nist::transformedResponse(p);
    const optim::LeastSquaresOptions lo = nist::solverOptions();
    for (const int start : {1, 2}) {
      const std::vector<double>& s = start == 1 ? p.start1 : p.start2;
      const Eigen::VectorXd b0 =
          Eigen::Map<const Eigen::VectorXd>(s.data(), static_cast<Eigen::Index>(s.size()));
      const Run ours = timed(repeat, [&] {
        Run r;
        r.b = b0;
        const optim::Residual res = [&](const Eigen::VectorXd& b, Eigen::VectorXd& rr, Eigen::MatrixXd* J) {
          nist::residuals(p, f, yt, b.data(), rr, J);
        };
        const optim::LeastSquaresSummary sum = optim::solveLeastSquares(res, r.b, lo);
        r.converged = sum.converged;
        r.iterations = sum.iterations;
        return r;
      });
      const Run peer = timed(repeat, [&] {
        Run r;
        r.b = b0;
        ceres::Problem problem;
        problem.AddResidualBlock(new NistCost(p, f, yt), nullptr, r.b.data());
        ceres::Solver::Options co;
        co.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
        co.linear_solver_type = ceres::DENSE_QR;
        co.max_num_iterations = static_cast<int>(lo.maxIterations);
        co.function_tolerance = 1e-15;
        co.gradient_tolerance = 1e-15;
        co.parameter_tolerance = 1e-15;
        co.num_threads = 1;
        co.logging_type = ceres::SILENT;
        ceres::Solver::Summary summary;
        ceres::Solve(co, &problem, &summary);
        r.converged = summary.termination_type == ceres::CONVERGENCE;
        r.iterations = static_cast<long>(summary.iterations.size());
        return r;
      });
      const double lreOurs = ours.converged ? nist::parameterLre(p, ours.b) : 0.0;
      const double lreCeres = peer.converged ? nist::parameterLre(p, peer.b) : 0.0;
      oursOk += lreOurs >= 6.0;
      ceresOk += lreCeres >= 6.0;
      oursWrong += ours.converged && lreOurs < 4.0;
      ceresWrong += peer.converged && lreCeres < 4.0;
      oursTotal += ours.seconds;
      ceresTotal += peer.seconds;
      std::printf("%-9s %5d | %-4s %5.1f %5ld %10.1f | %-4s %5.1f %5ld %10.1f | %6.2f\n", name.c_str(), start,
                  ours.converged ? "conv" : "no", lreOurs, ours.iterations, ours.seconds * 1e6,
                  peer.converged ? "conv" : "no", lreCeres, peer.iterations, peer.seconds * 1e6,
                  ours.seconds / peer.seconds);
      out.push_back({{"problem", name},
                     {"start", start},
                     {"converged", ours.converged},
                     {"lre", lreOurs},
                     {"time_ns", static_cast<long long>(ours.seconds * 1e9)},
                     {"iterations", ours.iterations},
                     {"ceres_converged", peer.converged},
                     {"ceres_lre", lreCeres},
                     {"ceres_time_ns", static_cast<long long>(peer.seconds * 1e9)},
                     {"ceres_iterations", peer.iterations}});
    }
  }
  std::printf(
      "LRE >= 6: ours %d / %zu, Ceres %d / %zu; converged with LRE < 4 (wrong answer): ours %d, Ceres %d\n",
      oursOk, out.size(), ceresOk, out.size(), oursWrong, ceresWrong);
  std::printf("total time: ours %.3f ms, Ceres %.3f ms (ratio %.2f)\n", oursTotal * 1e3, ceresTotal * 1e3,
              oursTotal / ceresTotal);
  return out;
}

}  // namespace metrofit::bench
