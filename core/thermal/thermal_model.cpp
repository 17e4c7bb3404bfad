#include "core/thermal/thermal_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/csv.h"
#include "core/io/file_io.h"
#include "core/io/json_util.h"

namespace metrofit::thermal {

const char* toString(ThermalModelKind kind) {
  switch (kind) {
    case ThermalModelKind::Gnnmci:
      return "gnnmci";
    case ThermalModelKind::Gmc:
      return "gmc";
    case ThermalModelKind::Mlp:
      return "mlp";
    case ThermalModelKind::Linear:
      return "linear";
    case ThermalModelKind::Lag:
      return "lag";
    case ThermalModelKind::DistributedLag:
      return "dlag";
  }
  return "?";
}

bool isGrey(ThermalModelKind kind) {
  return kind == ThermalModelKind::Gnnmci || kind == ThermalModelKind::Gmc;
}

bool isRegression(ThermalModelKind kind) {
  return kind == ThermalModelKind::Linear || kind == ThermalModelKind::Lag ||
         kind == ThermalModelKind::DistributedLag;
}

ThermalModelKind thermalModelKind(const std::string& name, const std::string& field) {
  for (auto k : kAllThermalModelKinds) {
    if (name == toString(k)) return k;
  }
  throw OptionsError(ErrorContext{{}, 0, 0, field},
                     "'" + name + "' is not a thermal model (gnnmci, gmc, mlp, linear, lag or dlag)");
}

bool ThermalFitOptions::isValid(std::string* why) const {
  std::string w;
  if (!gnnmci.isValid(&w)) {
    if (why) *why = "GNNMCI: " + w;
    return false;
  }
  if (!mlp.isValid(&w)) {
    if (why) *why = "MLP: " + w;
    return false;
  }
  return true;
}

double defaultTrainFraction(ThermalModelKind kind) {
  return kind == ThermalModelKind::Mlp ? 0.7 : kDefaultTrainFraction;
}

std::size_t fitRowCount(std::size_t rows, double trainFraction) {
  const auto n = static_cast<std::size_t>(std::llround(trainFraction * static_cast<double>(rows)));
  return std::clamp<std::size_t>(n, 1, rows);
}

namespace {

std::string sourcesOf(const std::vector<ThermalSeries>& segments) {
  std::string s;
  for (const auto& seg : segments) {
    if (s.find(seg.source) != std::string::npos) continue;
    s += (s.empty() ? "" : ", ") + seg.source;
  }
  return s;
}

/// Model-specific checks of the fitting data (see thermal_model.h).
void validateFitData(const std::vector<ThermalSeries>& segments, const ThermalFitOptions& o) {
  if (segments.empty()) throw std::invalid_argument("fitThermalModel: no data");
  const ThermalSeries& first = segments.front();
  const std::string source = sourcesOf(segments);
  std::size_t rows = 0, equations = 0, minSegment = std::numeric_limits<std::size_t>::max();
  for (const auto& s : segments) {
    if (!s.hasTarget()) {
      throw ValidationError(ErrorContext{s.source, 0, 0, s.targetName},
                            "the log has no target column to fit");
    }
    if (s.inputNames != first.inputNames || s.targetName != first.targetName)
      throw std::invalid_argument("fitThermalModel: segments differ in their columns");
    rows += s.rows();
    equations += s.rows() - 1;
    minSegment = std::min(minSegment, s.rows());
  }
  auto constant = [&](auto values) {
    for (const auto& s : segments) {
      const std::vector<double>& v = values(s);
      for (double x : v) {
        if (x != v.front()) return false;
      }
    }
    return true;
  };
  if (constant([](const ThermalSeries& s) -> const std::vector<double>& { return s.target; })) {
    throw ValidationError(ErrorContext{source, 0, 0, first.targetName},
                          "the target is constant on all " + std::to_string(rows) +
                              " fitting rows; there is no thermal error to model");
  }
  for (std::size_t j = 0; j < first.inputNames.size(); ++j) {
    if (constant([j](const ThermalSeries& s) -> const std::vector<double>& { return s.inputs[j]; })) {
      throw ValidationError(ErrorContext{source, 0, 0, first.inputNames[j]},
                            "input is constant (" + CsvWriter::formatNumber(first.inputs[j].front(), 6) +
                                ") on all " + std::to_string(rows) +
                                " fitting rows; a model cannot learn from it (drop it from --inputs)");
    }
  }
  const std::size_t m = first.inputNames.size();
  const std::string inputsText = std::to_string(m) + (m == 1 ? " input" : " inputs");
  switch (o.model) {
    case ThermalModelKind::Gmc:
      if (equations < m + 2) {
        throw ValidationError(ErrorContext{source, 0, 0, {}},
                              std::to_string(rows) + " fitting rows are too few: GMC(1,N) with " +
                                  inputsText + " has " + std::to_string(m + 2) +
                                  " parameters and needs at least " +
                                  std::to_string(m + 2 + segments.size()) +
                                  " rows (use more rows or a larger --train-fraction)");
      }
      break;
    case ThermalModelKind::Gnnmci:
      if (minSegment < 3) {
        throw ValidationError(
            ErrorContext{source, 0, 0, {}},
            std::to_string(minSegment) +
                " fitting rows are too few: GNNMCI(1,N) needs at least 3 per log (the first "
                "row is the initial condition)");
      }
      break;
    case ThermalModelKind::Mlp: {
      const std::size_t p = Mlp::parameterCount(m, static_cast<std::size_t>(o.mlp.hidden));
      if (rows <= p) {
        throw ValidationError(ErrorContext{source, 0, 0, {}},
                              std::to_string(rows) + " fitting rows are too few: the MLP with " + inputsText +
                                  " and " + std::to_string(o.mlp.hidden) + " hidden neurons has " +
                                  std::to_string(p) + " weights and needs at least " + std::to_string(p + 1) +
                                  " rows (use more rows, a larger --train-fraction or fewer inputs)");
      }
      break;
    }
    case ThermalModelKind::Linear:
    case ThermalModelKind::Lag:
    case ThermalModelKind::DistributedLag: {
      const std::size_t p = (o.model == ThermalModelKind::DistributedLag ? 2 * m : m) + 1;
      if (rows < kCvFolds * (p + 1)) {
        throw ValidationError(ErrorContext{source, 0, 0, {}},
                              std::to_string(rows) + " fitting rows are too few: the " + toString(o.model) +
                                  " model with " + inputsText + " has " + std::to_string(p) +
                                  " coefficients and its cross-validation needs at least " +
                                  std::to_string(kCvFolds * (p + 1)) + " rows");
      }
      break;
    }
  }
}

LagData lagData(const ThermalSeries& s) {
  LagData d;
  d.timeMin = s.timeMin;
  for (const auto& in : s.inputs) d.inputs.emplace_back(in);
  d.target = s.target;
  return d;
}

GreySeries greySeries(const ThermalSeries& s, double unitMin) {
  GreySeries g;
  g.time = greyTime(s.timeMin, unitMin);
  if (s.hasTarget()) g.target = change(s.target);
  for (const auto& in : s.inputs) g.inputs.push_back(change(in));
  return g;
}

double sumOfSquares(const std::vector<double>& measured, const std::vector<double>& predicted) {
  double f = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k)
    f += (measured[k] - predicted[k]) * (measured[k] - predicted[k]);
  return f;
}

}  // namespace

