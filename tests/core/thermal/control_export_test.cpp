// Thermal compensation exports (core/thermal/control_export.h), checked by running them: the ST
// function block through the interpreter of st_interpreter.h (REAL as IEEE single precision) over the
// real CAIVIAC log's held-out half against the model's own prediction (0.01 um), the vendor forms'
// formulas evaluated over the same run, the lag filter's step response against the continuous one,
// the csv table against the model at its grid points, and the refusals.
#include "core/thermal/control_export.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/thermal/thermal_data.h"
#include "core/thermal/thermal_log.h"
#include "st_interpreter.h"
#include "testsupport.h"

namespace metrofit::thermal {
namespace {

const std::vector<std::string> kInputs = {"t5_degC", "t9_degC", "spindle_rpm"};

ThermalSeries caiviacSeries() {
  const ThermalLog log =
      readThermalLog((test::sourceDir() / "resources/demo/data/thermal_caiviac.csv").string());
  return selectThermalSeries(log, "ch1_um", kInputs);
}

/// Rows [from, to) of a series, as a log of its own.
ThermalSeries rows(const ThermalSeries& s, std::size_t from, std::size_t to) {
  ThermalSeries out = s;
  auto cut = [&](std::vector<double>& v) { v = std::vector<double>(v.begin() + from, v.begin() + to); };
  cut(out.timeMin);
  if (out.hasTarget()) cut(out.target);
  for (auto& in : out.inputs) cut(in);
  return out;
}

/// Every `stride`-th row.
ThermalSeries decimate(const ThermalSeries& s, std::size_t stride) {
  ThermalSeries out = s;
  auto pick = [&](std::vector<double>& v) {
    std::vector<double> w;
    for (std::size_t k = 0; k < v.size(); k += stride) w.push_back(v[k]);
    v = w;
  };
  pick(out.timeMin);
  pick(out.target);
  for (auto& in : out.inputs) pick(in);
  return out;
}

ThermalModel fitOnFirstHalf(const ThermalSeries& all, ThermalModelKind kind) {
  ThermalFitOptions o;
  o.model = kind;
  o.mlp.maxEpochs = 40;
  o.mlp.keepTrace = false;
  return fitThermalModel({all.head(fitRowCount(all.rows(), 0.5))}, o).model;
}

/// The PLC's values after each call, by name (upper case), and the block's outputs.
struct BlockRun {
  std::vector<double> error, comp;
  std::vector<std::map<std::string, double>> state;
};

/// Runs the exported ST block over a log, one call per row, reset on the first.
BlockRun runBlock(const std::string& text, const ThermalModel& m, const ThermalSeries& s,
                  bool keepState = false) {
  test::st::Block fb(text);
  const std::vector<std::string> names = stInputNames(m);
  BlockRun r;
  for (std::size_t k = 0; k < s.rows(); ++k) {
    for (std::size_t j = 0; j < names.size(); ++j) fb.set(names[j], s.inputs[j][k]);
    fb.set("dt_s", k == 0 ? 0.0 : (s.timeMin[k] - s.timeMin[k - 1]) * 60.0);
    fb.set("reset", k == 0 ? 1.0 : 0.0);
    fb.run();
    r.error.push_back(fb.get("error_um"));
    r.comp.push_back(fb.get("comp_um"));
    if (keepState) {
      std::map<std::string, double> v;
      for (const auto& [name, value] : fb.variables()) v[name] = value.v;
      r.state.push_back(std::move(v));
    }
  }
  return r;
}

ControlExportOptions withLimit(double limitUm) {
  ControlExportOptions o;
  o.limitUm = limitUm;
  return o;
}

double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

TEST(ControlExport, StBlockReproducesLinearLagAndDlagOnTheRealHeldOutHalf) {
  const ThermalSeries all = caiviacSeries();
  const std::size_t n = fitRowCount(all.rows(), 0.5);
  const ThermalSeries heldout = rows(all, n, all.rows());
  for (ThermalModelKind kind :
       {ThermalModelKind::Linear, ThermalModelKind::Lag, ThermalModelKind::DistributedLag}) {
    SCOPED_TRACE(toString(kind));
    const ThermalModel m = fitOnFirstHalf(all, kind);
    if (kind != ThermalModelKind::Linear) {
      bool lagged = false;
      for (const LagTerm& t : m.regression.terms) lagged = lagged || t.tauMin > 0.0;
      ASSERT_TRUE(lagged) << "the fit chose no lag: the test would not exercise the filters";
    }
    const std::string st = exportControl(m, ControlFormat::St, {});
    // The held-out half as the control sees it: reset at its first row, then one call per sample.
    const BlockRun fb = runBlock(st, m, heldout);
    const std::vector<double> model = predictChange(m, heldout);
    EXPECT_LT(maxAbsDiff(fb.error, model), 0.01);
    std::printf("[ measured ] %s: ST block vs the model on the held-out half: max |diff| %.2g um\n",
                toString(kind), maxAbsDiff(fb.error, model));
    for (std::size_t k = 0; k < fb.comp.size(); ++k)
      ASSERT_EQ(fb.comp[k], -fb.error[k]) << k;  // within +-100
    // The whole log from its first row: the prediction fitAndEvaluate reports for the held-out rows.
    const BlockRun whole = runBlock(st, m, all);
    EXPECT_LT(maxAbsDiff(whole.error, predictChange(m, all)), 0.01);
  }
}

/// The first line of `text` that starts with `start` (after `prefix`), from `start` on, up to "   ["
/// (the unit).
std::string formulaLine(const std::string& text, const std::string& prefix, const std::string& start) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(prefix + start, 0) != 0) continue;
    const auto at = prefix.size();
    std::string f = line.substr(at + start.size());
    if (const auto u = f.find("   ["); u != std::string::npos) f.resize(u);
    return f;
  }
  ADD_FAILURE() << "no line with '" << start << "' in\n" << text;
  return "0";
}

