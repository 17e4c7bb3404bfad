#include "core/thermal/thermal_data.h"

#include <cmath>
#include <stdexcept>

#include "core/common/error.h"

namespace metrofit::thermal {

ThermalSeries ThermalSeries::head(std::size_t n) const {
  if (n > rows()) throw std::invalid_argument("ThermalSeries::head: more rows than the series has");
  ThermalSeries s = *this;
  s.timeMin.resize(n);
  if (!s.target.empty()) s.target.resize(n);
  for (auto& in : s.inputs) in.resize(n);
  return s;
}

namespace {

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::vector<double> finiteColumn(const ThermalLog& log, const std::string& name) {
  const ThermalChannel& c = log.channel(name);
  for (std::size_t r = 0; r < c.values.size(); ++r) {
    if (!std::isfinite(c.values[r])) {
      throw ValidationError(ErrorContext{log.source, 0, 0, name},
                            "row " + std::to_string(r + 1) + " is not a finite number");
    }
  }
  return c.values;
}

}  // namespace

ThermalSeries selectThermalSeries(const ThermalLog& log, const std::string& target,
                                  const std::vector<std::string>& inputs, bool requireTarget) {
  ThermalSeries s;
  s.source = log.source;
  s.timeColumn = log.timeColumn.empty() ? "time_min" : log.timeColumn;
  if (inputs.empty())
    throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "needs at least one column name");
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i] == target)
      throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "'" + inputs[i] + "' is also the --target");
    for (std::size_t j = 0; j < i; ++j) {
      if (inputs[j] == inputs[i])
        throw ValidationError(ErrorContext{{}, 0, 0, "--inputs"}, "'" + inputs[i] + "' is named twice");
    }
  }
  if (log.rows() < 2) {
    throw ValidationError(ErrorContext{log.source, 0, 0, {}},
                          "has " + std::to_string(log.rows()) + " rows; a thermal model needs at least 2");
  }
  for (std::size_t r = 0; r < log.rows(); ++r) {
    if (!std::isfinite(log.timeMin[r]) || (r > 0 && !(log.timeMin[r] > log.timeMin[r - 1]))) {
      throw ValidationError(ErrorContext{log.source, 0, 0, s.timeColumn},
                            "row " + std::to_string(r + 1) + ": time must be finite and strictly increasing");
    }
  }
  s.targetName = target;
  s.inputNames = inputs;
  if (log.gaps) {
    // Rows with a gap in a used column are left out (and counted); every other value must be finite.
    std::vector<std::string> used = inputs;
    if (requireTarget || log.indexOf(target) >= 0) used.insert(used.begin(), target);
    std::size_t leftOut = 0;
    const ThermalLog kept = thermalLogWithoutGaps(log, used, &leftOut);
    if (kept.rows() < 2)
      throw ValidationError(ErrorContext{log.source, 0, 0, {}},
                            std::to_string(leftOut) + " of its " + std::to_string(log.rows()) +
                                " rows have no value in a used column (" + joinNames(used) +
                                "); a thermal model needs at least 2 rows with values in all of them");
    s.timeMin = kept.timeMin;
    if (requireTarget || log.indexOf(target) >= 0) s.target = finiteColumn(kept, target);
    for (const auto& in : inputs) s.inputs.push_back(finiteColumn(kept, in));
    s.rowsWithGapsLeftOut = leftOut;
    return s;
  }
  s.timeMin = log.timeMin;
  if (requireTarget || log.indexOf(target) >= 0) s.target = finiteColumn(log, target);
  for (const auto& in : inputs) s.inputs.push_back(finiteColumn(log, in));
  return s;
}

ThermalLog thermalLogWithoutGaps(const ThermalLog& log, const std::vector<std::string>& used,
                                 std::size_t* leftOut) {
  if (leftOut) *leftOut = 0;
  if (!log.gaps) return log;
  std::vector<std::size_t> usedIndex;
  for (const auto& name : used)
    if (const int i = log.indexOf(name); i >= 0) usedIndex.push_back(static_cast<std::size_t>(i));
  std::vector<std::size_t> keep;
  for (std::size_t r = 0; r < log.rows(); ++r) {
    bool gap = false;
    for (std::size_t c : usedIndex) gap = gap || std::isnan(log.channels[c].values[r]);
    if (!gap) keep.push_back(r);
  }
  ThermalLog out;
  out.source = log.source;
  out.timeColumn = log.timeColumn;
  out.sampleIntervalMin = 0.0;  // rows may be missing: the time column says when each row is
  out.resampling = log.resampling;
  for (std::size_t r : keep) out.timeMin.push_back(log.timeMin[r]);
  for (const ThermalChannel& c : log.channels) {
    ThermalChannel k{c.name, c.unit, {}};
    bool complete = true;
    for (std::size_t r : keep) {
      complete = complete && !std::isnan(c.values[r]);
      k.values.push_back(c.values[r]);
    }
    if (complete) out.channels.push_back(std::move(k));
  }
  if (leftOut) *leftOut = log.rows() - keep.size();
  return out;
}

std::vector<double> change(const std::vector<double>& x) {
  std::vector<double> d(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) d[k] = x[k] - x[0];
  return d;
}

}  // namespace metrofit::thermal