ThermalTraining fitThermalModel(const std::vector<ThermalSeries>& segments, const ThermalFitOptions& o,
                                Observer* observer) {
  requireValid(o, "thermal model options");
  validateFitData(segments, o);
  ThermalTraining t;
  ThermalModel& model = t.model;
  model.kind = o.model;
  model.target = segments.front().targetName;
  model.inputs = segments.front().inputNames;
  double duration = 0.0, steps = 0.0;
  for (const auto& s : segments) {
    t.fitRows += s.rows();
    duration += s.timeMin.back() - s.timeMin.front();
    steps += static_cast<double>(s.rows() - 1);
  }
  model.timeUnitMin = duration / steps;
  if (isRegression(o.model)) {
    std::vector<LagData> logs;
    for (const auto& s : segments) logs.push_back(lagData(s));
    const LagForm form = o.model == ThermalModelKind::Linear ? LagForm::Static
                         : o.model == ThermalModelKind::Lag  ? LagForm::Lag
                                                             : LagForm::DistributedLag;
    model.regression = fitLagModel(form, model.inputs.size(), logs, &t.cvRmse);
    t.run.termination = Termination::Converged;
    t.run.message = form == LagForm::Static ? "least squares (QR)"
                                            : "least squares (QR), taus by blocked cross-validation";
  } else if (o.model == ThermalModelKind::Mlp) {
    std::size_t rows = 0;
    for (const auto& s : segments) rows += s.rows();
    const std::size_t m = model.inputs.size();
    Eigen::MatrixXd x(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(m));
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
    Eigen::Index r = 0;
    for (const auto& s : segments) {
      for (std::size_t k = 0; k < s.rows(); ++k, ++r) {
        for (std::size_t j = 0; j < m; ++j)
          x(r, static_cast<Eigen::Index>(j)) = s.inputs[j][k] - s.inputs[j][0];
        y(r) = s.target[k] - s.target[0];
      }
    }
    MlpTraining mt = trainMlp(x, y, o.mlp, observer);
    model.mlp = std::move(mt.net);
    t.run = std::move(mt.run);
  } else {
    std::vector<GreySeries> grey;
    for (const auto& s : segments) grey.push_back(greySeries(s, model.timeUnitMin));
    if (o.model == ThermalModelKind::Gmc) {
      model.grey = fitGmcLeastSquares(grey);
      t.run.termination = Termination::Converged;
      t.run.message = "least squares (QR)";
    } else {
      GnnmciTraining g = trainGnnmci(grey, o.gnnmci, observer);
      model.grey = g.weights.toGmc();
      t.run = std::move(g.run);
      t.firstFitness = g.firstFitness;
    }
  }
  t.fitness = 0.0;
  for (const auto& s : segments) t.fitness += sumOfSquares(change(s.target), predictChange(model, s));
  if (o.model != ThermalModelKind::Gnnmci) t.firstFitness = t.fitness;
  return t;
}

