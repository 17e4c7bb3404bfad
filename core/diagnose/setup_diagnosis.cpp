#include "core/diagnose/setup_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include <Eigen/QR>

#include "core/common/error.h"
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

/// The residual variables of the setup rows (CONTRACT.md "The open world"): row (file order) and
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

  std::vector<bool> used(defs.size(), false);
  std::vector<std::size_t> acceptedDefs;
  std::vector<std::string> genericTaken;
  std::vector<Eigen::Index> acceptedWidth;  ///< columns of each accepted candidate in Zacc
  double complexity = 0.0;                  ///< k ln n + search penalties of the accepted effects
  std::vector<Candidate> acceptedCandidates, lastRound;
  long tried = 0;
  LoopProgress progress(observer);
  for (int round = 0;; ++round) {
    std::vector<Candidate> roundCandidates;
    std::vector<EffectEstimate> estimates;
    std::vector<std::size_t> roundDefs;
    int best = -1;
    const double rmseBefore = rootMeanSquare(current.residual);
    for (std::size_t c = 0; c < defs.size(); ++c) {
      if (used[c] || excluded.count(defs[c].name) || excluded.count(kEveryNamedEffect)) continue;
      const CandidateDef& d = defs[c];
      Eigen::MatrixXd Z(static_cast<Eigen::Index>(n), Zacc.cols() + 1);
      Z.leftCols(Zacc.cols()) = Zacc;
      Z.col(Zacc.cols()) = column(d);
      EffectEstimate est = estimateEffects(declared, y, Z);
      ++tried;
      Candidate cand;
      cand.name = d.name;
      cand.round = round;
      cand.rmseBefore = rmseBefore;
      const std::string unit = d.perPart ? "mm_per_part" : "mm_per_min";
      if (!est.identifiable) {
        cand.rmseAfter = rmseBefore;
        cand.parameters.push_back({unit, 0.0, std::nullopt});
        cand.setEvidence({Phrase(d.perPart ? "not identifiable: %1 (one part only?)"
                                           : "not identifiable: %1 (time does not vary?)",
                                 {A::text({Phrase(est.why)})})});
      } else {
        const Eigen::Index k = est.beta.size() - 1;
        const double value = est.beta(k), se = std::sqrt(std::max(0.0, est.covariance(k, k)));
        cand.parameters.push_back({unit, value, se});
        cand.rmseAfter = rootMeanSquare(est.residual);
        const AcceptanceDecision dec =
            decideAcceptance(options.acceptance, current.rss, est.rss, n, current.dof, 1, "mm");
        cand.score = deltaBic(current.rss, est.rss, n, current.dof, 1);
        cand.setEvidence(
            {Phrase(d.perPart ? "%1 +- %2 mm/part (t = %3); " : "%1 +- %2 mm/min (t = %3); ",
                    {A::number(value, 3), A::number(se, 2), A::fixed(se > 0.0 ? value / se : 0.0, 1)})});
        cand.addEvidence(dec.reasonParts);
        // Residual plot: apparent error of the datum per part against part number or time.
        std::vector<bool> presentBefore, presentAfter;
        const std::vector<double> before =
            apparentError(current.residual, G, rowDim, rowPart, ordered.size(), d.datum, &presentBefore);
        const std::vector<double> after =
            apparentError(est.residual, G, rowDim, rowPart, ordered.size(), d.datum, &presentAfter);
        ResidualPlot plot;
        plot.setLabels({Phrase(d.perPart ? "part" : "time (min)")},
                       {Phrase("apparent error of %1 (mm)", {A::name(model.setup[d.datum].id)})});
        for (std::size_t p = 0; p < ordered.size(); ++p) {
          if (!presentBefore[p]) continue;
          plot.x.push_back(d.perPart ? ordered[p].first : slotTimeSum[p] / std::max(1, slotTimeCount[p]));
          plot.before.push_back(before[p]);
          plot.after.push_back(after[p]);
        }
        cand.plot = std::move(plot);
        if (dec.accepted && round < options.maxRounds &&
            (best < 0 || cand.score < roundCandidates[static_cast<std::size_t>(best)].score))
          best = static_cast<int>(roundCandidates.size());
        cand.accepted = dec.accepted;  // provisional: only the best one stays accepted
      }
      roundCandidates.push_back(std::move(cand));
      estimates.push_back(std::move(est));
      roundDefs.push_back(c);
    }
    // Generic candidates (CONTRACT.md "The open world"): the strongest structures of the current
    // residual, each a basis of its variable, under the same evidence (plus the search penalty).
    std::vector<Eigen::MatrixXd> genericColumns(roundCandidates.size());
    std::vector<double> genericPenalties(roundCandidates.size(), 0.0);
    const int bestNamed = best;  // a named effect that passes is preferred (keepNamedOnlyWhenNeeded)
    {
      const ResidualCheck rc = checkResidual(setupCheckInput(current.residual, X, Zacc, vars));
      const double penalty = genericSearchPenalty(rc);
      for (const GenericForm& g : genericCandidates(rc, genericTaken)) {
        const ResidualVariable* v = findVariable(vars, g.against);
        if (!v) continue;
        const Eigen::MatrixXd Zg = variableBasis(g, *v);
        Eigen::MatrixXd Z(static_cast<Eigen::Index>(n), Zacc.cols() + Zg.cols());
        Z << Zacc, Zg;
        EffectEstimate est = estimateEffects(declared, y, Z);
        ++tried;
        Candidate cand;
        cand.name = "unexplained:" + g.against;
        cand.generic = g;
        cand.round = round;
        cand.rmseBefore = rmseBefore;
        if (!est.identifiable) {
          cand.rmseAfter = rmseBefore;
          cand.setEvidence({Phrase("not identifiable: %1", {A::text({Phrase(est.why)})})});
        } else {
          const auto q = static_cast<int>(Zg.cols());
          cand.rmseAfter = rootMeanSquare(est.residual);
          const AcceptanceDecision dec =
              decideAcceptance(options.acceptance, current.rss, est.rss, n, current.dof, q, "mm", 0, penalty);
          cand.score = deltaBic(current.rss, est.rss, n, current.dof, q, penalty);
          const GenericSummary gs = summariseGeneric(g, est.beta.tail(q), v->values, "mm");
          for (const auto& [k, val] : gs.numbers) cand.parameters.push_back({k, val, std::nullopt});
          cand.parameters.insert(cand.parameters.begin(),
                                 Parameter{"form", std::string(formName(g.form)), std::nullopt});
          Phrases ev = gs.text;
          ev.push_back(Phrase("; "));
          for (const Phrase& ph : dec.reasonParts) ev.push_back(ph);
          cand.setEvidence(std::move(ev));
          if (dec.accepted && round < options.maxRounds && bestNamed < 0 &&
              (best < 0 || cand.score < roundCandidates[static_cast<std::size_t>(best)].score))
            best = static_cast<int>(roundCandidates.size());
          cand.accepted = dec.accepted;
        }
        roundCandidates.push_back(std::move(cand));
        estimates.push_back(std::move(est));
        roundDefs.push_back(defs.size());  // not a named definition
        genericColumns.push_back(Zg);
        genericPenalties.push_back(penalty);
      }
    }
    std::vector<bool> acceptable(roundCandidates.size());
    for (std::size_t j = 0; j < roundCandidates.size(); ++j) {
      acceptable[j] = roundCandidates[j].accepted;
      roundCandidates[j].accepted = false;
    }
    // tool_wear:T and drift:T explain the same datum, by part number and by time. When time is
    // nearly proportional to the part number the data cannot tell them apart: unless the best one
    // beats the other by the decision threshold, the one listed first (tool wear) is preferred.
    Phrases preferredOver;
    if (best >= 0) {
      const auto b = static_cast<std::size_t>(best);
      for (std::size_t j = 0; j < b; ++j) {
        if (!acceptable[j] || roundDefs[j] >= defs.size() || roundDefs[b] >= defs.size() ||
            defs[roundDefs[j]].datum != defs[roundDefs[b]].datum)
          continue;
        if (roundCandidates[j].score - roundCandidates[b].score < options.acceptance.bicThreshold) {
          preferredOver = {
              Phrase("; preferred to %1 (its dBIC is %2 lower, below the threshold: the data cannot tell "
                     "them apart)",
                     {A::name(roundCandidates[b].name),
                      A::fixed(roundCandidates[j].score - roundCandidates[b].score, 1)})};
          best = static_cast<int>(j);
          break;
        }
      }
    }
    bool cancelled = false;
    if (best >= 0) {
      const auto b = static_cast<std::size_t>(best);
      Candidate& win = roundCandidates[b];
      win.accepted = true;
      win.addEvidence(std::move(preferredOver));
      // Ties (e.g. time proportional to part number): the first listed wins, the evidence says so.
      for (std::size_t j = 0; j < roundCandidates.size(); ++j) {
        if (j == b || !estimates[j].identifiable) continue;
        if (std::abs(roundCandidates[j].score - win.score) <= 1e-6 * std::abs(win.score) + 1e-9)
          win.addEvidence(
              {Phrase("; indistinguishable from %1 with these data", {A::name(roundCandidates[j].name)})});
      }
      const bool generic = roundDefs[b] >= defs.size();
      const Eigen::MatrixXd add = generic ? genericColumns[b] : Eigen::MatrixXd(column(defs[roundDefs[b]]));
      if (generic) {
        genericTaken.push_back(win.generic->against);
      } else {
        used[roundDefs[b]] = true;
        acceptedDefs.push_back(roundDefs[b]);
      }
      acceptedWidth.push_back(add.cols());
      complexity += static_cast<double>(add.cols()) * std::log(static_cast<double>(n)) +
                    (generic ? genericPenalties[b] : 0.0);
      Eigen::MatrixXd Z(static_cast<Eigen::Index>(n), Zacc.cols() + add.cols());
      Z << Zacc, add;
      Zacc = Z;
      current = std::move(estimates[b]);
      acceptedCandidates.push_back(win);
    } else {
      lastRound = std::move(roundCandidates);
    }
    cancelled =
        progress.afterRound(round, tried, rootMeanSquare(current.residual), acceptedCandidates.size());
    if (best < 0) break;
    if (cancelled) {
      progress.addNote(result);
      break;
    }
  }
  // Accepted effects carry the parameters of the final joint fit.
  Eigen::Index col = 0;
  for (std::size_t j = 0; j < acceptedCandidates.size(); ++j) {
    Candidate& c = acceptedCandidates[j];
    const Eigen::Index w = acceptedWidth[j];
    if (c.generic) {
      if (const ResidualVariable* v = findVariable(vars, c.generic->against)) {
        const GenericSummary gs = summariseGeneric(*c.generic, current.beta.segment(col, w), v->values, "mm");
        c.parameters = {Parameter{"form", std::string(formName(c.generic->form)), std::nullopt}};
        for (const auto& [k, val] : gs.numbers) c.parameters.push_back({k, val, std::nullopt});
      }
    } else {
      Parameter& p = c.parameters.front();
      p.value = current.beta(col);
      p.standardError = std::sqrt(std::max(0.0, current.covariance(col, col)));
    }
    col += w;
  }
  result.effects = std::move(acceptedCandidates);
  for (Candidate& c : lastRound) result.effects.push_back(std::move(c));
  result.final = summarise(current.residual);
  ResidualCheckInput in = setupCheckInput(current.residual, X, Zacc, vars);
  for (std::size_t r = 0; r < n; ++r) {
    in.unitRow.push_back(static_cast<long>(origRow[r] + 1));
    in.unitPart.push_back(measurements.rows[r].part);
    in.unitDimension.push_back(model.dimensions[rowDim[r]].id);
  }
  result.residualCheck = checkResidual(in);
  LoopRun out;
  out.bic =
      static_cast<double>(n) * std::log(std::max(current.rss, 1e-300) / static_cast<double>(n)) + complexity;
  out.stopped = progress.stopped();
  out.diagnosis = std::move(result);
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
  // Gross errors (CONTRACT.md `outliers`): found on the declared model's residual (robust z, see
  // residual_check.h), excluded, and the loop run without them. A gross error hides behind an
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
