// metrofit-cli fit-element: a geometric element fitted to measured points (core/geometry/element_fit.h).
//   fit-element --data F.csv --element plane|line|circle|sphere|cylinder|cone [--radius R]
//               [--criterion ls|minimax] [--robust [--robust-k K]] [--unit mm|um|m|in] [--out J.json]
// Points: columns x_mm,y_mm,z_mm, or x,y,z in --unit (default mm); an optional `id` column names the
// points in `excluded` and in the certificate (else 1-based data rows). docs/file-formats.md#element-points.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/commands.h"
#include "core/common/error.h"
#include "core/common/numformat.h"
#include "core/geometry/element_fit.h"
#include "core/geometry/point_table.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"

namespace metrofit::cli {
namespace {

struct FitArgs {
  std::string data, element, criterion = "ls", unit, out;
  double radius = 0.0, robustK = geometry::ElementFitOptions{}.robustK;
  bool robust = false;
  CLI::Option* radiusOpt = nullptr;
};

double unitFactor(const std::string& unit) {
  if (unit == "mm") return 1.0;
  if (unit == "um") return 1e-3;
  if (unit == "m") return 1e3;
  if (unit == "in") return 25.4;
  throw OptionsError(ErrorContext{{}, 0, 0, "--unit"}, "must be mm, um, m or in, got '" + unit + "'");
}

struct Points {
  geometry::PointSet set;
  std::vector<std::string> names;  ///< id, or the 1-based data row
  bool hasIds = false;
};

Points readPoints(const FitArgs& a) {
  const CsvTable t = readCsvFile(a.data, csvOptions());
  const std::string source = displayPath(a.data);
  // The columns (x_mm.., px.. or x,y,z) and their reading: one owner, core/geometry/point_table.h.
  const geometry::PointTableColumns columns = geometry::pointTableColumns(t);
  double factor = 1.0;
  if (columns.bare) {
    factor = unitFactor(a.unit.empty() ? "mm" : a.unit);
  } else if (!a.unit.empty() && a.unit != "mm") {
    unitFactor(a.unit);  // a bad spelling is named first
    throw OptionsError(ErrorContext{{}, 0, 0, "--unit"}, "applies to columns x,y,z; " + source + " has " +
                                                             columns.x + "," + columns.y + "," + columns.z +
                                                             " (already in mm)");
  }
  Points p;
  p.set = geometry::pointsFromTable(t, factor);
  p.set.source = source;
  p.hasIds = !p.set.ids.empty();
  for (std::size_t r = 0; r < p.set.points.size(); ++r)
    p.names.push_back(p.hasIds ? p.set.ids[r] : std::to_string(r + 1));
  return p;
}

nlohmann::json vec(const Eigen::Vector3d& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

/// A point as `excluded` and the certificate name it: its id (string) or its 1-based data row (number).
nlohmann::json pointName(const Points& p, std::size_t i) {
  if (p.hasIds) return p.names[i];
  return static_cast<long>(i + 1);
}

nlohmann::json resultJson(const geometry::ElementFitResult& r, const Points& p, const FitArgs& a) {
  using geometry::ElementKind;
  const geometry::FittedElement& e = r.element;
  nlohmann::json j;
  j["element"] = geometry::toString(e.kind);
  j["criterion"] = geometry::toString(r.criterion);
  j["centre_mm"] = vec(e.centre);
  j["axis"] = e.kind == ElementKind::Sphere ? nlohmann::json(nullptr) : vec(e.axis);
  j["radius_mm"] = e.kind == ElementKind::Plane || e.kind == ElementKind::Line ? nlohmann::json(nullptr)
                                                                               : nlohmann::json(e.radiusMm);
  j["form_mm"] = r.formMm;
  j["rmse_mm"] = r.rmseMm;
  j["residuals_mm"] = r.residualsMm;
  nlohmann::json excluded = nlohmann::json::array();
  for (std::size_t i : r.excluded) excluded.push_back(pointName(p, i));
  j["excluded"] = excluded;
  j["condition"] = r.condition;
  // Extra keys.
  j["points"] = p.set.points.size();
  j["fixed_radius"] = r.fixedRadius;
  j["max_abs_mm"] = r.maxAbsMm;
  if (e.kind == ElementKind::Cone) {
    j["half_angle_deg"] = e.halfAngleRad * 180.0 / 3.14159265358979323846;
    j["apex_mm"] = vec(e.apex);
  }
  j["well_conditioned"] = r.wellConditioned;
  j["noise_amplification"] = r.noiseAmplification;
  if (e.kind != ElementKind::Plane && e.kind != ElementKind::Line) j["coverage_deg"] = r.coverageDeg;
  nlohmann::json se = nlohmann::json::object();
  for (const auto& s : r.standardErrors) se[s.name] = s.value;
  j["standard_errors"] = se;
  j["standard_errors_of"] = "least squares";
  if (a.robust) {
    j["robust"] = {{"rule",
                    "least trimmed squares start, then |d - median| > max(k * 1.4826 * MAD, 0.001 mm) "
                    "excluded, iterated"},
                   {"k", a.robustK},
                   {"threshold_mm", r.robustThresholdMm}};
  }
  if (r.certificate) {
    const geometry::MinimaxCertificate& c = *r.certificate;
    nlohmann::json contacts = nlohmann::json::array();
    for (const auto& k : c.contacts)
      contacts.push_back({{"point", pointName(p, k.index)},
                          {"side", k.side > 0 ? "outer" : "inner"},
                          {"multiplier", k.multiplier},
                          {"residual_mm", r.residualsMm[k.index]}});
    j["certificate"] = {{"holds", c.holds},
                        {"contacts", contacts},
                        {"max_abs_mm", c.maxAbsMm},
                        {"lp_optimum_mm", c.lpOptimumMm},
                        {"predicted_decrease_mm", c.predictedDecreaseMm},
                        {"multiplier_sum", c.multiplierSum},
                        {"stationarity", c.stationarity},
                        {"meaning", c.meaning}};
    j["lp_solves"] = r.lpSolves;
  }
  j["termination"] = toString(r.run.termination);
  j["message"] = r.run.message;
  return j;
}

int runFit(const FitArgs& a) {
  geometry::ElementFitOptions o;
  if (!geometry::parseElementKind(a.element, &o.element))
    throw OptionsError(ErrorContext{{}, 0, 0, "--element"},
                       "must be plane, line, circle, sphere, cylinder or cone, got '" + a.element + "'");
  if (!geometry::parseFitCriterion(a.criterion, &o.criterion))
    throw OptionsError(ErrorContext{{}, 0, 0, "--criterion"},
                       "must be ls or minimax, got '" + a.criterion + "'");
  if (a.radiusOpt->count() > 0) {
    if (!geometry::takesFixedRadius(o.element))
      throw OptionsError(ErrorContext{{}, 0, 0, "--radius"},
                         "applies to a sphere, circle or cylinder, not a " + a.element);
    o.fixedRadiusMm = a.radius;
  }
  o.robust = a.robust;
  o.robustK = a.robustK;
  requireValid(o, "fit-element options");
  const Points p = readPoints(a);
  geometry::ElementFitResult r;
  {
    TerminalProgress progress([](const IterationSummary& s) {
      return "fit-element: iteration " + std::to_string(s.iteration + 1) + ", " + num::general(s.best, 4);
    });
    r = geometry::fitElement(p.set, o, progress.observer());
  }
  writeResult(a.out, dumpJson(resultJson(r, p, a)));
  std::string line = "fit-element: " + a.element + " (" + a.criterion + ") of " +
                     std::to_string(p.set.points.size() - r.excluded.size()) + " points";
  if (!r.excluded.empty()) line += " (" + std::to_string(r.excluded.size()) + " excluded)";
  if (r.element.kind != geometry::ElementKind::Plane && r.element.kind != geometry::ElementKind::Line)
    line += ", radius " + num::fixed(r.element.radiusMm, 4) + " mm";
  line += ", form " + num::fixed(r.formMm, 4) + " mm, rmse " + num::fixed(r.rmseMm, 4) + " mm";
  if (r.certificate) line += r.certificate->holds ? ", zone certified" : ", zone NOT certified";
  line += "; " + r.condition;
  std::fprintf(stderr, "%s\n", line.c_str());
  return r.run.termination == Termination::Failed ? 1 : 0;
}

}  // namespace

void registerFitElementCommand(CLI::App& app) {
  auto a = std::make_shared<FitArgs>();
  auto* sub = app.add_subcommand(
      "fit-element",
      "Fit a plane, line, circle, sphere, cylinder or cone to measured points (LS or minimum zone)");
  existingFile(
      sub->add_option("--data", a->data, "Points (CSV): x_mm,y_mm,z_mm or x,y,z (see --unit), optional id")
          ->required());
  sub->add_option("--element", a->element, "plane | line | circle | sphere | cylinder | cone")->required();
  a->radiusOpt =
      sub->add_option("--radius", a->radius, "Fixed (calibrated) radius in mm: sphere, circle, cylinder")
          ->check(positiveNumber());
  sub->add_option("--criterion", a->criterion,
                  "ls (orthogonal least squares) | minimax (minimum zone, ISO 1101, with a certificate)")
      ->capture_default_str();
  sub->add_flag("--robust", a->robust,
                "Exclude stray points: |d - median| > k * 1.4826 * MAD, iterated (listed in 'excluded')");
  sub->add_option("--robust-k", a->robustK, "The k of --robust")
      ->check(positiveNumber())
      ->capture_default_str();
  sub->add_option("--unit", a->unit, "Unit of columns x,y,z: mm | um | m | in [mm]");
  addCsvOptions(sub);
  addOut(sub, a->out);
  sub->callback([a] { selectRunner([a]() -> int { return runFit(*a); }); });
}

}  // namespace metrofit::cli