std::vector<double> predictChange(const ThermalModel& model, const ThermalSeries& s) {
  if (s.inputs.size() != model.inputs.size())
    throw std::invalid_argument("predictChange: the series does not have the model's inputs");
  std::vector<double> out;
  if (isRegression(model.kind)) {
    LagData d = lagData(s);
    d.target = {};
    return predictLag(model.regression, d);
  }
  if (model.kind == ThermalModelKind::Mlp) {
    out.resize(s.rows());
    std::vector<double> x(model.inputs.size());
    for (std::size_t k = 0; k < s.rows(); ++k) {
      for (std::size_t j = 0; j < x.size(); ++j) x[j] = s.inputs[j][k] - s.inputs[j][0];
      out[k] = model.mlp.predict(x);
    }
    return out;
  }
  GreySeries g = greySeries(s, model.timeUnitMin);
  g.target.clear();  // the initial condition is the change at the first row: 0
  return model.kind == ThermalModelKind::Gmc ? gmcPredict(model.grey, g)
                                             : gnnmciPredict(GnnmciWeights::fromGmc(model.grey), g);
}

std::vector<double> predictTarget(const ThermalModel& model, const ThermalSeries& s) {
  std::vector<double> out = predictChange(model, s);
  const double y0 = s.hasTarget() ? s.target.front() : 0.0;
  for (double& v : out) v += y0;
  return out;
}

