// Phase detection and decimation for the thermal trend chart (see trend_analysis.h for the maths).
#include "core/study/trend_analysis.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>

#include "core/common/error.h"
#include "core/thermal/thermal_log.h"

namespace metrofit {
namespace {

/// A run of consecutive rows with the same label: +1 heating, -1 cooling, 0 neither.
struct Run {
  int label = 0;
  std::size_t first = 0;  ///< first row (inclusive)
  std::size_t last = 0;   ///< last row (inclusive)
};

double runStart(const std::vector<double>& t, const Run& r) {
  return r.first == 0 ? t.front() : 0.5 * (t[r.first - 1] + t[r.first]);
}

double runEnd(const std::vector<double>& t, const Run& r) {
  return r.last + 1 >= t.size() ? t.back() : 0.5 * (t[r.last] + t[r.last + 1]);
}

std::vector<Run> runsOf(const std::vector<int>& labels) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (runs.empty() || runs.back().label != labels[i]) {
      runs.push_back({labels[i], i, i});
    } else {
      runs.back().last = i;
    }
  }
  return runs;
}

void mergeEqualNeighbours(std::vector<Run>& runs) {
  std::vector<Run> merged;
  for (const Run& r : runs) {
    if (!merged.empty() && merged.back().label == r.label) {
      merged.back().last = r.last;
    } else {
      merged.push_back(r);
    }
  }
  runs.swap(merged);
}

/// Absorbs runs shorter than minDuration into their longer neighbour, shortest first; idle runs at
/// either end are kept, and so is any end run when keepEndRuns. Every step removes at least one
/// run, so this terminates.
void absorbShortRuns(const std::vector<double>& t, std::vector<Run>& runs, double minDuration,
                     bool keepEndRuns) {
  while (runs.size() > 1) {
    std::size_t shortest = runs.size();
    double shortestDuration = minDuration;
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const bool atEnd = k == 0 || k + 1 == runs.size();
      if (atEnd && (keepEndRuns || runs[k].label == 0)) {
        continue;
      }
      const double duration = runEnd(t, runs[k]) - runStart(t, runs[k]);
      if (duration < shortestDuration) {
        shortestDuration = duration;
        shortest = k;
      }
    }
    if (shortest == runs.size()) {
      return;
    }
    std::size_t neighbour = 0;
    if (shortest == 0) {
      neighbour = 1;
    } else if (shortest + 1 == runs.size()) {
      neighbour = shortest - 1;
    } else {
      const Run& before = runs[shortest - 1];
      const Run& after = runs[shortest + 1];
      neighbour = (runEnd(t, before) - runStart(t, before)) >= (runEnd(t, after) - runStart(t, after))
                      ? shortest - 1
                      : shortest + 1;
    }
    runs[shortest].label = runs[neighbour].label;
    mergeEqualNeighbours(runs);
  }
}

std::vector<ThermalPhase> phasesOf(const std::vector<double>& t, const std::vector<Run>& runs) {
  std::vector<ThermalPhase> phases;
  for (const Run& r : runs) {
    if (r.label != 0) {
      phases.push_back({r.label > 0 ? ThermalPhaseKind::Heating : ThermalPhaseKind::Cooling, runStart(t, r),
                        runEnd(t, r)});
    }
  }
  return phases;
}

double medianSpacing(const std::vector<double>& t) {
  std::vector<double> dt(t.size() - 1);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    dt[i] = t[i + 1] - t[i];
  }
  const auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
  std::nth_element(dt.begin(), mid, dt.end());
  return *mid;
}

bool usable(const std::vector<double>& t, const std::vector<double>& v) {
  return t.size() >= 3 && v.size() == t.size() && t.back() > t.front();
}

}  // namespace

bool PhaseOptions::isValid(std::string* why) const {
  const auto fail = [why](const char* text) {
    if (why != nullptr) {
      *why = text;
    }
    return false;
  };
  if (!(smoothingFraction > 0.0 && smoothingFraction < 1.0)) {
    return fail("smoothingFraction must lie in (0, 1)");
  }
  if (!(slopeDeadBand >= 0.0 && slopeDeadBand < 1.0)) {
    return fail("slopeDeadBand must lie in [0, 1)");
  }
  if (!(speedOnFraction >= 0.0 && speedOnFraction < 1.0)) {
    return fail("speedOnFraction must lie in [0, 1)");
  }
  if (!(minPhaseFraction >= 0.0 && minPhaseFraction < 1.0)) {
    return fail("minPhaseFraction must lie in [0, 1)");
  }
  if (!(minPhaseChange >= 0.0 && std::isfinite(minPhaseChange))) {
    return fail("minPhaseChange must be finite and >= 0");
  }
  return true;
}

