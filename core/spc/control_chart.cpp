#include "core/spc/control_chart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <numbers>

namespace metrofit {
namespace {

constexpr double kStep = 0.05;
constexpr int kXCount = 361;  // x in [-9, 9]
constexpr int kWCount = 321;  // w in [0, 16], an even number of Simpson intervals
constexpr double kX0 = -9.0;

struct NormalGrid {
  std::array<double, kXCount + kWCount - 1> Phi{};  // Phi(kX0 + j h), x + w up to 25
  std::array<double, kXCount> phi{};
  NormalGrid() {
    for (std::size_t j = 0; j < Phi.size(); ++j) {
      const double t = kX0 + kStep * static_cast<double>(j);
      Phi[j] = 0.5 * std::erfc(-t / std::numbers::sqrt2);
    }
    for (std::size_t i = 0; i < phi.size(); ++i) {
      const double t = kX0 + kStep * static_cast<double>(i);
      phi[i] = std::exp(-0.5 * t * t) / std::sqrt(2.0 * std::numbers::pi);
    }
  }
};

/// d2, d3 and the chart constants for one n from the distribution of the range (header comment).
ControlChartConstants computeConstants(int n) {
  static const NormalGrid grid;
  const double h = kStep;
  double d2 = 0.0, m2 = 0.0;
  for (int k = 0; k < kWCount; ++k) {
    double g = 0.0;
    for (int i = 0; i < kXCount; ++i) {
      const double diff = grid.Phi[static_cast<std::size_t>(i + k)] - grid.Phi[static_cast<std::size_t>(i)];
      g += grid.phi[static_cast<std::size_t>(i)] * std::pow(diff, n - 1);
    }
    g *= n * h;
    const double simpson = (k == 0 || k == kWCount - 1) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    const double w = h * k;
    d2 += simpson * (1.0 - g);
    m2 += simpson * 2.0 * w * (1.0 - g);
  }
  d2 *= h / 3.0;
  m2 *= h / 3.0;
  ControlChartConstants c;
  c.n = n;
  c.d2 = d2;
  c.d3 = std::sqrt(std::max(0.0, m2 - d2 * d2));
  c.A2 = 3.0 / (d2 * std::sqrt(static_cast<double>(n)));
  c.D3 = std::max(0.0, 1.0 - 3.0 * c.d3 / d2);
  c.D4 = 1.0 + 3.0 * c.d3 / d2;
  c.E2 = 3.0 / d2;
  return c;
}

}  // namespace

const ControlChartConstants& controlChartConstants(int n) {
  if (n < kMinSubgroupSize || n > kMaxSubgroupSize) {
    throw OptionsError(
        ErrorContext{{}, 0, 0, "subgroup size"},
        "must be between 2 and 25 (the range of the A2/D3/D4 table), got " + std::to_string(n));
  }
  // Computed on first use of each n (about 10 ms each), then cached.
  static std::array<ControlChartConstants, kMaxSubgroupSize + 1> cache{};
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  ControlChartConstants& c = cache[static_cast<std::size_t>(n)];
  if (c.n == 0) c = computeConstants(n);
  return c;
}

const char* chartTypeName(ChartType type) {
  return type == ChartType::IndividualsMR ? "x-mr" : "xbar-r";
}

XbarRChart xbarRChart(const std::vector<double>& values, int n, const ErrorContext& where) {
  controlChartConstants(n);  // OptionsError outside [2, 25]
  return controlChart(values, n, 0, where);
}

XbarRChart controlChart(const std::vector<double>& values, int n, std::size_t base,
                        const ErrorContext& where) {
  if (n < 1 || n > kMaxSubgroupSize) {
    throw OptionsError(ErrorContext{{}, 0, 0, "subgroup size"},
                       "must be between 1 (individuals and moving range) and 25 (the range of the A2/D3/D4 "
                       "table), got " +
                           std::to_string(n));
  }
  const bool individuals = n == 1;
  const ControlChartConstants& c = controlChartConstants(individuals ? 2 : n);
  const std::size_t k = values.size() / static_cast<std::size_t>(n);
  if (k < 2) {
    if (individuals) {
      throw ValidationError(where, "has " + std::to_string(values.size()) + " value" +
                                       (values.size() == 1 ? "" : "s") +
                                       ": at least 2 are needed for a moving range");
    }
    throw ValidationError(where, "has " + std::to_string(values.size()) + " value" +
                                     (values.size() == 1 ? "" : "s") + ": at least 2 subgroups of " +
                                     std::to_string(n) + " (" + std::to_string(2 * n) +
                                     " values) are needed");
  }
  if (base == 1) {
    throw ValidationError(where,
                          "a base of 1 subgroup has no range to set control limits from: give 2 or more");
  }
  if (base > k) {
    throw ValidationError(
        where, "has " + std::to_string(k) +
                   (individuals ? " values" : " complete subgroups of " + std::to_string(n)) +
                   ", fewer than the base of " + std::to_string(base) + " to set control limits from");
  }
  XbarRChart chart;
  chart.subgroupSize = n;
  chart.type = individuals ? ChartType::IndividualsMR : ChartType::XbarR;
  chart.baseSubgroups = base == 0 ? k : base;
  chart.means.reserve(k);
  chart.ranges.reserve(k);
  for (std::size_t g = 0; g < k; ++g) {
    const auto first = values.begin() + static_cast<std::ptrdiff_t>(g * static_cast<std::size_t>(n));
    const auto last = first + n;
    double sum = 0.0;
    for (auto it = first; it != last; ++it) {
      if (!std::isfinite(*it)) {
        throw ValidationError(where,
                              "value " + std::to_string(it - values.begin() + 1) + " is not a finite number");
      }
      sum += *it;
    }
    chart.means.push_back(sum / n);
    if (individuals) {
      if (g > 0) chart.ranges.push_back(std::abs(*first - *(first - 1)));
    } else {
      const auto [lo, hi] = std::minmax_element(first, last);
      chart.ranges.push_back(*hi - *lo);
    }
  }
  // Centre lines from the base: K subgroup means and their K ranges (K - 1 moving ranges).
  const std::size_t kb = chart.baseSubgroups;
  const std::size_t rb = individuals ? kb - 1 : kb;
  for (std::size_t g = 0; g < kb; ++g) chart.grandMean += chart.means[g] / static_cast<double>(kb);
  for (std::size_t j = 0; j < rb; ++j) chart.meanRange += chart.ranges[j] / static_cast<double>(rb);
  // The mean of every subgroup, summed the same way (bit for bit grandMean when the base is all).
  for (std::size_t g = 0; g < k; ++g) chart.meanOfAll += chart.means[g] / static_cast<double>(k);
  if (!(chart.meanRange > 0.0)) {
    const std::string of = kb == k ? "" : " of the first " + std::to_string(kb);
    throw ValidationError(
        where, individuals ? "every moving range" + of +
                                 " is 0: no variation between consecutive values to set control limits from "
                                 "(is the measurement resolution too coarse?)"
                           : "every subgroup" + of +
                                 " has a range of 0: no within-subgroup variation to set control limits "
                                 "from (is the measurement resolution too coarse?)");
  }
  const double factor = individuals ? c.E2 : c.A2;
  chart.xbarUcl = chart.grandMean + factor * chart.meanRange;  // Eq. 18
  chart.xbarLcl = chart.grandMean - factor * chart.meanRange;  // Eq. 19
  chart.rUcl = c.D4 * chart.meanRange;
  chart.rLcl = c.D3 * chart.meanRange;
  for (std::size_t g = 0; g < k; ++g) {
    if (chart.means[g] > chart.xbarUcl || chart.means[g] < chart.xbarLcl) chart.xbarOutOfControl.push_back(g);
  }
  for (std::size_t j = 0; j < chart.ranges.size(); ++j) {
    if (chart.ranges[j] > chart.rUcl || chart.ranges[j] < chart.rLcl)
      chart.rOutOfControl.push_back(chart.rangeSubgroup(j));
  }
  return chart;
}

}  // namespace metrofit
