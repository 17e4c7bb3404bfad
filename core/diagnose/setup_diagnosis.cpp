#include "core/diagnose/setup_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <set>

#include <Eigen/QR>

#include "core/common/error.h"
#include "core/diagnose/loop.h"
#include "core/diagnose/residual_check.h"
#include "core/io/csv.h"

namespace metrofit::diagnose {
namespace {

struct CandidateDef {
  std::string name;
  std::size_t datum = 0;
  bool perPart = true;  ///< tool wear (regressor: part number) or drift (regressor: time)
};

using A = PhraseArg;

ErrorSummary summarise(const Eigen::VectorXd& residual) {
  ErrorSummary s;
  s.rmse = rootMeanSquare(residual);
  s.maxAbs = residual.size() ? residual.cwiseAbs().maxCoeff() : 0.0;
  return s;
}

/// Per part: the least-squares apparent error of datum `datum` from the residuals of that part's rows.
std::vector<double> apparentError(const Eigen::VectorXd& residual, const Eigen::MatrixXd& G,
                                  const std::vector<std::size_t>& rowDim, const std::vector<int>& rowPart,
                                  std::size_t parts, std::size_t datum, std::vector<bool>* present) {
  std::vector<double> num(parts, 0.0), den(parts, 0.0);
  for (std::size_t r = 0; r < rowDim.size(); ++r) {
    const double g = G(static_cast<Eigen::Index>(rowDim[r]), static_cast<Eigen::Index>(datum));
    if (g == 0.0) continue;
    num[rowPart[r]] += g * residual(static_cast<Eigen::Index>(r));
    den[rowPart[r]] += g * g;
  }
  std::vector<double> out(parts, 0.0);
  present->assign(parts, false);
  for (std::size_t p = 0; p < parts; ++p) {
    if (den[p] > 0.0) {
      out[p] = num[p] / den[p];
      (*present)[p] = true;
    }
  }
  return out;
}

}  // namespace

bool SetupDiagnosisOptions::isValid(std::string* why) const {
  if (!acceptance.isValid(why)) return false;
  if (maxRounds < 0 || maxRounds > 1000) {
    if (why) *why = "max rounds must be in 0..1000";
    return false;
  }
  return true;
}

namespace {

/// The residual variables of the setup rows (docs/file-formats.md#residual_check): row (file order) and
/// time (natural orders), part (one level per part), dimension (one level per dimension) and, per
/// dimension with at least 6 rows, dimension:<d> = the part number on that dimension's rows, and per
/// setup datum datum:<id> = the part number weighted by the datum's gain on each row's dimension.
std::vector<ResidualVariable> setupVariables(const setup::Model& model, const Eigen::MatrixXd& gains,
                                             const std::vector<std::size_t>& rowDim,
                                             const std::vector<int>& rowPart, const Eigen::VectorXd& partCol,
                                             const Eigen::VectorXd& timeCol,
                                             const std::vector<std::size_t>& origRow,
                                             const std::vector<std::string>& partNames) {
  const std::size_t n = rowDim.size();
  std::vector<ResidualVariable> vars;
  ResidualVariable row;
  row.name = "row";
  row.naturalOrder = true;
  row.label = {Phrase("data row")};
  for (std::size_t r = 0; r < n; ++r) row.values.push_back(static_cast<double>(origRow[r] + 1));
  vars.push_back(std::move(row));
  ResidualVariable time;
  time.name = "time";
  time.naturalOrder = true;
  time.label = {Phrase("time (min)")};
  time.values.assign(timeCol.data(), timeCol.data() + n);
  if (n > 0 && timeCol.maxCoeff() > timeCol.minCoeff()) vars.push_back(std::move(time));
  ResidualVariable part;
  part.name = "part";
  part.kind = ResidualVariable::Kind::Category;
  part.label = {Phrase("part")};
  part.levels = partNames;
  for (std::size_t r = 0; r < n; ++r) part.values.push_back(rowPart[r]);
  vars.push_back(std::move(part));
  ResidualVariable dim;
  dim.name = "dimension";
  dim.kind = ResidualVariable::Kind::Category;
  dim.label = {Phrase("dimension")};
  std::map<std::size_t, int> dense;
  for (std::size_t r = 0; r < n; ++r)
    if (!dense.count(rowDim[r])) dense[rowDim[r]] = 0;
  int next = 0;
  for (auto& [d, i] : dense) {
    i = next++;
    dim.levels.push_back(model.dimensions[d].id);
  }
  std::map<std::size_t, int> count;
  for (std::size_t r = 0; r < n; ++r) {
    dim.values.push_back(dense[rowDim[r]]);
    ++count[rowDim[r]];
  }
  vars.push_back(std::move(dim));
  // datum:<id>: a change of one setup datum as a function of the part number, acting through its
  // gains (a re-clamped work offset, a tool changed mid-series: a step of every dimension it feeds).
  for (std::size_t i = 0; i < model.setup.size(); ++i) {
    ResidualVariable v;
    v.name = "datum:" + model.setup[i].id;
    v.label = {Phrase("part number (%1)", {PhraseArg::name(model.setup[i].id)})};
    bool any = false;
    for (std::size_t r = 0; r < n; ++r) {
      v.values.push_back(partCol(static_cast<Eigen::Index>(r)));
      v.weights.push_back(gains(static_cast<Eigen::Index>(rowDim[r]), static_cast<Eigen::Index>(i)));
      any = any || v.weights.back() != 0.0;
    }
    if (any) vars.push_back(std::move(v));
  }
  for (const auto& [d, c] : count) {
    if (c < 6) continue;
    ResidualVariable v;
    v.name = "dimension:" + model.dimensions[d].id;
    v.label = {Phrase("part number (%1)", {PhraseArg::name(model.dimensions[d].id)})};
    for (std::size_t r = 0; r < n; ++r)
      v.values.push_back(rowDim[r] == d ? partCol(static_cast<Eigen::Index>(r)) : std::nan(""));
    vars.push_back(std::move(v));
  }
  return vars;
}

ResidualCheckInput setupCheckInput(const Eigen::VectorXd& residual, const Eigen::MatrixXd& X,
                                   const Eigen::MatrixXd& Z, std::vector<ResidualVariable> vars) {
  ResidualCheckInput in;
  in.residual = residual;
  in.modelColumns.resize(X.rows(), X.cols() + Z.cols());
  in.modelColumns << X, Z;
  in.variables = std::move(vars);
  return in;
}

LoopRun runSetup(const setup::Model& model, const setup::Measurements& measurements,
                 const std::vector<std::size_t>& origRow, const SetupDiagnosisOptions& options,
                 const std::set<std::string>& excluded, Observer* observer) {
  const std::string source = measurements.sources.empty() ? std::string() : measurements.sources.front();
  const Eigen::MatrixXd G = setup::gainMatrix(model);
  const std::size_t n = measurements.rows.size();
  const auto nd = static_cast<Eigen::Index>(model.setup.size());
  if (n == 0) throw ValidationError(ErrorContext{source, 0, 0, {}}, "the report has no rows");

  // Part numbers: the numbers of the "part" column when all are numbers, else 1, 2, ... in order.
  std::map<std::string, double> partNumber;
  bool numeric = true;
  for (const std::string& part : measurements.parts) {
    double v = 0.0;
    if (!parseNumber(part, &v) || !std::isfinite(v)) numeric = false;
    partNumber[part] = v;
  }
  if (!numeric) {
    for (std::size_t i = 0; i < measurements.parts.size(); ++i)
      partNumber[measurements.parts[i]] = static_cast<double>(i + 1);
  }
  // Distinct parts in increasing part number, for the plots.
  std::vector<std::pair<double, std::string>> ordered;
  for (const auto& [name, number] : partNumber) ordered.emplace_back(number, name);
  std::sort(ordered.begin(), ordered.end());
  std::map<std::string, int> partSlot;
  for (std::size_t i = 0; i < ordered.size(); ++i) partSlot[ordered[i].second] = static_cast<int>(i);

  Eigen::MatrixXd X(static_cast<Eigen::Index>(n), nd);
  Eigen::VectorXd y(static_cast<Eigen::Index>(n)), partCol(static_cast<Eigen::Index>(n)),
      timeCol(static_cast<Eigen::Index>(n));
  std::vector<std::size_t> rowDim(n);
  std::vector<int> rowPart(n);
  std::vector<double> slotTimeSum(ordered.size(), 0.0);
  std::vector<int> slotTimeCount(ordered.size(), 0);
  for (std::size_t r = 0; r < n; ++r) {
    const setup::Measurements::Row& row = measurements.rows[r];
    if (row.dimension >= model.dimensions.size())
      throw ValidationError(ErrorContext{row.source, row.line, 0, "dimension"},
                            "the report does not belong to the model (dimension index out of range)");
    const auto i = static_cast<Eigen::Index>(r);
    X.row(i) = G.row(static_cast<Eigen::Index>(row.dimension));
    y(i) = row.deviationMm;
    partCol(i) = partNumber.count(row.part) ? partNumber[row.part] : 0.0;
    timeCol(i) = row.timeMin;
    rowDim[r] = row.dimension;
    rowPart[r] = partSlot.count(row.part) ? partSlot[row.part] : 0;
    slotTimeSum[rowPart[r]] += row.timeMin;
    ++slotTimeCount[rowPart[r]];
  }
  const ColumnSpace declared(X);
  if (static_cast<long>(n) <= declared.rank())
    throw ValidationError(ErrorContext{source, 0, 0, {}}, "too few rows (" + std::to_string(n) +
                                                              ") for the declared model of rank " +
                                                              std::to_string(declared.rank()));

  std::vector<CandidateDef> defs;
  for (std::size_t i = 0; i < model.setup.size(); ++i)
    if (model.setup[i].kind == setup::DatumKind::Tool)
      defs.push_back({"tool_wear:" + model.setup[i].id, i, true});
  for (std::size_t i = 0; i < model.setup.size(); ++i)
    defs.push_back({"drift:" + model.setup[i].id, i, false});

  auto column = [&](const CandidateDef& d) {
    const Eigen::VectorXd g = X.col(static_cast<Eigen::Index>(d.datum));
    return Eigen::VectorXd(g.cwiseProduct(d.perPart ? partCol : timeCol));
  };

  Diagnosis result;
  result.domain = "setup";
  result.units = "mm";
  Eigen::MatrixXd Zacc(static_cast<Eigen::Index>(n), 0);
  EffectEstimate current = estimateEffects(declared, y, Zacc);
  result.baseline = summarise(current.residual);
  {
    const auto data = static_cast<long long>(model.setup.size());
    Phrases note = {Phrase(
        "declared model: constant errors of the %1 setup data through the relation graph, "
        "least squares over %2 rows of %3 parts; rank %4 of %5",
        {A::integer(data), A::integer(static_cast<long long>(n)),
         A::integer(static_cast<long long>(ordered.size())), A::integer(declared.rank()), A::integer(data)})};
    if (declared.rank() < static_cast<int>(model.setup.size()))
      note.push_back(Phrase(" (rank deficient: minimum-norm solution)"));
    result.addNote(std::move(note));
  }
  {
    const Eigen::VectorXd e = X.completeOrthogonalDecomposition().solve(y);
    Phrases note = {Phrase("declared fit (minimum norm), setup errors mm:")};
    for (Eigen::Index i = 0; i < nd; ++i)
      note.push_back(Phrase(" %1=%2", {A::name(model.setup[i].id), A::fixed(e(i), 4)}));
    result.addNote(std::move(note));
  }

  std::vector<std::string> slotNames;
  for (const auto& o : ordered) slotNames.push_back(o.second);
  const std::vector<ResidualVariable> vars =
      setupVariables(model, G, rowDim, rowPart, partCol, timeCol, origRow, slotNames);

  /// The setup domain of the shared loop (loop.h): a linear model, effects as extra columns Z.
  class Domain final : public LoopDomain {
   public:
    Domain(
        const SetupDiagnosisOptions& o, const ColumnSpace& declared, const Eigen::VectorXd& y,
        const Eigen::MatrixXd& X, EffectEstimate start, const std::vector<CandidateDef>& defs,
        const std::vector<ResidualVariable>& vars, std::function<Eigen::VectorXd(const CandidateDef&)> column,
        std::function<ResidualPlot(const CandidateDef&, const Eigen::VectorXd&, const Eigen::VectorXd&)> plot)
        : o_(o),
          declared_(declared),
          y_(y),
          X_(X),
          current_(std::move(start)),
          defs_(defs),
          vars_(vars),
          column_(std::move(column)),
          plot_(std::move(plot)),
          used_(defs.size(), false),
          Zacc_(y.size(), 0) {}

    std::vector<std::string> namedCandidates(const std::set<std::string>& excluded) override {
      std::vector<std::string> names;
      for (const auto& d : defs_) names.push_back(d.name);
      return openNamedEffects(names, used_, excluded);
    }
    // The variable of tool_wear:T and drift:T (loop.h, "a generic effect of the same variable
    // explains clearly more"): datum:T, the part number weighted by the datum's gains (both are that
    // datum's gain times a linear function of the part number or of time).
    std::vector<std::string> namedVariables(const Candidate& c) const override {
      for (const CandidateDef& d : defs_)
        if (d.name == c.name) return {"datum:" + d.name.substr(d.name.find(':') + 1)};
      return {};
    }
    double clearMargin() const override { return o_.acceptance.bicThreshold; }
    ResidualCheck roundCheck() override {
      return checkResidual(setupCheckInput(current_.residual, X_, Zacc_, vars_));
    }
    bool beginRound(int) override {
      slots_.clear();
      return true;
    }

    std::optional<LoopTrial> tryNamed(const std::string& name, int /*round*/, std::size_t slot) override {
      const std::size_t c = indexOf(name);
      const CandidateDef& d = defs_[c];
      const auto n = static_cast<std::size_t>(y_.size());
      Slot s;
      s.def = c;
      s.add = column_(d);
      Eigen::MatrixXd Z(y_.size(), Zacc_.cols() + 1);
      Z << Zacc_, s.add;
      s.est = estimateEffects(declared_, y_, Z);
      LoopTrial t;
      Candidate& cand = t.candidate;
      cand.name = d.name;
      const double rmseBefore = rootMeanSquare(current_.residual);
      cand.rmseBefore = rmseBefore;
      const std::string unit = d.perPart ? "mm_per_part" : "mm_per_min";
      if (!s.est.identifiable) {
        cand.rmseAfter = rmseBefore;
        cand.parameters.push_back({unit, 0.0, std::nullopt});
        cand.setEvidence({Phrase(d.perPart ? "not identifiable: %1 (one part only?)"
                                           : "not identifiable: %1 (time does not vary?)",
                                 {A::text({Phrase(s.est.why)})})});
      } else {
        t.estimable = true;
        const Eigen::Index k = s.est.beta.size() - 1;
        const double value = s.est.beta(k), se = std::sqrt(std::max(0.0, s.est.covariance(k, k)));
        cand.parameters.push_back({unit, value, se});
        cand.rmseAfter = rootMeanSquare(s.est.residual);
        const AcceptanceDecision dec =
            decideAcceptance(o_.acceptance, current_.rss, s.est.rss, n, current_.dof, 1, "mm");
        cand.score = deltaBic(current_.rss, s.est.rss, n, current_.dof, 1);
        cand.setEvidence(
            {Phrase(d.perPart ? "%1 +- %2 mm/part (t = %3); " : "%1 +- %2 mm/min (t = %3); ",
                    {A::number(value, 3), A::number(se, 2), A::fixed(se > 0.0 ? value / se : 0.0, 1)})});
        cand.addEvidence(dec.reasonParts);
        cand.plot = plot_(d, current_.residual, s.est.residual);
        t.passes = dec.accepted;
        t.complexity = std::log(static_cast<double>(n));
      }
      store(slot, std::move(s));
      return t;
    }

    std::optional<LoopTrial> tryGeneric(const GenericForm& g, double penalty, int /*round*/,
                                        std::size_t slot) override {
      const ResidualVariable* v = findVariable(vars_, g.against);
      const auto n = static_cast<std::size_t>(y_.size());
      Slot s;
      s.def = defs_.size();
      s.add = v ? variableBasis(g, *v) : Eigen::MatrixXd(y_.size(), 0);
      Eigen::MatrixXd Z(y_.size(), Zacc_.cols() + s.add.cols());
      Z << Zacc_, s.add;
      s.est = estimateEffects(declared_, y_, Z);
      LoopTrial t;
      Candidate& cand = t.candidate;
      cand.name = "unexplained:" + g.against;
      cand.generic = g;
      const double rmseBefore = rootMeanSquare(current_.residual);
      cand.rmseBefore = rmseBefore;
      if (!s.est.identifiable || !v) {
        cand.rmseAfter = rmseBefore;
        cand.setEvidence({Phrase("not identifiable: %1", {A::text({Phrase(s.est.why)})})});
      } else {
        t.estimable = true;
        const auto q = static_cast<int>(s.add.cols());
        cand.rmseAfter = rootMeanSquare(s.est.residual);
        const AcceptanceDecision dec =
            decideAcceptance(o_.acceptance, current_.rss, s.est.rss, n, current_.dof, q, "mm", 0, penalty);
        cand.score = deltaBic(current_.rss, s.est.rss, n, current_.dof, q, penalty);
        const GenericSummary gs = summariseGeneric(g, s.est.beta.tail(q), v->values, "mm");
        for (const auto& [k, val] : gs.numbers) cand.parameters.push_back({k, val, std::nullopt});
        cand.parameters.insert(cand.parameters.begin(),
                               Parameter{"form", std::string(formName(g.form)), std::nullopt});
        Phrases ev = gs.text;
        ev.push_back(Phrase("; "));
        for (const Phrase& ph : dec.reasonParts) ev.push_back(ph);
        cand.setEvidence(std::move(ev));
        t.passes = dec.accepted;
        t.complexity = static_cast<double>(q) * std::log(static_cast<double>(n)) + penalty;
      }
      store(slot, std::move(s));
      return t;
    }

    // tool_wear:T and drift:T explain the same datum, by part number and by time. When time is
    // nearly proportional to the part number the data cannot tell them apart: unless the best one
    // beats the other by the decision threshold, the one listed first (tool wear) is preferred.
    std::optional<std::size_t> prefer(const std::vector<LoopTrial>& trials, std::size_t b,
                                      Phrases* why) override {
      if (slots_[b].def >= defs_.size()) return std::nullopt;
      for (std::size_t j = 0; j < b; ++j) {
        if (!trials[j].passes || !trials[j].estimable || slots_[j].def >= defs_.size() ||
            defs_[slots_[j].def].datum != defs_[slots_[b].def].datum)
          continue;
        if (trials[j].candidate.score - trials[b].candidate.score < o_.acceptance.bicThreshold) {
          *why = {
              Phrase("; preferred to %1 (its dBIC is %2 lower, below the threshold: the data cannot tell "
                     "them apart)",
                     {A::name(trials[b].candidate.name),
                      A::fixed(trials[j].candidate.score - trials[b].candidate.score, 1)})};
          return j;
        }
      }
      return std::nullopt;
    }

    void accept(std::size_t slot, Candidate& /*accepted*/) override {
      Slot& s = slots_[slot];
      if (s.def < defs_.size()) used_[s.def] = true;
      width_.push_back(s.add.cols());
      Eigen::MatrixXd Z(y_.size(), Zacc_.cols() + s.add.cols());
      Z << Zacc_, s.add;
      Zacc_ = std::move(Z);
      current_ = std::move(s.est);
    }
    double currentError() const override { return rootMeanSquare(current_.residual); }

    void finish(Diagnosis& d, std::vector<Candidate*> accepted, bool /*stopped*/) override {
      // Accepted effects carry the parameters of the final joint fit.
      Eigen::Index col = 0;
      for (std::size_t j = 0; j < accepted.size(); ++j) {
        Candidate& c = *accepted[j];
        const Eigen::Index width = width_[j];
        if (c.generic) {
          if (const ResidualVariable* v = findVariable(vars_, c.generic->against)) {
            const GenericSummary gs =
                summariseGeneric(*c.generic, current_.beta.segment(col, width), v->values, "mm");
            c.parameters = {Parameter{"form", std::string(formName(c.generic->form)), std::nullopt}};
            for (const auto& [k, val] : gs.numbers) c.parameters.push_back({k, val, std::nullopt});
            // Apply (applied_setup_matching.h) predicts the next part with these coefficients of the
            // shape's basis.
            const Eigen::VectorXd w = current_.beta.segment(col, width);
            c.genericCoefficients.assign(w.data(), w.data() + w.size());
          }
        } else {
          Parameter& p = c.parameters.front();
          p.value = current_.beta(col);
          p.standardError = std::sqrt(std::max(0.0, current_.covariance(col, col)));
        }
        col += width;
      }
      d.final = summarise(current_.residual);
    }
    double dataCriterion() const override {
      const auto n = static_cast<double>(y_.size());
      return n * std::log(std::max(current_.rss, 1e-300) / n);
    }
    const EffectEstimate& current() const { return current_; }
    const Eigen::MatrixXd& Zacc() const { return Zacc_; }

   private:
    struct Slot {
      std::size_t def = 0;  ///< defs index, or defs.size() for a generic effect
      Eigen::MatrixXd add;
      EffectEstimate est;
    };
    std::size_t indexOf(const std::string& name) const {
      for (std::size_t c = 0; c < defs_.size(); ++c)
        if (defs_[c].name == name) return c;
      return defs_.size();
    }
    void store(std::size_t slot, Slot s) {
      if (slots_.size() <= slot) slots_.resize(slot + 1);
      slots_[slot] = std::move(s);
    }

    const SetupDiagnosisOptions& o_;
    const ColumnSpace& declared_;
    const Eigen::VectorXd& y_;
    const Eigen::MatrixXd& X_;
    EffectEstimate current_;
    const std::vector<CandidateDef>& defs_;
    const std::vector<ResidualVariable>& vars_;
    std::function<Eigen::VectorXd(const CandidateDef&)> column_;
    std::function<ResidualPlot(const CandidateDef&, const Eigen::VectorXd&, const Eigen::VectorXd&)> plot_;
    std::vector<bool> used_;
    Eigen::MatrixXd Zacc_;
    std::vector<Eigen::Index> width_;
    std::vector<Slot> slots_;
  };

  // Residual plot of a named effect: apparent error of the datum per part against part number or time.
  auto plot = [&](const CandidateDef& d, const Eigen::VectorXd& before, const Eigen::VectorXd& after) {
    std::vector<bool> presentBefore, presentAfter;
    const std::vector<double> b =
        apparentError(before, G, rowDim, rowPart, ordered.size(), d.datum, &presentBefore);
    const std::vector<double> a =
        apparentError(after, G, rowDim, rowPart, ordered.size(), d.datum, &presentAfter);
    ResidualPlot p;
    p.setLabels({Phrase(d.perPart ? "part" : "time (min)")},
                {Phrase("apparent error of %1 (mm)", {A::name(model.setup[d.datum].id)})});
    for (std::size_t k = 0; k < ordered.size(); ++k) {
      if (!presentBefore[k]) continue;
      p.x.push_back(d.perPart ? ordered[k].first : slotTimeSum[k] / std::max(1, slotTimeCount[k]));
      p.before.push_back(b[k]);
      p.after.push_back(a[k]);
    }
    return p;
  };
  Domain domain(
      options, declared, y, X, std::move(current), defs, vars,
      [&](const CandidateDef& d) { return Eigen::VectorXd(column(d)); }, plot);
  LoopStyle style;
  style.maxRounds = options.maxRounds;
  LoopRun out = runLoop(domain, style, excluded, observer, std::move(result));
  ResidualCheckInput in = setupCheckInput(domain.current().residual, X, domain.Zacc(), vars);
  for (std::size_t r = 0; r < n; ++r) {
    in.unitRow.push_back(static_cast<long>(origRow[r] + 1));
    in.unitPart.push_back(measurements.rows[r].part);
    in.unitDimension.push_back(model.dimensions[rowDim[r]].id);
  }
  out.diagnosis.residualCheck = checkResidual(in);
  return out;
}

/// The declared model's residual of every row (for the outlier search).
Eigen::VectorXd declaredResidual(const setup::Model& model, const setup::Measurements& m) {
  const Eigen::MatrixXd G = setup::gainMatrix(model);
  const auto n = static_cast<Eigen::Index>(m.rows.size());
  Eigen::MatrixXd X(n, G.cols());
  Eigen::VectorXd y(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto& row = m.rows[static_cast<std::size_t>(r)];
    if (row.dimension >= model.dimensions.size())
      throw ValidationError(ErrorContext{row.source, row.line, 0, "dimension"},
                            "the report does not belong to the model (dimension index out of range)");
    X.row(r) = G.row(static_cast<Eigen::Index>(row.dimension));
    y(r) = row.deviationMm;
  }
  return ColumnSpace(X).residual(y);
}

}  // namespace

Diagnosis diagnoseSetup(const setup::Model& model, const setup::Measurements& measurements,
                        const SetupDiagnosisOptions& options, Observer* observer) {
  requireValid(options, "setup diagnosis options");
  // Gross errors (`outliers`, docs/file-formats.md#residual_check): found on the declared model's residual
  // (robust z, see residual_check.h), excluded, and the loop run without them. A gross error hides behind an
  // effect only when the effect is many times larger than the noise; the final check still lists
  // such a point as structure (a spike), not silently.
  std::vector<bool> excluded(measurements.rows.size(), false);
  std::vector<Outlier> outliers;
  double threshold = 0.0;
  auto runWithout = [&]() {
    setup::Measurements kept = measurements;
    kept.rows.clear();
    std::vector<std::size_t> orig;
    for (std::size_t r = 0; r < measurements.rows.size(); ++r)
      if (!excluded[r]) {
        kept.rows.push_back(measurements.rows[r]);
        orig.push_back(r);
      }
    Diagnosis d = keepNamedOnlyWhenNeeded(
        [&](const std::set<std::string>& ex) { return runSetup(model, kept, orig, options, ex, observer); },
        options.acceptance.bicThreshold);
    return std::make_pair(std::move(d), orig);
  };
  auto addOutliers = [&](const Eigen::VectorXd& residual, const std::vector<std::size_t>& orig) {
    ResidualCheckInput in;
    in.residual = residual;
    for (std::size_t r : orig) {
      in.unitRow.push_back(static_cast<long>(r + 1));
      in.unitPart.push_back(measurements.rows[r].part);
      in.unitDimension.push_back(model.dimensions[measurements.rows[r].dimension].id);
    }
    std::vector<Outlier> found = findOutliers(in, {}, &threshold);
    for (Outlier& o : found) {
      o.unit = orig[o.unit];
      excluded[o.unit] = true;
      outliers.push_back(o);
    }
    return !found.empty();
  };
  if (!measurements.rows.empty()) {
    std::vector<std::size_t> all(measurements.rows.size());
    std::iota(all.begin(), all.end(), 0);
    addOutliers(declaredResidual(model, measurements), all);
  }
  auto [result, orig] = runWithout();
  (void)orig;
  attachOutliers(result, std::move(outliers), threshold, [](const Outlier& o) {
    return Phrase(" row %1 (part %2, %3, %4 mm)",
                  {A::integer(o.row.value_or(0)), A::name(o.part.value_or("")),
                   A::name(o.dimension.value_or("")), A::number(o.residual, 3)});
  });
  return result;
}

}  // namespace metrofit::diagnose
