#include "bench_diagnose_scale.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <thread>

#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/diagnose/thermal_diagnosis.h"

namespace metrofit::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

diagnose::ThermalDiagnosisOptions scaleOptions() {
  diagnose::ThermalDiagnosisOptions o;
  o.target = "disp_um";
  o.inputs = {"T1", "T2", "T3"};
  return o;
}

}  // namespace

ThermalLog scaleLog(std::size_t rows, std::uint64_t seed) {
  Rng rng(seed);
  ThermalLog log;
  log.source = "scale-" + std::to_string(rows) + ".csv";
  log.timeColumn = "time_s";
  log.timeMin.resize(rows);
  for (std::size_t k = 0; k < rows; ++k) log.timeMin[k] = static_cast<double>(k) / 60.0;
  ThermalChannel rpm{"spindle_rpm", "rpm", std::vector<double>(rows)};
  {
    double until = 0.0, speed = 0.0;
    for (std::size_t k = 0; k < rows; ++k) {
      const double t = log.timeMin[k];
      if (t >= until) {
        until = t + rng.uniform(30.0, 240.0);
        speed = rng.uniform() < 0.4 ? 0.0 : std::round(rng.uniform(500.0, 6000.0) / 250.0) * 250.0;
      }
      rpm.values[k] = speed;
    }
  }
  log.channels.push_back(rpm);
  const double dt = 1.0 / 60.0;
  std::vector<std::vector<double>> temps;
  for (int j = 0; j < 18; ++j) {
    const double tau = 5.0 * std::pow(72.0, j / 17.0);  // 5 min .. 6 h
    const double gain = rng.uniform(0.5, 3.0) / 6000.0;
    const double ambient = rng.uniform(0.2, 1.0);
    const double a = 1.0 - std::exp(-dt / tau);
    ThermalChannel c{"T" + std::to_string(j + 1), "degC", std::vector<double>(rows)};
    double s = 0.0;
    for (std::size_t k = 0; k < rows; ++k) {
      s += a * (gain * rpm.values[k] * 10.0 - s);
      const double day = ambient * std::sin(2.0 * M_PI * log.timeMin[k] / 1440.0 + j);
      c.values[k] = 20.0 + s + day + 0.01 * rng.normal();
    }
    log.channels.push_back(std::move(c));
  }
  const auto& t1 = log.channels[1].values;
  const auto& t2 = log.channels[2].values;
  const auto& t3 = log.channels[3].values;
  ThermalChannel y{"disp_um", "um", std::vector<double>(rows)};
  const double a20 = 1.0 - std::exp(-dt / 20.0);
  double l = t1[0];
  for (std::size_t k = 0; k < rows; ++k) {
    l += a20 * (t1[k] - l);
    y.values[k] = -2.0 * (l - t1[0]) - 1.5 * (t2[k] - t2[0]) + (t3[k] - t3[0]) + 0.0003 * rpm.values[k] +
                  0.3 * rng.normal();
  }
  log.channels.push_back(std::move(y));
  return log;
}

nlohmann::json benchDiagnoseScale(const std::vector<std::size_t>& rows) {
  nlohmann::json out = nlohmann::json::array();
  // CPU seconds of this process (one thread) beside the wall clock: on a shared machine the wall
  // clock also counts the time other processes held the core.
  std::printf("diagnose thermal, declared T1,T2,T3, 20 data columns, 1 Hz (one thread)\n");
  std::printf("%10s %8s %8s %8s %10s %10s %6s  %s\n", "rows", "wall_s", "cpu_s", "tried", "heldout0",
              "heldout1", "white", "accepted");
  for (std::size_t n : rows) {
    const ThermalLog log = scaleLog(n);
    const auto t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    const diagnose::Diagnosis d = diagnose::diagnoseThermal(log, scaleOptions());
    const double s = seconds(t0);
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    const bool white = d.residualCheck && d.residualCheck->white;
    std::string acc;
    for (const auto* c : d.accepted()) acc += (acc.empty() ? "" : ",") + c->name;
    std::printf("%10zu %8.2f %8.2f %8zu %10.3f %10.3f %6s  %s\n", n, s, cpu, d.effects.size(),
                *d.baseline.heldoutRmse, *d.final.heldoutRmse, white ? "yes" : "no", acc.c_str());
    std::fflush(stdout);
    out.push_back({{"rows", n},
                   {"seconds", s},
                   {"cpu_seconds", cpu},
                   {"white", white},
                   {"candidates", d.effects.size()},
                   {"heldout_before", *d.baseline.heldoutRmse},
                   {"heldout_after", *d.final.heldoutRmse},
                   {"accepted", acc}});
  }
  // Cancel latency on the largest log: a token raised from another thread after 1 s.
  if (!rows.empty()) {
    const ThermalLog log = scaleLog(rows.back());
    CancelToken token;
    std::atomic<long> steps{0};
    FunctionObserver obs([&](const IterationSummary& s) {
      ++steps;
      return token.onIteration(s);
    });
    const auto t0 = Clock::now();
    std::atomic<bool> done{false};
    Clock::time_point raised{};
    std::atomic<bool> isRaised{false};
    std::thread raiser([&] {
      while (!done && seconds(t0) < 1.0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      if (done) return;
      raised = Clock::now();
      isRaised = true;
      token.cancel();
    });
    const diagnose::Diagnosis d = diagnose::diagnoseThermal(log, scaleOptions(), &obs);
    const auto end = Clock::now();
    done = true;
    raiser.join();
    const double latency = isRaised ? std::chrono::duration<double>(end - raised).count() : 0.0;
    std::printf("cancel after 1 s on %zu rows: returned %.3f s later (%ld progress steps, note '%s')\n",
                rows.back(), latency, steps.load(), d.notes.empty() ? "" : d.notes.back().c_str());
    out.push_back(
        {{"cancel_rows", rows.back()}, {"cancel_latency_s", latency}, {"progress_steps", steps.load()}});
  }
  return out;
}

}  // namespace metrofit::bench