ThermalEvaluation fitAndEvaluate(const ThermalSeries& series, double trainFraction,
                                 const ThermalFitOptions& o, Observer* observer) {
  if (!(trainFraction > 0.0 && trainFraction < 1.0)) {
    throw OptionsError(ErrorContext{{}, 0, 0, "--train-fraction"},
                       CsvWriter::formatNumber(trainFraction) + " is not in (0, 1)");
  }
  if (!series.hasTarget())
    throw ValidationError(ErrorContext{series.source, 0, 0, series.targetName},
                          "the log has no target column");
  ThermalEvaluation ev;
  ev.trainFraction = trainFraction;
  ev.fitRows = fitRowCount(series.rows(), trainFraction);
  ev.heldoutRows = series.rows() - ev.fitRows;
  if (ev.heldoutRows < 2) {
    throw ValidationError(ErrorContext{series.source, 0, 0, "--train-fraction"},
                          "with " + std::to_string(series.rows()) + " rows, train fraction " +
                              CsvWriter::formatNumber(trainFraction) + " holds out " +
                              std::to_string(ev.heldoutRows) + (ev.heldoutRows == 1 ? " row" : " rows") +
                              "; at least 2 are needed");
  }
  ev.training = fitThermalModel({series.head(ev.fitRows)}, o, observer);
  ev.predicted = predictTarget(ev.training.model, series);
  const std::span<const double> y(series.target), p(ev.predicted);
  ev.fit = thermalMetrics(y.first(ev.fitRows), p.first(ev.fitRows));
  ev.heldout = thermalMetrics(y.subspan(ev.fitRows), p.subspan(ev.fitRows));
  return ev;
}

bool ThermalEvaluation::heldoutFails() const {
  if (!std::isfinite(heldout.rmse)) return true;
  if (heldout.e < 0.0) return true;
  return isGrey(training.model.kind) && !(training.model.grey.b1 > 0.0);
}

namespace {

ThermalSeries sliceRows(const ThermalSeries& s, std::size_t begin, std::size_t end) {
  ThermalSeries out = s;
  auto cut = [&](std::vector<double>& v) {
    if (v.empty()) return;
    v = std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(begin),
                            v.begin() + static_cast<std::ptrdiff_t>(end));
  };
  cut(out.timeMin);
  cut(out.target);
  for (auto& in : out.inputs) cut(in);
  return out;
}

/// Blocked CV of GMC(1,N) on the first n rows (see ThermalSelection).
double greyCvRmse(const ThermalSeries& head, const ThermalFitOptions& o) {
  const std::size_t n = head.rows();
  const std::vector<double> y = change(head.target);
  double sse = 0.0;
  for (int f = 0; f < kCvFolds; ++f) {
    const std::size_t b = n * static_cast<std::size_t>(f) / kCvFolds;
    const std::size_t e = n * static_cast<std::size_t>(f + 1) / kCvFolds;
    std::vector<ThermalSeries> segments;
    if (b >= head.inputs.size() + 4) segments.push_back(sliceRows(head, 0, b));
    if (n - e >= head.inputs.size() + 4) segments.push_back(sliceRows(head, e, n));
    if (segments.empty()) return std::numeric_limits<double>::infinity();
    try {
      ThermalFitOptions go = o;
      go.model = ThermalModelKind::Gmc;
      const ThermalTraining t = fitThermalModel(segments, go);
      if (!(t.model.grey.b1 > 0.0)) return std::numeric_limits<double>::infinity();
      const std::vector<double> p = predictChange(t.model, head);
      for (std::size_t k = b; k < e; ++k) sse += (y[k] - p[k]) * (y[k] - p[k]);
    } catch (const std::exception&) {
      return std::numeric_limits<double>::infinity();
    }
  }
  const double r = std::sqrt(sse / static_cast<double>(n));
  return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
}

}  // namespace

