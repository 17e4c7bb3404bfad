// The setup simulator (core/sim/setup_sim.h, paper Eq. 12-13): determinism, ranges, the report
// writer, and the bundled demo report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../setup/setup_fixtures.h"
#include "core/io/csv.h"
#include "core/setup/exact.h"
#include "core/setup/report.h"
#include "core/sim/setup_sim.h"

namespace metrofit {
namespace {

TEST(SetupSim, SetsAreDeterministicAndIndependentOfOrder) {
  const setup::Model m = setup::readModel(setup::test::paperModelPath());
  SetupSimOptions o;
  o.seed = 11;
  const auto all = simulateSetupSets(m, o, 5);
  ASSERT_EQ(all.size(), 5u);
  const SetupMeasurementSet third = simulateSetupSet(m, o, 3);
  EXPECT_EQ(third.setupErrorMm, all[3].setupErrorMm);  // bit for bit, any order
  EXPECT_EQ(third.deviationMm, all[3].deviationMm);
  EXPECT_NE(all[2].deviationMm, all[3].deviationMm);
  o.seed = 12;
  EXPECT_NE(simulateSetupSet(m, o, 3).deviationMm, third.deviationMm);
}

TEST(SetupSim, ErrorsFollowEquations12And13) {
  const setup::Model m = setup::readModel(setup::test::paperModelPath());
  const Eigen::MatrixXd g = setup::gainMatrix(m);
  SetupSimOptions o;
  double maxSd = 0.0, maxRandom = 0.0;
  for (std::size_t j = 0; j < 50; ++j) {
    const SetupMeasurementSet s = simulateSetupSet(m, o, j);
    ASSERT_EQ(s.setupErrorMm.size(), 10u);
    ASSERT_EQ(s.deviationMm.size(), 28u);
    const Eigen::VectorXd shift = g * Eigen::Map<const Eigen::VectorXd>(s.setupErrorMm.data(), 10);
    for (double e : s.setupErrorMm) maxSd = std::max(maxSd, std::abs(e));
    for (std::size_t q = 0; q < 28; ++q)
      maxRandom = std::max(maxRandom, std::abs(s.deviationMm[q] - shift(q)));
  }
  // |w (1 - 2r)| <= w, and with 500 / 1400 draws the extremes come close to w.
  EXPECT_LE(maxSd, o.w1);
  EXPECT_GT(maxSd, 0.95 * o.w1);
  EXPECT_LE(maxRandom, o.w2 + 1e-15);
  EXPECT_GT(maxRandom, 0.95 * o.w2);
  // Without random errors the setup errors are fully correctable (they are inside the bounds):
  // the exact correction then reaches the f1 of the error-free parts up to the grid rounding.
  o.w2 = 0.0;
  const SetupMeasurementSet clean = simulateSetupSet(m, o, 0);
  const double f1 = setup::solveExact(setup::SetupInstance(m, clean.deviationMm)).score.f1;
  const double ideal = setup::solveExact(setup::SetupInstance(m, std::vector<double>(28, 0.0))).score.f1;
  EXPECT_LE(f1, ideal + 1e-12);
  EXPECT_GE(f1, ideal - 0.002);
}

TEST(SetupSim, ReportSeriesIsAReadableCmmReport) {
  const setup::Model m = setup::readModel(setup::test::paperModelPath());
  SetupSimOptions o;
  o.parts = 4;
  o.seed = 5;
  std::vector<double> esd;
  const std::string text = simulateSetupReport(m, o, &esd);
  EXPECT_EQ(text, simulateSetupReport(m, o));
  const CsvTable t = parseCsv(text, "sim.csv");
  EXPECT_EQ(t.rowCount(), 4u * 28u);
  const setup::Measurements meas = setup::cmmReportFromCsv(t, m);
  EXPECT_EQ(meas.parts, (std::vector<std::string>{"1", "2", "3", "4"}));
  EXPECT_EQ(t.cell(0, 1), "12");
  EXPECT_EQ(t.cell(t.rowCount() - 1, 1), "48");
  // Mean deviation = G E^sd + mean of 4 random errors (|.| <= w2) + rounding to 0.001 mm.
  const Eigen::VectorXd shift = setup::gainMatrix(m) * Eigen::Map<const Eigen::VectorXd>(esd.data(), 10);
  for (std::size_t q = 0; q < 28; ++q)
    EXPECT_LE(std::abs(meas.deviationMm[q] - shift(q)), o.w2 + 0.0005 + 1e-12);
  SetupSimOptions bad;
  bad.w1 = -1.0;
  EXPECT_THROW((void)simulateSetupReport(m, bad), OptionsError);
}

// resources/demo/setup/paper_example_report.csv is simulator output (see resources/demo/setup/
// README.md): metrofit-cli simulate setup --model paper_example.json --parts 3 --seed 6.
TEST(SetupSim, DemoReportIsSimulatorOutput) {
  const setup::Model m = setup::readModel(setup::test::paperModelPath());
  SetupSimOptions o;
  o.parts = 3;
  o.seed = 6;
  const std::string committed = metrofit::test::readText(
      (metrofit::test::sourceDir() / "resources/demo/setup/paper_example_report.csv").string());
  EXPECT_EQ(committed, simulateSetupReport(m, o));
}

}  // namespace
}  // namespace metrofit
