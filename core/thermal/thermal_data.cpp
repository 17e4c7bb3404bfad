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
  s.timeMin = log.timeMin;
  s.targetName = target;
  if (requireTarget || log.indexOf(target) >= 0) s.target = finiteColumn(log, target);
  s.inputNames = inputs;
  for (const auto& in : inputs) s.inputs.push_back(finiteColumn(log, in));
  return s;
}

std::vector<double> change(const std::vector<double>& x) {
  std::vector<double> d(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) d[k] = x[k] - x[0];
  return d;
}

}  // namespace metrofit::thermal