std::vector<double> localSlope(const std::vector<double>& timeMin, const std::vector<double>& value,
                               double windowMin) {
  const std::size_t n = std::min(timeMin.size(), value.size());
  std::vector<double> slope(n, 0.0);
  if (n < 2) {
    return slope;
  }
  // Prefix sums of shifted t, v, t^2, t*v: every window's fit in O(1). The shift by the first row
  // keeps the cancellation in var = S_tt/m - mean_t^2 small.
  const double t0 = timeMin.front();
  const double v0 = value.front();
  std::vector<double> st(n + 1, 0.0), sv(n + 1, 0.0), stt(n + 1, 0.0), stv(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = timeMin[i] - t0;
    const double v = value[i] - v0;
    st[i + 1] = st[i] + t;
    sv[i + 1] = sv[i] + v;
    stt[i + 1] = stt[i] + t * t;
    stv[i + 1] = stv[i] + t * v;
  }
  const double half = 0.5 * windowMin;
  std::size_t lo = 0;
  std::size_t hi = 0;  // window = rows [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    while (timeMin[lo] < timeMin[i] - half) {
      ++lo;
    }
    hi = std::max(hi, i + 1);
    while (hi < n && timeMin[hi] <= timeMin[i] + half) {
      ++hi;
    }
    // At least the two neighbours, so a window narrower than the row spacing still has a slope.
    const std::size_t a = std::min(lo, i > 0 ? i - 1 : 0);
    const std::size_t b = std::max(hi, std::min(n, i + 2));
    const double m = static_cast<double>(b - a);
    const double mt = (st[b] - st[a]) / m;
    const double mv = (sv[b] - sv[a]) / m;
    const double varT = (stt[b] - stt[a]) / m - mt * mt;
    const double covTV = (stv[b] - stv[a]) / m - mt * mv;
    slope[i] = varT > 0.0 ? covTV / varT : 0.0;
  }
  return slope;
}

std::vector<ThermalPhase> phasesFromSlope(const std::vector<double>& timeMin,
                                          const std::vector<double>& value, const PhaseOptions& options) {
  if (!usable(timeMin, value)) {
    return {};
  }
  const std::size_t n = timeMin.size();
  const double span = timeMin.back() - timeMin.front();
  const double window = std::max(options.smoothingFraction * span, 4.0 * medianSpacing(timeMin));
  const std::vector<double> slope = localSlope(timeMin, value, window);

  std::vector<double> magnitude(n);
  std::transform(slope.begin(), slope.end(), magnitude.begin(), [](double s) { return std::abs(s); });
  const auto p95 = magnitude.begin() + static_cast<std::ptrdiff_t>(std::min(n - 1, (n * 95) / 100));
  std::nth_element(magnitude.begin(), p95, magnitude.end());
  const double deadBand = options.slopeDeadBand * *p95;
  if (!(*p95 > 0.0)) {
    return {};
  }

  std::vector<int> labels(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    labels[i] = slope[i] > deadBand ? 1 : (slope[i] < -deadBand ? -1 : 0);
  }
  std::vector<Run> runs = runsOf(labels);
  const double minDuration = options.minPhaseFraction * span;
  absorbShortRuns(timeMin, runs, minDuration, false);

  // A phase must change the smoothed signal by at least minPhaseChange: integrate the slope.
  bool dropped = false;
  for (Run& r : runs) {
    if (r.label == 0) {
      continue;
    }
    double change = 0.0;
    for (std::size_t i = r.first; i <= r.last; ++i) {
      const double left = i == 0 ? timeMin[i] : 0.5 * (timeMin[i - 1] + timeMin[i]);
      const double right = i + 1 == n ? timeMin[i] : 0.5 * (timeMin[i] + timeMin[i + 1]);
      change += slope[i] * (right - left);
    }
    if (std::abs(change) < options.minPhaseChange) {
      r.label = 0;
      dropped = true;
    }
  }
  if (dropped) {
    mergeEqualNeighbours(runs);
    absorbShortRuns(timeMin, runs, minDuration, false);
  }
  return phasesOf(timeMin, runs);
}

