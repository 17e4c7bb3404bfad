#include "core/sim/effects_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/common/rng.h"
#include "core/common/run.h"
#include "core/io/csv.h"

namespace metrofit {
namespace {

std::string number(double v, double resolution) {
  if (resolution <= 0.0) return CsvWriter::formatNumber(v);
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(resolution) - 1e-9)));
  char buf[64];
  metrofit::c_snprintf(buf, sizeof buf, "%.*f", decimals, std::round(v / resolution) * resolution);
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // "-0.000"
  return s;
}

}  // namespace

bool SetupEffectsSimOptions::isValid(std::string* why) const {
  if (!base.isValid(why)) return false;
  auto no = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(timeJitter >= 0.0 && timeJitter < 1.0)) return no("the time jitter must be in [0, 1)");
  for (const auto& [id, rate] : toolWearMmPerPart)
    if (!std::isfinite(rate)) return no("tool wear rates must be finite");
  for (const auto& [id, rate] : driftMmPerMin)
    if (!std::isfinite(rate)) return no("drift rates must be finite");
  return true;
}

std::string simulateSetupEffectsReport(const setup::Model& model, const SetupEffectsSimOptions& options,
                                       SetupEffectsTruth* truth) {
  requireValid(options, "setup effects simulation options");
  const std::size_t nd = model.setup.size();
  // Per datum: wear rate (mm/part) and drift rate (mm/min).
  std::vector<double> wear(nd, 0.0), drift(nd, 0.0);
  for (const auto& [id, rate] : options.toolWearMmPerPart) {
    const int i = model.setupIndex(id);
    if (i < 0 || model.setup[static_cast<std::size_t>(i)].kind != setup::DatumKind::Tool)
      throw OptionsError(ErrorContext{{}, 0, 0, "tool_wear:" + id},
                         "'" + id + "' is not a tool of the model");
    wear[static_cast<std::size_t>(i)] += rate;
  }
  for (const auto& [id, rate] : options.driftMmPerMin) {
    const int i = model.setupIndex(id);
    if (i < 0)
      throw OptionsError(ErrorContext{{}, 0, 0, "drift:" + id},
                         "'" + id + "' is not a setup datum of the model");
    drift[static_cast<std::size_t>(i)] += rate;
  }

  // The composed series: setup_sim.h without rounding.
  SetupSimOptions base = options.base;
  base.resolutionMm = 0.0;
  std::vector<double> esd;
  const std::string plain = simulateSetupReport(model, base, &esd);
  const CsvTable table = parseCsv(plain, "simulated report");

  // Times of the parts (own stream, so the effects do not change the setup errors or the noise).
  Rng rng(options.base.seed ^ 0x5DEECE66DULL);
  std::vector<double> time(static_cast<std::size_t>(options.base.parts) + 1, 0.0);
  double t = 0.0;
  for (int p = 1; p <= options.base.parts; ++p) {
    t += options.base.minutesPerPart * (1.0 + options.timeJitter * (2.0 * rng.uniform() - 1.0));
    time[static_cast<std::size_t>(p)] = std::round(t * 100.0) / 100.0;
  }
  if (truth) {
    truth->setupErrorMm = esd;
    truth->timeMin.assign(time.begin() + 1, time.end());
  }

  const Eigen::MatrixXd G = setup::gainMatrix(model);
  const std::size_t cPart = table.requireColumn("part"), cTime = table.requireColumn("time_min"),
                    cDim = table.requireColumn("dimension"), cNom = table.requireColumn("nominal_mm"),
                    cMeas = table.requireColumn("measured_mm"), cLo = table.requireColumn("lower_tol_mm"),
                    cUp = table.requireColumn("upper_tol_mm");
  (void)cTime;
  CsvWriter w;
  std::string effects;
  for (const auto& [id, rate] : options.toolWearMmPerPart)
    effects += " tool_wear:" + id + " " + CsvWriter::formatNumber(rate) + " mm/part;";
  for (const auto& [id, rate] : options.driftMmPerMin)
    effects += " drift:" + id + " " + CsvWriter::formatNumber(rate) + " mm/min;";
  if (effects.empty()) effects = " none;";
  w.comment(
      " Simulated CMM report series with undeclared effects (metrofit core/sim/effects_setup.h): model '" +
      model.name + "', " + std::to_string(options.base.parts) + " parts, w1 = " +
      CsvWriter::formatNumber(options.base.w1) + " mm, w2 = " + CsvWriter::formatNumber(options.base.w2) +
      " mm, time jitter " + CsvWriter::formatNumber(options.timeJitter) + ", seed " +
      std::to_string(options.base.seed) + "; effects:" + effects);
  w.row({"part", "time_min", "dimension", "nominal_mm", "measured_mm", "lower_tol_mm", "upper_tol_mm"});
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    const auto p = static_cast<std::size_t>(table.number(r, cPart));
    const int q = model.dimensionIndex(table.cell(r, cDim));
    double measured = table.number(r, cMeas);
    for (std::size_t i = 0; i < nd; ++i) {
      const double delta = wear[i] * static_cast<double>(p - 1) + drift[i] * (time[p] - time[1]);
      measured += G(q, static_cast<Eigen::Index>(i)) * delta;
    }
    w.row({table.cell(r, cPart), CsvWriter::formatNumber(time[p]), table.cell(r, cDim), table.cell(r, cNom),
           number(measured, options.base.resolutionMm), table.cell(r, cLo), table.cell(r, cUp)});
  }
  return w.text();
}

}  // namespace metrofit
