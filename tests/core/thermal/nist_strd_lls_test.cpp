// The regression solve of the thermal models (core/thermal/linear_least_squares.h, used by the linear,
// lag and dlag models) on the NIST StRD linear regression problems (../shared/data/real/nist-strd-lls:
// Filip, degree 10 and notoriously ill-conditioned; Pontius; Wampler 1-4, degree 5), against NIST's
// certified coefficients, standard deviations and residual sums of squares (15 digits). Log relative
// error (tests/nist_strd.h) of each: >= 6 everywhere. The standard deviations are computed here from
// the solve's residual and a QR of the design (test code); the coefficients and the RSS are the
// solve's own.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/thermal/linear_least_squares.h"
#include "nist_strd.h"
#include "testsupport.h"

namespace metrofit::test {
namespace {

struct Lls {
  std::string name;
  int degree = 0;
  std::vector<double> coef, sd;
  double rss = 0.0;
};

/// Certified values (NIST StRD; nist-strd-lls/certified_values.txt and Filip_certified.txt).
std::vector<Lls> certified() {
  std::vector<Lls> out;
  {
    Lls f{"Filip", 10, {}, {}, 0.795851382172941E-03};
    std::ifstream in(realData("nist-strd-lls/Filip_certified.txt"));
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream ls(line);
      std::string name, b, s;
      ls >> name >> b >> s;
      f.coef.push_back(cnumber(b));
      f.sd.push_back(cnumber(s));
    }
    out.push_back(f);
  }
  out.push_back({"Pontius",
                 2,
                 {0.673565789473684E-03, 0.732059160401003E-06, -0.316081871345029E-14},
                 {0.107938612033077E-03, 0.157817399981659E-09, 0.486652849992036E-16},
                 0.155761768796992E-05});
  out.push_back({"Wampler1", 5, std::vector<double>(6, 1.0), std::vector<double>(6, 0.0), 0.0});
  out.push_back({"Wampler2", 5, {1.0, 0.1, 0.01, 0.001, 1e-4, 1e-5}, std::vector<double>(6, 0.0), 0.0});
  out.push_back({"Wampler3",
                 5,
                 std::vector<double>(6, 1.0),
                 {2152.32624678170, 2363.55173469681, 779.343524331583, 101.475507550350, 5.64566512170752,
                  0.112324854679312},
                 83554268.0000000});
  out.push_back({"Wampler4",
                 5,
                 std::vector<double>(6, 1.0),
                 {215232.624678170, 236355.173469681, 77934.3524331583, 10147.5507550350, 564.566512170752,
                  11.2324854679312},
                 835542680000.000});
  return out;
}

void readData(const std::string& path, Eigen::VectorXd& y, Eigen::VectorXd& x) {
  std::ifstream in(path);
  std::vector<double> ys, xs;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string a, b;
    ls >> a >> b;
    ys.push_back(cnumber(a));
    xs.push_back(cnumber(b));
  }
  y = Eigen::Map<Eigen::VectorXd>(ys.data(), static_cast<Eigen::Index>(ys.size()));
  x = Eigen::Map<Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
}

TEST(NistStrdLls, ThermalRegressionSolveMeetsTheCertifiedValues) {
  METROFIT_REQUIRE_PATH(realData("nist-strd-lls"));
  for (const Lls& c : certified()) {
    SCOPED_TRACE(c.name);
    Eigen::VectorXd y, x;
    readData((realData("nist-strd-lls") / (c.name + ".txt")).string(), y, x);
    ASSERT_GT(y.size(), c.degree + 1);
    Eigen::MatrixXd X(y.size(), c.degree + 1);
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      double p = 1.0;
      for (int k = 0; k <= c.degree; ++k, p *= x(i)) X(i, k) = p;
    }
    const Eigen::VectorXd b = thermal::linearLeastSquares(X, y);
    const double rss = (X * b - y).squaredNorm();
    const Eigen::VectorXd sd = nist::standardDeviations(X, rss);
    double lreB = 99, lreSd = 99;
    for (int k = 0; k <= c.degree; ++k) {
      lreB = std::min(lreB, nist::lre(b(k), c.coef[static_cast<std::size_t>(k)], 15));
      lreSd = std::min(lreSd, nist::lre(sd(k), c.sd[static_cast<std::size_t>(k)], 15));
    }
    const double lreRss = nist::lre(rss, c.rss, 15);
    std::printf("%-9s LRE b %5.2f  sd %5.2f  rss %5.2f\n", c.name.c_str(), lreB, lreSd, lreRss);
    EXPECT_GE(lreB, 6.0);
    EXPECT_GE(lreSd, 6.0);
    EXPECT_GE(lreRss, 6.0);
    if (c.name == "Filip") {
      // The test has teeth: the normal equations in double lose Filip (condition number squared).
      const Eigen::VectorXd bn = (X.transpose() * X).ldlt().solve(X.transpose() * y);
      double lreN = 99;
      for (int k = 0; k <= c.degree; ++k)
        lreN = std::min(lreN, nist::lre(bn(k), c.coef[static_cast<std::size_t>(k)], 15));
      std::printf("Filip by the normal equations (LDLT): LRE b %5.2f\n", lreN);
      EXPECT_LT(lreN, 6.0);
    }
  }
}

}  // namespace
}  // namespace metrofit::test
