// The shared Levenberg-Marquardt (core/optim/least_squares.h) on the 27 NIST StRD nonlinear
// regression problems (../shared/data/real/nist-strd-nls, certified by NIST in 128-bit arithmetic),
// from both of NIST's starts, with analytic derivatives written in tests/nist_strd.h from each file's
// model. Log relative errors (LRE) of the parameters, their standard deviations and the residual sum
// of squares against the certified values:
//   start 2 (near): must converge, LRE >= 6 for all three;
//   start 1 (far):  either LRE >= 6, or a clean "did not converge" - never a wrong answer reported as
//                   converged.
// The RSS and standard-deviation LRE are asked for up to what double precision can carry: where the
// certified RSS is at the rounding level of the responses (Lanczos1: RSS 1.4e-25 from data of 13
// digits), the residuals themselves are computed to a few digits only (achievableLre).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "nist_strd.h"
#include "testsupport.h"

namespace metrofit::test {
namespace {

std::filesystem::path nlsFile(const std::string& name) {
  return realData("nist-strd-nls") / (name + ".dat");
}

TEST(NistStrdNls, ReaderReadsEveryFile) {
  METROFIT_REQUIRE_PATH(realData("nist-strd-nls"));
  for (const std::string& name : nist::problemNames()) {
    const nist::Problem p = nist::readProblem(nlsFile(name).string());
    EXPECT_EQ(p.start1.size(), p.parameters()) << name;
    EXPECT_GT(p.y.size(), static_cast<Eigen::Index>(p.parameters())) << name;
    EXPECT_GT(p.certifiedRss, 0.0) << name;
  }
  const nist::Problem m = nist::readProblem(nlsFile("Misra1a").string());
  EXPECT_EQ(m.y.size(), 14);
  EXPECT_DOUBLE_EQ(m.certified[0], 2.3894212918E+02);
  EXPECT_EQ(m.certifiedDigits[0], 11);
  EXPECT_DOUBLE_EQ(m.x(13, 0), 760.0);
  EXPECT_DOUBLE_EQ(m.y(13), 81.78);
  const nist::Problem n = nist::readProblem(nlsFile("Nelson").string());
  EXPECT_EQ(n.x.cols(), 2);
  EXPECT_EQ(n.y.size(), 128);
}

// The analytic derivatives of every model against central differences at both starts and at the
// certified values: a typo in a hand-written derivative would otherwise pass as "did not converge".
TEST(NistStrdNls, AnalyticDerivativesMatchDifferences) {
  METROFIT_REQUIRE_PATH(realData("nist-strd-nls"));
  for (const std::string& name : nist::problemNames()) {
    const nist::Problem p = nist::readProblem(nlsFile(name).string());
    const nist::Model f = nist::model(name);
    for (const auto* b0 : {&p.start1, &p.start2, &p.certified}) {
      const std::vector<double>& b = *b0;
      Eigen::VectorXd g(static_cast<Eigen::Index>(b.size()));
      for (Eigen::Index i = 0; i < p.y.size(); i += 7) {
        f(b.data(), p.x.row(i), g.data());
        for (std::size_t k = 0; k < b.size(); ++k) {
          std::vector<double> lo = b, hi = b;
          const double h = 1e-6 * (b[k] != 0.0 ? std::abs(b[k]) : 1e-6);
          lo[k] -= h;
          hi[k] += h;
          const double d =
              (f(hi.data(), p.x.row(i), nullptr) - f(lo.data(), p.x.row(i), nullptr)) / (2.0 * h);
          EXPECT_TRUE(near(g(static_cast<Eigen::Index>(k)), d, 1e-6 * (1.0 + std::abs(d)), 1e-5))
              << name << " row " << i << " b" << k + 1;
        }
      }
    }
  }
}

/// The LRE of the RSS that residuals computed in double can carry: each residual f - y has an absolute
/// rounding error of about eps max|y|, so the RSS is known to 2 sqrt(m RSS) eps max|y|.
double achievableLre(const nist::Problem& p) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double delta = 2.0 * std::sqrt(static_cast<double>(p.y.size()) * p.certifiedRss) * eps *
                       nist::transformedResponse(p).cwiseAbs().maxCoeff();
  return -std::log10(delta / p.certifiedRss);
}

TEST(NistStrdNls, RoszmanFileErratumIsCorrectedAndTheFitAgreesWithNist) {
  METROFIT_REQUIRE_PATH(nlsFile("Roszman1"));
  nist::Problem p = nist::readProblem(nlsFile("Roszman1").string());
  EXPECT_DOUBLE_EQ(p.certified[0], 1.20196866396);  // as the stored file prints it
  EXPECT_FALSE(nist::applyErrata(p).empty());
  EXPECT_DOUBLE_EQ(p.certified[0], 0.20196866396);
  const nist::Fit r = nist::fit(p, 2);
  EXPECT_GE(nist::lre(r.b(0), 0.20196866396, 11), 8.0);
}

TEST(NistStrdNls, LanczosOneRssIsAtTheRoundingLevel) {
  METROFIT_REQUIRE_PATH(nlsFile("Lanczos1"));
  EXPECT_LT(achievableLre(nist::readProblem(nlsFile("Lanczos1").string())), 3.0);
  EXPECT_GT(achievableLre(nist::readProblem(nlsFile("Lanczos2").string())), 6.0);
}

class NistStrdNlsProblem : public ::testing::TestWithParam<std::string> {};

TEST_P(NistStrdNlsProblem, CertifiedDigitsOrCleanFailure) {
  const std::string name = GetParam();
  METROFIT_REQUIRE_PATH(nlsFile(name));
  nist::Problem p = nist::readProblem(nlsFile(name).string());
  nist::applyErrata(p);
  const double floor = std::min(6.0, achievableLre(p));
  for (const int start : {1, 2}) {
    const nist::Fit r = nist::fit(p, start);
    std::printf("%-9s start %d: %-18s %5ld it  LRE b %5.2f  sd %5.2f  rss %5.2f\n", name.c_str(), start,
                r.termination.c_str(), r.iterations, r.lre, r.sdLre, r.rssLre);
    SCOPED_TRACE(name + " from start " + std::to_string(start) + ": " + r.termination);
    if (start == 2) {
      EXPECT_TRUE(r.converged);
    }
    if (r.converged) {
      EXPECT_GE(r.lre, 6.0) << "converged to a wrong answer";
      EXPECT_GE(r.sdLre, floor);
      EXPECT_GE(r.rssLre, floor);
    }
    EXPECT_TRUE(r.b.allFinite());
  }
}

INSTANTIATE_TEST_SUITE_P(Nist, NistStrdNlsProblem, ::testing::ValuesIn(nist::problemNames()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace metrofit::test