std::vector<ThermalPhase> phasesFromSpeed(const std::vector<double>& timeMin,
                                          const std::vector<double>& speed, const PhaseOptions& options) {
  if (!usable(timeMin, speed)) {
    return {};
  }
  double maxSpeed = 0.0;
  for (double s : speed) {
    maxSpeed = std::max(maxSpeed, std::abs(s));
  }
  if (!(maxSpeed > 0.0)) {
    return {};
  }
  const double onLevel = options.speedOnFraction * maxSpeed;
  std::vector<int> labels(speed.size(), 0);
  bool ranBefore = false;
  for (std::size_t i = 0; i < speed.size(); ++i) {
    const bool running = std::abs(speed[i]) > onLevel;
    ranBefore = ranBefore || running;
    labels[i] = running ? 1 : (ranBefore ? -1 : 0);
  }
  std::vector<Run> runs = runsOf(labels);
  // A stop or start at either end of the log is real, however short: keep end runs.
  absorbShortRuns(timeMin, runs, options.minPhaseFraction * (timeMin.back() - timeMin.front()), true);
  return phasesOf(timeMin, runs);
}

std::vector<double> meanTemperature(const ThermalLog& log) {
  const auto isAmbient = [](const ThermalChannel& c) {
    std::string name = c.name;
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return name.find("amb") != std::string::npos;
  };
  std::vector<const ThermalChannel*> machine;
  std::vector<const ThermalChannel*> ambient;
  for (const ThermalChannel& c : log.channels) {
    if (channelKind(c) == ChannelKind::Temperature && c.values.size() == log.rows() && !hasGaps(c)) {
      (isAmbient(c) ? ambient : machine).push_back(&c);
    }
  }
  const std::vector<const ThermalChannel*>& used = machine.empty() ? ambient : machine;
  if (used.empty()) {
    return {};
  }
  std::vector<double> mean(log.rows(), 0.0);
  for (const ThermalChannel* c : used) {
    for (std::size_t i = 0; i < mean.size(); ++i) {
      mean[i] += c->values[i];
    }
  }
  for (double& m : mean) {
    m /= static_cast<double>(used.size());
  }
  return mean;
}

PhaseDetection detectThermalPhases(const ThermalLog& log, const PhaseOptions& options) {
  std::string why;
  if (!options.isValid(&why)) {
    throw OptionsError({"", 0, 0, "phase detection"}, why);
  }
  PhaseDetection result;
  for (const ThermalChannel& c : log.channels) {
    if (channelKind(c) == ChannelKind::Speed && c.values.size() == log.rows() && !hasGaps(c)) {
      result.phases = phasesFromSpeed(log.timeMin, c.values, options);
      if (!result.phases.empty()) {
        result.source = PhaseSource::Speed;
        result.channel = c.name;
        return result;
      }
      break;
    }
  }
  const std::vector<double> mean = meanTemperature(log);
  if (!mean.empty()) {
    result.phases = phasesFromSlope(log.timeMin, mean, options);
    result.source = PhaseSource::TemperatureSlope;
  }
  return result;
}

std::vector<std::size_t> decimateMinMax(const std::vector<double>& timeMin, const std::vector<double>& value,
                                        std::size_t maxPoints) {
  const std::size_t n = std::min(timeMin.size(), value.size());
  std::vector<std::size_t> rows;
  if (n <= std::max<std::size_t>(maxPoints, 4) || !(timeMin[n - 1] > timeMin[0])) {
    rows.resize(n);
    std::iota(rows.begin(), rows.end(), std::size_t{0});
    return rows;
  }
  const std::size_t buckets = (std::max<std::size_t>(maxPoints, 4) - 2) / 2;
  const std::size_t none = n;
  std::vector<std::size_t> minRow(buckets, none), maxRow(buckets, none);
  const double t0 = timeMin[0];
  const double scale = static_cast<double>(buckets) / (timeMin[n - 1] - t0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto b = std::min(buckets - 1, static_cast<std::size_t>(std::max(0.0, (timeMin[i] - t0) * scale)));
    if (minRow[b] == none || value[i] < value[minRow[b]]) {
      minRow[b] = i;
    }
    if (maxRow[b] == none || value[i] > value[maxRow[b]]) {
      maxRow[b] = i;
    }
  }
  rows.reserve(2 * buckets + 2);
  rows.push_back(0);
  for (std::size_t b = 0; b < buckets; ++b) {
    if (minRow[b] != none) {
      rows.push_back(std::min(minRow[b], maxRow[b]));
      rows.push_back(std::max(minRow[b], maxRow[b]));
    }
  }
  rows.push_back(n - 1);
  // Buckets are in time order and each bucket's rows are sorted, so a pass of unique suffices.
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

}  // namespace metrofit
