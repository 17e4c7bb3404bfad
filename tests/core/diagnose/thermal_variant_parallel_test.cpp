// fitDeclaredAndWithEffects (core/diagnose/thermal_applied.h) fits the declared and the with-effects
// variant at once. Each fit is seeded, so the results are those of the two fits made one after the
// other, bit for bit; the observer sees the same calls in the same order as in the sequential run,
// never two at once; a Stop in either part cancels as the sequential run did.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

#include "core/diagnose/thermal_applied.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_model.h"
#include "testsupport.h"

namespace metrofit::diagnose {
namespace {

const std::vector<std::string> kDeclared{"T2", "T4", "T_amb"};
using Call = std::tuple<long, long, double, double>;  // iteration, evaluations, best, progress

/// Records every call; counts calls that overlap another (there must be none); says Stop at call
/// `stopAt` (0-based; never when negative).
class Recorder final : public Observer {
 public:
  explicit Recorder(long stopAt = -1) : stopAt_(stopAt) {}
  ObserverDecision onIteration(const IterationSummary& s) override {
    if (inside_.exchange(true)) ++overlaps;
    calls.emplace_back(s.iteration, s.evaluations, s.best, s.progress);
    const bool stop = stopAt_ >= 0 && static_cast<long>(calls.size()) - 1 >= stopAt_;
    inside_ = false;
    return stop ? ObserverDecision::Stop : ObserverDecision::Continue;
  }
  std::vector<Call> calls;
  int overlaps = 0;

 private:
  long stopAt_;
  std::atomic<bool> inside_{false};
};

struct Series {
  thermal::ThermalSeries declared, withEffects;
};

Series demoSeries() {
  const ThermalLog log =
      readThermalLog((test::sourceDir() / "resources/demo/data/diagnose_thermal.csv").string());
  const AppliedThermalEffects a = appliedThermalEffects(
      nlohmann::json::parse(R"([{"name": "lag:T2", "parameters": {"tau_min": 15.0}}, {"name": "drift"}])"),
      log, "disp_z_um", kDeclared);
  const ThermalLogWithEffects with = withThermalEffects(log, kDeclared, a.effects);
  return {thermal::selectThermalSeries(log, "disp_z_um", kDeclared),
          thermal::selectThermalSeries(with.log, "disp_z_um", with.inputs)};
}

thermal::ThermalFitOptions optionsFor(thermal::ThermalModelKind kind) {
  thermal::ThermalFitOptions o;
  o.model = kind;
  o.setSeed(7);
  return o;
}

void expectSameFit(const thermal::ThermalEvaluation& a, const thermal::ThermalEvaluation& b,
                   const char* what) {
  EXPECT_EQ(a.predicted, b.predicted) << what;  // bit for bit
  EXPECT_EQ(a.heldout.rmse, b.heldout.rmse) << what;
  EXPECT_EQ(a.fit.rmse, b.fit.rmse) << what;
  EXPECT_EQ(a.training.run.termination, b.training.run.termination) << what;
  EXPECT_EQ(a.training.run.iterations, b.training.run.iterations) << what;
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(ThermalVariantParallel, ResultsAndObserverCallsAreThoseOfTheSequentialRun) {
  const Series s = demoSeries();
  for (thermal::ThermalModelKind kind :
       {thermal::ThermalModelKind::Gnnmci, thermal::ThermalModelKind::Gmc, thermal::ThermalModelKind::Mlp}) {
    const thermal::ThermalFitOptions o = optionsFor(kind);
    Recorder sequential;
    auto t0 = std::chrono::steady_clock::now();
    const thermal::ThermalEvaluation e0 = thermal::fitAndEvaluate(s.declared, 0.5, o, &sequential);
    const thermal::ThermalEvaluation e1 = thermal::fitAndEvaluate(s.withEffects, 0.5, o, &sequential);
    const double tSequential = seconds(t0);
    Recorder parallel;
    t0 = std::chrono::steady_clock::now();
    const ThermalVariantFit v = fitDeclaredAndWithEffects(s.declared, s.withEffects, 0.5, o, &parallel);
    const double tParallel = seconds(t0);
    std::cout << thermal::toString(kind) << ": sequential " << tSequential << " s, parallel " << tParallel
              << " s, " << sequential.calls.size() << " observer calls\n";
    expectSameFit(v.declared, e0, "declared");
    expectSameFit(v.withEffects, e1, "with effects");
    EXPECT_FALSE(v.cancelled);
    EXPECT_EQ(v.usesEffects, keepsAppliedEffects(e0.heldout.rmse, e1.heldout.rmse));
    EXPECT_EQ(parallel.calls, sequential.calls);
    EXPECT_EQ(parallel.overlaps, 0);
  }
}

TEST(ThermalVariantParallel, StopInTheDeclaredFitCancelsLikeTheSequentialRun) {
  const Series s = demoSeries();
  const thermal::ThermalFitOptions o = optionsFor(thermal::ThermalModelKind::Gnnmci);
  Recorder all;
  (void)fitDeclaredAndWithEffects(s.declared, s.withEffects, 0.5, o, &all);
  ASSERT_GT(all.calls.size(), 40u);
  Recorder sequentialStop(9);
  const thermal::ThermalEvaluation e0 = thermal::fitAndEvaluate(s.declared, 0.5, o, &sequentialStop);
  ASSERT_EQ(e0.training.run.termination, Termination::Cancelled);
  Recorder stop(9);
  const ThermalVariantFit v = fitDeclaredAndWithEffects(s.declared, s.withEffects, 0.5, o, &stop);
  EXPECT_TRUE(v.cancelled);
  EXPECT_FALSE(v.usesEffects);
  expectSameFit(v.declared, e0, "declared, stopped");
  EXPECT_TRUE(v.withEffects.predicted.empty());  // reported as not run, as in the sequential run
  EXPECT_EQ(stop.calls, std::vector<Call>(all.calls.begin(), all.calls.begin() + 10));
  EXPECT_EQ(stop.overlaps, 0);
}

TEST(ThermalVariantParallel, StopInTheWithEffectsFitCancelsAndReportsIt) {
  const Series s = demoSeries();
  const thermal::ThermalFitOptions o = optionsFor(thermal::ThermalModelKind::Gnnmci);
  Recorder declaredOnly;
  (void)thermal::fitAndEvaluate(s.declared, 0.5, o, &declaredOnly);
  Recorder all;
  (void)fitDeclaredAndWithEffects(s.declared, s.withEffects, 0.5, o, &all);
  const long n0 = static_cast<long>(declaredOnly.calls.size());
  ASSERT_GT(static_cast<long>(all.calls.size()), n0 + 10);
  for (long at : {n0, n0 + 5}) {
    Recorder stop(at);
    const ThermalVariantFit v = fitDeclaredAndWithEffects(s.declared, s.withEffects, 0.5, o, &stop);
    EXPECT_TRUE(v.cancelled) << at;
    EXPECT_TRUE(v.usesEffects) << at;  // the cancelled run is the one reported
    EXPECT_NE(v.declared.training.run.termination, Termination::Cancelled) << at;
    EXPECT_EQ(stop.calls, std::vector<Call>(all.calls.begin(), all.calls.begin() + at + 1)) << at;
    EXPECT_EQ(stop.overlaps, 0);
  }
}

}  // namespace
}  // namespace metrofit::diagnose