TEST(ControlExport, VendorFormulasReproduceTheModelOverTheRealLog) {
  // The PLC's formula of the siemens and isg forms and the TEMPCOMP formula of the heidenhain form,
  // evaluated with the sensors, their references and their filtered values of each sample (taken
  // from the ST block's run: the PLC's part), give the model's prediction.
  const ThermalSeries all = caiviacSeries();
  const ThermalSeries heldout = rows(all, fitRowCount(all.rows(), 0.5), all.rows());
  for (ThermalModelKind kind :
       {ThermalModelKind::Linear, ThermalModelKind::Lag, ThermalModelKind::DistributedLag}) {
    SCOPED_TRACE(toString(kind));
    const ThermalModel m = fitOnFirstHalf(all, kind);
    const BlockRun fb = runBlock(exportControl(m, ControlFormat::St, {}), m, heldout, true);
    const std::vector<double> model = predictChange(m, heldout);
    const std::string siemens = exportControl(m, ControlFormat::Siemens, {});
    const std::string isg = exportControl(m, ControlFormat::Isg, {});
    const std::string heidenhain = exportControl(m, ControlFormat::Heidenhain, {});
    EXPECT_NE(siemens.find("\n$MA_TEMP_COMP_TYPE[Z1]=1\n$SA_TEMP_COMP_SLOPE[Z1]=0\n"), std::string::npos);
    EXPECT_NE(siemens.find("SD43900 $SA_TEMP_COMP_ABS_VALUE[Z1] := e"), std::string::npos);
    EXPECT_TRUE(siemens.ends_with("\nM17\n"));
    EXPECT_NE(isg.find("\nkopf.achs_nr 3\n"), std::string::npos);
    EXPECT_NE(isg.find("\nlr_param.temp_comp 1\nlr_param.temp_comp_position_0 0\n"), std::string::npos);
    EXPECT_NE(isg.find("\nlr_param.temp_comp_coefficient 0\n"), std::string::npos);
    const std::string eMm = formulaLine(siemens, ";   ", "e := "), eUm = formulaLine(isg, "#   ", "e := ");
    const std::string tempcomp = formulaLine(heidenhain, "", "TEMPCOMP = ");
    const std::vector<std::string> names = stInputNames(m);
    double worst = 0.0;
    for (std::size_t k = 0; k < model.size(); ++k) {
      const auto& s = fb.state[k];
      std::map<std::string, double> plc, words;
      int filter = 0;
      for (std::size_t j = 0; j < names.size(); ++j) {
        const std::string x = test::st::upper(names[j]), ref = "REF_" + x;
        plc[x] = s.at(x);
        plc[ref] = s.at(ref);
        words["W" + std::to_string(1000 + 2 * j)] = s.at(x);
        words["W" + std::to_string(1100 + 2 * j)] = s.at(ref);
      }
      for (const LagTerm& t : m.regression.terms) {
        if (!(t.tauMin > 0.0)) continue;
        const std::string x = test::st::upper(names[t.input]);
        const double filtered = s.at("LAG_" + x) + s.at("REF_" + x);  // the block holds L[x] - r
        plc["LAG_" + x] = filtered;
        words["W" + std::to_string(1200 + 2 * filter++)] = filtered;
      }
      worst = std::max(worst, std::abs(test::st::evaluateFormula(eMm, plc) * 1000.0 - model[k]));
      worst = std::max(worst, std::abs(test::st::evaluateFormula(eUm, plc) - model[k]));
      worst = std::max(worst, std::abs(test::st::evaluateFormula(tempcomp, words) * 1000.0 - model[k]));
    }
    EXPECT_LT(worst, 0.01);
  }
}

