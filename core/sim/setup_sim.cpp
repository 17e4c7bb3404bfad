#include "core/sim/setup_sim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/numformat.h"
#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/io/csv.h"

namespace metrofit {
namespace {

/// Independent stream per (seed, index).
Rng streamFor(std::uint64_t seed, std::uint64_t index) {
  return Rng(seed ^ (0x9E3779B97F4A7C15ULL * (index + 1)));
}

double roundTo(double v, double resolution) {
  return resolution > 0.0 ? std::round(v / resolution) * resolution : v;
}

std::string number(double v, double resolution) {
  if (resolution <= 0.0) return CsvWriter::formatNumber(v);
  // Enough decimals for the resolution, no float noise.
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(resolution) - 1e-9)));
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // "-0.000"
  return s;
}

std::vector<double> drawSetupErrors(const setup::Model& model, double w1, Rng& rng) {
  std::vector<double> e(model.setup.size());
  for (double& v : e) v = w1 * (1.0 - 2.0 * rng.uniform());  // Eq. 12
  return e;
}

}  // namespace

bool SetupSimOptions::isValid(std::string* why) const {
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(w1 >= 0.0) || !std::isfinite(w1)) return no("w1 must be a finite number >= 0");
  if (!(w2 >= 0.0) || !std::isfinite(w2)) return no("w2 must be a finite number >= 0");
  if (parts < 1 || parts > 100000) return no("parts must be in 1..100000");
  if (!(minutesPerPart >= 0.0) || !std::isfinite(minutesPerPart)) return no("minutes per part must be >= 0");
  if (!(resolutionMm >= 0.0) || !std::isfinite(resolutionMm) || resolutionMm > 1.0)
    return no("the resolution must be in [0, 1] mm");
  return true;
}

SetupMeasurementSet simulateSetupSet(const setup::Model& model, const SetupSimOptions& options,
                                     std::size_t index) {
  requireValid(options, "setup simulation options");
  const Eigen::MatrixXd g = setup::gainMatrix(model);
  Rng rng = streamFor(options.seed, index);
  SetupMeasurementSet set;
  set.setupErrorMm = drawSetupErrors(model, options.w1, rng);
  const Eigen::VectorXd esd = Eigen::Map<const Eigen::VectorXd>(set.setupErrorMm.data(), g.cols());
  const Eigen::VectorXd shift = g * esd;
  set.deviationMm.resize(model.dimensions.size());
  for (std::size_t q = 0; q < set.deviationMm.size(); ++q)
    set.deviationMm[q] =
        shift(static_cast<Eigen::Index>(q)) + options.w2 * (1.0 - 2.0 * rng.uniform());  // Eq. 13
  return set;
}

std::vector<SetupMeasurementSet> simulateSetupSets(const setup::Model& model, const SetupSimOptions& options,
                                                   std::size_t count) {
  std::vector<SetupMeasurementSet> out;
  out.reserve(count);
  for (std::size_t j = 0; j < count; ++j) out.push_back(simulateSetupSet(model, options, j));
  return out;
}

std::string simulateSetupReport(const setup::Model& model, const SetupSimOptions& options,
                                std::vector<double>* setupErrorMm) {
  requireValid(options, "setup simulation options");
  const Eigen::MatrixXd g = setup::gainMatrix(model);
  Rng rng(options.seed);
  const std::vector<double> esd = drawSetupErrors(model, options.w1, rng);
  if (setupErrorMm) *setupErrorMm = esd;
  const Eigen::VectorXd shift = g * Eigen::Map<const Eigen::VectorXd>(esd.data(), g.cols());
  CsvWriter w;
  w.comment(" Simulated CMM report series (metrofit core/sim/setup_sim.h): model '" + model.name + "', " +
            std::to_string(options.parts) + " parts, w1 = " + CsvWriter::formatNumber(options.w1) +
            " mm, w2 = " + CsvWriter::formatNumber(options.w2) + " mm, seed " + std::to_string(options.seed));
  w.row({"part", "time_min", "dimension", "nominal_mm", "measured_mm", "lower_tol_mm", "upper_tol_mm"});
  const double res = options.resolutionMm;
  for (int p = 1; p <= options.parts; ++p) {
    for (std::size_t q = 0; q < model.dimensions.size(); ++q) {
      const setup::Dimension& d = model.dimensions[q];
      const double nominal = d.nominal.value_or(0.0);
      const double dev = shift(static_cast<Eigen::Index>(q)) + options.w2 * (1.0 - 2.0 * rng.uniform());
      const double measured = roundTo(nominal + dev, res);
      w.row({std::to_string(p), CsvWriter::formatNumber(p * options.minutesPerPart), d.id,
             CsvWriter::formatNumber(nominal), number(measured, res), CsvWriter::formatNumber(d.lower),
             CsvWriter::formatNumber(d.upper)});
    }
  }
  return w.text();
}

}  // namespace metrofit
