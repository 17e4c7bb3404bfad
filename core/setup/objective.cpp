#include "core/setup/objective.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/setup/report.h"

namespace metrofit::setup {

SetupInstance::SetupInstance(const Model& model, std::vector<double> deviationMm)
    : gain_(gainMatrix(model)), deviation_(std::move(deviationMm)), step_(model.stepMm) {
  if (deviation_.size() != model.dimensions.size()) {
    throw ValidationError(ErrorContext{model.source, 0, 0, "dimensions"},
                          "got " + std::to_string(deviation_.size()) + " deviations for " +
                              std::to_string(model.dimensions.size()) + " dimensions");
  }
  for (std::size_t q = 0; q < deviation_.size(); ++q) {
    if (!std::isfinite(deviation_[q]))
      throw ValidationError(ErrorContext{model.source, 0, 0, model.dimensions[q].id},
                            "deviation is not finite");
  }
  for (std::size_t i = 0; i < model.setup.size(); ++i) {
    datumIds_.push_back(model.setup[i].id);
    datumKinds_.push_back(model.setup[i].kind);
    xLower_.push_back(model.lower(i));
    xUpper_.push_back(model.upper(i));
  }
  rows_.resize(model.dimensions.size());
  for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
    dimensionIds_.push_back(model.dimensions[q].id);
    lower_.push_back(model.dimensions[q].lower);
    upper_.push_back(model.dimensions[q].upper);
    for (std::size_t i = 0; i < model.setup.size(); ++i) {
      const double g = gain_(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(i));
      if (g != 0.0) rows_[q].emplace_back(i, g);
    }
  }
  rowStart_.push_back(0);
  for (const auto& row : rows_) {
    for (const auto& [i, g] : row) {
      rowIndex_.push_back(i);
      rowGain_.push_back(g);
    }
    rowStart_.push_back(rowIndex_.size());
  }
}

SetupInstance::SetupInstance(const Model& model, const Measurements& measurements)
    : SetupInstance(model, measurements.deviationMm) {}

long SetupInstance::gridPoints(std::size_t i) const {
  return static_cast<long>(std::floor((xUpper_[i] - xLower_[i]) / step_ + 1e-9));
}

std::vector<double> SetupInstance::deviationsAfter(std::span<const double> x) const {
  std::vector<double> out(deviation_);
  for (std::size_t q = 0; q < rows_.size(); ++q)
    for (const auto& [i, g] : rows_[q]) out[q] += g * x[i];
  return out;
}

std::vector<double> SetupInstance::budgets(std::span<const double> x) const {
  std::vector<double> e = deviationsAfter(x);
  for (std::size_t q = 0; q < e.size(); ++q) e[q] = std::min(upper_[q] - e[q], e[q] - lower_[q]);
  return e;
}

double SetupInstance::f1(std::span<const double> x) const {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t* index = rowIndex_.data();
  const double* gain = rowGain_.data();
  for (std::size_t q = 0, m = rows_.size(); q < m; ++q) {
    double e = deviation_[q];
    for (std::size_t k = rowStart_[q], end = rowStart_[q + 1]; k < end; ++k) e += gain[k] * x[index[k]];
    best = std::min(best, std::min(upper_[q] - e, e - lower_[q]));
  }
  return best;
}

SetupScore SetupInstance::score(std::span<const double> x) const {
  SetupScore s;
  s.f1 = f1(x);
  double sq = 0.0;
  for (const double v : x) sq += v * v;
  s.f2 = std::sqrt(sq);
  s.f = 10.0 * s.f1 - s.f2;
  return s;
}

double SetupInstance::f1Before() const {
  const std::vector<double> zero(variables(), 0.0);
  return f1(zero);
}

std::vector<double> SetupInstance::fromGrid(std::span<const long> k) const {
  std::vector<double> x(k.size());
  for (std::size_t i = 0; i < k.size(); ++i) x[i] = xLower_[i] + static_cast<double>(k[i]) * step_;
  return x;
}

double SetupProblem::evaluate(std::span<const double> x, std::span<double> components) const {
  const SetupScore s = instance_.score(x);
  if (components.size() >= 3) {
    components[0] = s.f1;
    components[1] = s.f2;
    components[2] = s.f;
  }
  return -s.f;
}

}  // namespace metrofit::setup