TEST(ControlExport, StBlockReproducesAnMlp) {
  // A network trained briefly on the real log (every 8th row, 40 epochs): the block's mapminmax,
  // logistic layer and output in REAL give the network's prediction on the held-out rows.
  const ThermalSeries all = decimate(caiviacSeries(), 8);
  const ThermalModel m = fitOnFirstHalf(all, ThermalModelKind::Mlp);
  const ThermalSeries heldout = rows(all, fitRowCount(all.rows(), 0.5), all.rows());
  const std::string st = exportControl(m, ControlFormat::St, withLimit(1000.0));
  EXPECT_LT(maxAbsDiff(runBlock(st, m, heldout).error, predictChange(m, heldout)), 0.01);
  EXPECT_LT(maxAbsDiff(runBlock(st, m, all).error, predictChange(m, all)), 0.01);
}

ThermalModel oneLag(double tauMin) {
  ThermalModel m;
  m.kind = ThermalModelKind::Lag;
  m.target = "d_um";
  m.inputs = {"T1_degC"};
  m.timeUnitMin = 0.25;
  m.regression.terms = {{0, tauMin}};
  m.regression.coef = {1.0};
  m.regression.intercept = 0.0;
  return m;
}

TEST(ControlExport, LagStepResponseIsTheContinuousOneAtEverySample) {
  // Exact zero-order hold, a = exp(-dt / tau), with the input held at its new value over the step: a
  // unit step applied just after the reference sample gives 1 - exp(-t / tau) at every sample t, for
  // any spacing. Checked through the ST block (REAL) and the model's own filter (double).
  const double tauMin = 30.0;
  const ThermalModel m = oneLag(tauMin);
  const std::string st = exportControl(m, ControlFormat::St, {});
  EXPECT_NE(st.find("(1.0 - EXP(-dt_s / 1800.0))"), std::string::npos) << st;
  ThermalSeries s;
  s.source = "step";
  s.timeColumn = "time_s";
  s.inputNames = m.inputs;
  s.inputs.resize(1);
  const double steps[] = {15.0, 40.0, 7.5, 600.0, 1.0};
  double t = 0.0;
  for (int k = 0; k < 400; ++k) {
    if (k > 0) t += steps[k % 5];
    s.timeMin.push_back(t / 60.0);
    s.inputs[0].push_back(k == 0 ? 20.0 : 21.0);  // 20 degC at the reference, then a step of 1 K
  }
  const BlockRun fb = runBlock(st, m, s);
  const std::vector<double> filter = firstOrderLagMin(s.inputs[0], s.timeMin, tauMin);
  double worstFb = 0.0, worstCore = 0.0;
  for (std::size_t k = 0; k < s.rows(); ++k) {
    const double exact = k == 0 ? 0.0 : 1.0 - std::exp(-(s.timeMin[k] - s.timeMin[0]) / tauMin);
    worstFb = std::max(worstFb, std::abs(fb.error[k] - exact));
    worstCore = std::max(worstCore, std::abs(filter[k] - 20.0 - exact));
  }
  EXPECT_LT(worstFb, 2e-6);     // single precision
  EXPECT_LT(worstCore, 1e-12);  // the model's filter
  EXPECT_GT(fb.error.back(), 0.999);
  // Forward Euler (a = dt / tau), the usual PLC shortcut, is not the continuous lag: it is off by more
  // than 1e-3 of the step here, which is why the exact form is exported.
  double euler = 0.0, worstEuler = 0.0;
  for (std::size_t k = 1; k < s.rows(); ++k) {
    const double dt = s.timeMin[k] - s.timeMin[k - 1];
    euler += std::min(1.0, dt / tauMin) * (1.0 - euler);
    worstEuler =
        std::max(worstEuler, std::abs(euler - (1.0 - std::exp(-(s.timeMin[k] - s.timeMin[0]) / tauMin))));
  }
  EXPECT_GT(worstEuler, 1e-3);
}