ThermalSelection chooseThermalModel(const ThermalSeries& series, std::size_t fitRows,
                                    const ThermalFitOptions& o) {
  if (fitRows > series.rows()) throw std::invalid_argument("chooseThermalModel: more fit rows than rows");
  const ThermalSeries head = series.head(fitRows);
  ThermalSelection sel;
  sel.candidates = {ThermalModelKind::Linear, ThermalModelKind::Lag, ThermalModelKind::DistributedLag,
                    ThermalModelKind::Gmc};
  double best = std::numeric_limits<double>::infinity();
  for (ThermalModelKind k : sel.candidates) {
    double score = std::numeric_limits<double>::infinity();
    if (isRegression(k)) {
      ThermalFitOptions ro = o;
      ro.model = k;
      validateFitData({head}, ro);
      const LagForm form = k == ThermalModelKind::Linear ? LagForm::Static
                           : k == ThermalModelKind::Lag  ? LagForm::Lag
                                                         : LagForm::DistributedLag;
      fitLagModel(form, head.inputs.size(), {lagData(head)}, &score);
    } else {
      score = greyCvRmse(head, o);
    }
    sel.cvRmse.push_back(score);
    if (score < best) {
      best = score;
      sel.chosen = k;
    }
  }
  return sel;
}

namespace {

/// The figures of a modular prediction of `test` (m.predicted set): metrics and the error reduction.
void modularFigures(const ThermalSeries& test, ModularEvaluation& m) {
  m.test = thermalMetrics(test.target, m.predicted);
  double ss = 0.0;
  for (std::size_t k = 0; k < test.rows(); ++k) {
    const double e = test.target[k] - test.target[0];
    m.errorPeak = std::max(m.errorPeak, std::abs(e));
    ss += e * e;
  }
  m.errorRms = std::sqrt(ss / static_cast<double>(test.rows()));
  m.residualPeak = m.test.residualBand;
  m.reductionPeak = m.errorPeak > 0.0 ? 1.0 - m.residualPeak / m.errorPeak : 0.0;
  m.reductionRms = m.errorRms > 0.0 ? 1.0 - m.test.rmse / m.errorRms : 0.0;
}

void requireTarget(const ThermalSeries& test) {
  if (!test.hasTarget())
    throw ValidationError(ErrorContext{test.source, 0, 0, test.targetName},
                          "the test log has no target column");
}

}  // namespace

ModularEvaluation fitModular(const std::vector<ThermalSeries>& trainingTests, const ThermalSeries& test,
                             const ThermalFitOptions& o, Observer* observer) {
  requireTarget(test);
  ModularEvaluation m;
  m.training = fitThermalModel(trainingTests, o, observer);
  m.predicted = predictTarget(m.training.model, test);
  modularFigures(test, m);
  return m;
}

ThermalModule fitThermalModule(const std::string& name, const ThermalSeries& test, const ThermalFitOptions& o,
                               Observer* observer) {
  ThermalModule module;
  module.name = name;
  module.test = test.source;
  module.training = fitThermalModel({test}, o, observer);
  return module;
}

ModulesEvaluation evaluateModules(const std::vector<ThermalModule>& modules,
                                  const std::vector<ThermalSeries>& tests) {
  if (modules.empty() || modules.size() != tests.size())
    throw ValidationError(ErrorContext{}, "one test series per module is needed, " +
                                              std::to_string(tests.size()) + " for " +
                                              std::to_string(modules.size()) + " modules");
  const ThermalSeries& first = tests.front();
  requireTarget(first);
  ModulesEvaluation m;
  m.predicted.assign(first.rows(), first.target.front());
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const ThermalSeries& t = tests[i];
    if (t.rows() != first.rows() || t.target != first.target)
      throw ValidationError(ErrorContext{t.source, 0, 0, t.targetName},
                            "module '" + modules[i].name + "': not the same test log as the first module's");
    if (t.inputNames != modules[i].training.model.inputs)
      throw ValidationError(ErrorContext{t.source, 0, 0, t.targetName},
                            "module '" + modules[i].name + "' needs its own inputs on the test log");
    std::vector<double> c = predictChange(modules[i].training.model, t);
    double peak = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      m.predicted[k] += c[k];
      if (std::abs(c[k]) > std::abs(peak)) peak = c[k];
    }
    m.contributionPeaks.push_back(peak);
    m.contributions.push_back(std::move(c));
  }
  modularFigures(first, m);
  return m;
}