/// The rows of a csv export (comment lines skipped): header and numbers.
CsvTable csvOf(const std::string& text) {
  return parseCsv(text, "export.csv");
}

TEST(ControlExport, CsvTableIsTheModelsPredictionAtItsGridPoints) {
  const ThermalSeries all = caiviacSeries();
  for (ThermalModelKind kind : {ThermalModelKind::Linear, ThermalModelKind::Lag}) {
    SCOPED_TRACE(toString(kind));
    const ThermalModel m = fitOnFirstHalf(all, kind);
    ControlExportOptions o;
    o.grid.push_back({"spindle_rpm", 0.0, 3000.0, 1000.0});
    const std::string text = exportControl(m, ControlFormat::Csv, o);
    EXPECT_EQ(text.rfind("# Metrofit thermal compensation, form 'csv'", 0), 0u) << text.substr(0, 200);
    const CsvTable t = csvOf(text);
    ASSERT_EQ(t.rowCount(), 6u * 6u * 4u);
    ASSERT_EQ(t.columnCount(), 5u);
    EXPECT_EQ(t.header()[3], "error_um");
    EXPECT_EQ(t.header()[4], "compensation_um");
    for (std::size_t r = 0; r < t.rowCount(); ++r) {
      // The model on a log that holds the grid point from the reference (0) long enough for every lag
      // to settle: its prediction at the second row is the table's value.
      ThermalSeries s;
      s.timeMin = {0.0, 1e6};
      s.inputNames = m.inputs;
      for (std::size_t j = 0; j < 3; ++j) s.inputs.push_back({0.0, t.number(r, j)});
      const double e = predictChange(m, s)[1];
      ASSERT_NEAR(t.number(r, 3), e, 5.1e-7) << r;
      ASSERT_NEAR(t.number(r, 4), -e, 5.1e-7) << r;
    }
  }
}

TEST(ControlExport, MlpCsvOverItsTrainingRange) {
  const ThermalSeries all = decimate(caiviacSeries(), 8);
  const ThermalModel m = fitOnFirstHalf(all, ThermalModelKind::Mlp);
  const CsvTable t = csvOf(exportControl(m, ControlFormat::Csv, {}));
  ASSERT_EQ(t.rowCount(), 216u);
  EXPECT_DOUBLE_EQ(t.number(0, 0), m.mlp.inMin(0));
  EXPECT_DOUBLE_EQ(t.number(t.rowCount() - 1, 2), m.mlp.inMax(2));
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    const std::vector<double> x = {t.number(r, 0), t.number(r, 1), t.number(r, 2)};
    ASSERT_NEAR(t.number(r, 3), m.mlp.predict(x), 5.1e-7) << r;
  }
}

TEST(ControlExport, GreyModelsAndTheMlpInVendorFormsAreRefusedWithTheReason) {
  ThermalModel grey;
  grey.kind = ThermalModelKind::Gnnmci;
  grey.target = "d_um";
  grey.inputs = {"T1"};
  grey.grey = {0.2, {0.1}, 0.0};
  ControlExportOptions o;
  o.source = "models/g.json";
  for (ThermalModelKind kind : {ThermalModelKind::Gnnmci, ThermalModelKind::Gmc}) {
    grey.kind = kind;
    for (ControlFormat f : kAllControlFormats) {
      EXPECT_FALSE(controlExportRefusal(grey, f).empty());
      try {
        exportControl(grey, f, o);
        ADD_FAILURE() << toString(kind) << " as " << toString(f);
      } catch (const ValidationError& e) {
        const std::string w = e.what();
        EXPECT_EQ(w.rfind("models/g.json: field 'model': the " + std::string(toString(kind)) +
                              " model cannot be exported as " + toString(f) + ": ",
                          0),
                  0u)
            << w;
        EXPECT_NE(w.find("convolution"), std::string::npos) << w;
      }
    }
  }
  const ThermalModel mlp = fitOnFirstHalf(decimate(caiviacSeries(), 16), ThermalModelKind::Mlp);
  for (ControlFormat f : {ControlFormat::Siemens, ControlFormat::Heidenhain, ControlFormat::Isg}) {
    EXPECT_THROW(exportControl(mlp, f, o), ValidationError) << toString(f);
    EXPECT_NE(controlExportRefusal(mlp, f).find("nonlinear"), std::string::npos);
  }
  EXPECT_TRUE(controlExportRefusal(mlp, ControlFormat::St).empty());
  EXPECT_TRUE(controlExportRefusal(mlp, ControlFormat::Csv).empty());
  for (ControlFormat f : kAllControlFormats) EXPECT_TRUE(controlExportRefusal(oneLag(10.0), f).empty());
  // Options: a grid of something the model does not have, too many rows.
  ControlExportOptions g;
  g.grid.push_back({"T9", 0.0, 1.0, 0.5});
  EXPECT_THROW(exportControl(oneLag(10.0), ControlFormat::Csv, g), OptionsError);
  g.grid = {{"T1_degC", 0.0, 1.0, 1e-6}};
  EXPECT_THROW(exportControl(oneLag(10.0), ControlFormat::Csv, g), OptionsError);
  EXPECT_THROW(controlFormat("fanuc"), OptionsError);
}

TEST(ControlExport, InputNamesBecomeDistinctIecIdentifiers) {
  ThermalModel m;
  m.kind = ThermalModelKind::Linear;
  m.target = "disp z [um]";
  m.inputs = {
      "T1 [\xc2\xb0"
      "C]",
      "t1_C", "2nd sensor", "IF", "reset"};
  m.regression.terms = {{0, 0.0}, {1, 0.0}, {2, 0.0}, {3, 0.0}, {4, 0.0}};
  m.regression.coef = {1.0, 2.0, -3.0, 4.0, 0.5};
  m.regression.intercept = -0.25;
  EXPECT_EQ(stInputNames(m),
            (std::vector<std::string>{"T1_C", "t1_C_2", "in_2nd_sensor", "in_IF", "reset_2"}));
  const std::string st = exportControl(m, ControlFormat::St, {});
  test::st::Block fb(st);
  EXPECT_EQ(fb.name(), "FB_METROFIT_THERMAL_DISP_Z_UM");
  const std::vector<std::string> names = stInputNames(m);
  for (const auto& n : names) fb.set(n, 20.0);
  fb.set("reset", 1.0);
  fb.run();
  EXPECT_DOUBLE_EQ(fb.get("error_um"), -0.25);
  const double x[] = {21.0, 20.5, 19.0, 20.25, 24.0};
  for (std::size_t j = 0; j < names.size(); ++j) fb.set(names[j], x[j]);
  fb.set("reset", 0.0);
  fb.run();
  EXPECT_NEAR(fb.get("error_um"), -0.25 + 1.0 + 1.0 + 3.0 + 1.0 + 2.0, 1e-5);
  // The limit: comp_um is held at +-limit and `limited` says so.
  const std::string limited = exportControl(m, ControlFormat::St, withLimit(5.0));
  test::st::Block l(limited);
  for (const auto& n : names) l.set(n, 20.0);
  l.set("reset", 1.0);
  l.run();
  for (std::size_t j = 0; j < names.size(); ++j) l.set(names[j], x[j]);
  l.set("reset", 0.0);
  l.run();
  EXPECT_FLOAT_EQ(static_cast<float>(l.get("comp_um")), -5.0f);
  EXPECT_EQ(l.get("limited"), 1.0);
}

}  // namespace
}  // namespace metrofit::thermal