// ---- persistence ------------------------------------------------------------------------------

namespace {

constexpr const char* kFormat = "metrofit-thermal-model";

nlohmann::json vec(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

std::vector<double> numbers(const JsonReader& r, const std::string& key, std::size_t size) {
  const JsonReader a = r.array(key);
  if (a.size() != size) {
    r.fail("expected " + std::to_string(size) + " numbers, found " + std::to_string(a.size()), key);
  }
  std::vector<double> out(size);
  for (std::size_t i = 0; i < size; ++i) {
    const auto& v = a.json().at(i);
    if (!v.is_number() || !std::isfinite(v.get<double>())) a.at(i).fail("expected a finite number");
    out[i] = v.get<double>();
  }
  return out;
}

Eigen::VectorXd eigenVec(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

void saveThermalModules(const std::vector<ThermalModule>& modules, const std::string& folder) {
  for (const ThermalModule& m : modules)
    writeFileAtomic((std::filesystem::path(folder) / (m.name + ".json")).string(),
                    dumpJson(thermalModelToJson(m.training.model)));
}

nlohmann::json thermalModelToJson(const ThermalModel& m) {
  nlohmann::json j;
  j["format"] = kFormat;
  j["version"] = 1;
  j["model"] = toString(m.kind);
  j["target"] = m.target;
  j["inputs"] = m.inputs;
  j["time_unit_min"] = m.timeUnitMin;
  if (m.kind == ThermalModelKind::Mlp) {
    nlohmann::json n;
    n["hidden"] = m.mlp.hidden();
    n["in_min"] = vec(m.mlp.inMin);
    n["in_max"] = vec(m.mlp.inMax);
    n["out_min"] = m.mlp.outMin;
    n["out_max"] = m.mlp.outMax;
    nlohmann::json w = nlohmann::json::array();
    for (Eigen::Index i = 0; i < m.mlp.w.rows(); ++i) w.push_back(vec(m.mlp.w.row(i).transpose()));
    n["w"] = w;
    n["c"] = vec(m.mlp.c);
    n["v"] = vec(m.mlp.v);
    n["v0"] = m.mlp.v0;
    j["mlp"] = n;
  } else if (isRegression(m.kind)) {
    nlohmann::json terms = nlohmann::json::array();
    for (std::size_t t = 0; t < m.regression.terms.size(); ++t) {
      terms.push_back({{"input", m.inputs.at(m.regression.terms[t].input)},
                       {"tau_min", m.regression.terms[t].tauMin},
                       {"coefficient", m.regression.coef[t]}});
    }
    j["regression"] = {{"intercept", m.regression.intercept}, {"terms", terms}};
  } else {
    j["grey"] = {{"b1", m.grey.b1}, {"b", m.grey.b}, {"u", m.grey.u}};
  }
  return j;
}

ThermalModel thermalModelFromJson(const nlohmann::json& j, const std::string& source) {
  const JsonReader r(j, source);
  r.requireObject();
  if (r.string("format") != kFormat) r.fail(std::string("expected \"") + kFormat + "\"", "format");
  if (r.integer("version") != 1) r.fail("unsupported version (this build reads version 1)", "version");
  ThermalModel m;
  const std::string kind = r.string("model");
  bool known = false;
  for (auto k : kAllThermalModelKinds) known = known || kind == toString(k);
  if (!known) r.fail("expected gnnmci, gmc, mlp, linear, lag or dlag", "model");
  m.kind = thermalModelKind(kind);
  m.target = r.string("target");
  const JsonReader in = r.array("inputs");
  if (in.size() == 0) r.fail("needs at least one input", "inputs");
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (!in.json().at(i).is_string()) in.at(i).fail("expected a column name");
    m.inputs.push_back(in.json().at(i).get<std::string>());
  }
  m.timeUnitMin = r.number("time_unit_min");
  if (!(m.timeUnitMin > 0.0)) r.fail("must be positive", "time_unit_min");
  const std::size_t n = m.inputs.size();
  if (m.kind == ThermalModelKind::Mlp) {
    const JsonReader net = r.object("mlp");
    const long h = net.integer("hidden");
    if (h < 1 || h > 100000) net.fail("must be a positive count", "hidden");
    const auto hs = static_cast<std::size_t>(h);
    m.mlp.inMin = eigenVec(numbers(net, "in_min", n));
    m.mlp.inMax = eigenVec(numbers(net, "in_max", n));
    for (std::size_t i = 0; i < n; ++i) {
      if (!(m.mlp.inMax(static_cast<Eigen::Index>(i)) > m.mlp.inMin(static_cast<Eigen::Index>(i))))
        net.fail("in_max must exceed in_min for every input", "in_max");
    }
    m.mlp.outMin = net.number("out_min");
    m.mlp.outMax = net.number("out_max");
    if (!(m.mlp.outMax > m.mlp.outMin)) net.fail("must exceed out_min", "out_max");
    const JsonReader w = net.array("w");
    if (w.size() != hs) net.fail("expected " + std::to_string(hs) + " rows", "w");
    m.mlp.w.resize(h, static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < hs; ++i) {
      const JsonReader row = w.at(i);
      if (!row.json().is_array() || row.size() != n) row.fail("expected " + std::to_string(n) + " numbers");
      for (std::size_t k = 0; k < n; ++k) {
        const auto& v = row.json().at(k);
        if (!v.is_number() || !std::isfinite(v.get<double>())) row.at(k).fail("expected a finite number");
        m.mlp.w(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = v.get<double>();
      }
    }
    m.mlp.c = eigenVec(numbers(net, "c", hs));
    m.mlp.v = eigenVec(numbers(net, "v", hs));
    m.mlp.v0 = net.number("v0");
  } else if (isRegression(m.kind)) {
    const JsonReader g = r.object("regression");
    m.regression.intercept = g.number("intercept");
    const JsonReader terms = g.array("terms");
    if (terms.size() == 0) g.fail("needs at least one term", "terms");
    for (std::size_t t = 0; t < terms.size(); ++t) {
      const JsonReader term = terms.at(t);
      term.requireObject();
      const std::string input = term.string("input");
      const auto it = std::find(m.inputs.begin(), m.inputs.end(), input);
      if (it == m.inputs.end()) term.fail("'" + input + "' is not one of the model's inputs", "input");
      const double tau = term.number("tau_min");
      if (!(tau >= 0.0) || !std::isfinite(tau)) term.fail("must be a finite number >= 0", "tau_min");
      m.regression.terms.push_back({static_cast<std::size_t>(it - m.inputs.begin()), tau});
      m.regression.coef.push_back(term.number("coefficient"));
    }
  } else {
    const JsonReader g = r.object("grey");
    m.grey.b1 = g.number("b1");
    m.grey.b = numbers(g, "b", n);
    m.grey.u = g.number("u");
    if (m.kind == ThermalModelKind::Gnnmci && !(m.grey.b1 > 0.0)) g.fail("GNNMCI needs b1 = w11 > 0", "b1");
  }
  return m;
}

nlohmann::json thermalModelParameters(const ThermalModel& m) {
  nlohmann::json p;
  switch (m.kind) {
    case ThermalModelKind::Gnnmci: {
      // Paper names (Fig. 2): w11, w21 (= -x_1^(1)(1) = 0 on changes), w22.., the u weight last.
      p["w11"] = m.grey.b1;
      p["w21"] = 0.0;
      for (std::size_t j = 0; j < m.inputs.size(); ++j) p["w2" + std::to_string(j + 2)] = m.grey.b[j];
      p["w2" + std::to_string(m.inputs.size() + 2)] = m.grey.u;
      p["w3"] = "1 + exp(-w11 k)";
      p["time_constant_min"] = m.grey.b1 > 0.0 ? nlohmann::json(m.timeUnitMin / m.grey.b1) : nlohmann::json();
      nlohmann::json gains;
      for (std::size_t j = 0; j < m.inputs.size(); ++j) gains[m.inputs[j]] = m.grey.b[j] / m.grey.b1;
      p["static_gain"] = gains;
      break;
    }
    case ThermalModelKind::Gmc: {
      p["b1"] = m.grey.b1;
      nlohmann::json b;
      for (std::size_t j = 0; j < m.inputs.size(); ++j) b[m.inputs[j]] = m.grey.b[j];
      p["b"] = b;
      p["u"] = m.grey.u;
      p["time_constant_min"] = m.grey.b1 > 0.0 ? nlohmann::json(m.timeUnitMin / m.grey.b1) : nlohmann::json();
      p["stable"] = m.grey.b1 > 0.0;
      break;
    }
    case ThermalModelKind::Mlp:
      p["hidden"] = m.mlp.hidden();
      p["weights"] = Mlp::parameterCount(m.mlp.inputs(), m.mlp.hidden());
      p["transfer"] = "logsig-purelin";
      break;
    case ThermalModelKind::Linear:
    case ThermalModelKind::Lag:
    case ThermalModelKind::DistributedLag: {
      p["intercept"] = m.regression.intercept;
      nlohmann::json terms = nlohmann::json::array();
      for (std::size_t t = 0; t < m.regression.terms.size(); ++t) {
        terms.push_back({{"input", m.inputs.at(m.regression.terms[t].input)},
                         {"tau_min", m.regression.terms[t].tauMin},
                         {"coefficient", m.regression.coef[t]}});
      }
      p["terms"] = terms;
      break;
    }
  }
  p["time_unit_min"] = m.timeUnitMin;
  return p;
}

Compensation compensationValues(const ThermalModel& model, const ThermalSeries& s) {
  Compensation c;
  c.timeColumn = s.timeColumn;
  c.target = model.target;
  c.timeMin = s.timeMin;
  if (isGrey(model.kind) && !(model.grey.b1 > 0.0)) {
    throw ValidationError(ErrorContext{{}, 0, 0, "b1"},
                          "the " + std::string(toString(model.kind)) +
                              " model is unstable (b1 = " + CsvWriter::formatNumber(model.grey.b1, 6) +
                              " <= 0: its response grows without bound); it cannot give compensation values");
  }
  c.predicted = predictChange(model, s);
  for (std::size_t k = 0; k < c.predicted.size(); ++k) {
    if (!std::isfinite(c.predicted[k])) {
      throw ValidationError(ErrorContext{s.source, 0, 0, {}},
                            "the model's prediction is not finite at row " + std::to_string(k + 1));
    }
  }
  c.compensation.resize(c.predicted.size());
  for (std::size_t k = 0; k < c.predicted.size(); ++k) c.compensation[k] = -c.predicted[k];
  return c;
}

std::string compensationToCsv(const Compensation& c) {
  CsvWriter w;
  w.row({c.timeColumn, "predicted_" + c.target, "compensation_" + c.target});
  const double toCol = c.timeColumn == "time_s" ? 60.0 : c.timeColumn == "time_h" ? 1.0 / 60.0 : 1.0;
  auto fmt = [](double v) { return CsvWriter::formatNumber(std::round(v * 1e6) / 1e6 + 0.0); };
  for (std::size_t k = 0; k < c.timeMin.size(); ++k) {
    w.row({fmt(c.timeMin[k] * toCol), fmt(c.predicted[k]), fmt(c.compensation[k])});
  }
  return w.text();
}

}  // namespace metrofit::thermal
