#include "core/diagnose/setup_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/QR>

#include "core/common/error.h"
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

Diagnosis diagnoseSetup(const setup::Model& model, const setup::Measurements& measurements,
                        const SetupDiagnosisOptions& options, Observer* observer) {
  requireValid(options, "setup diagnosis options");
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

  std::vector<bool> used(defs.size(), false);
  std::vector<std::size_t> acceptedDefs;
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
      if (used[c]) continue;
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
        if (!acceptable[j] || defs[roundDefs[j]].datum != defs[roundDefs[b]].datum) continue;
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
      used[roundDefs[b]] = true;
      acceptedDefs.push_back(roundDefs[b]);
      Eigen::MatrixXd Z(static_cast<Eigen::Index>(n), Zacc.cols() + 1);
      Z.leftCols(Zacc.cols()) = Zacc;
      Z.col(Zacc.cols()) = column(defs[roundDefs[b]]);
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
  for (std::size_t j = 0; j < acceptedCandidates.size(); ++j) {
    Parameter& p = acceptedCandidates[j].parameters.front();
    p.value = current.beta(static_cast<Eigen::Index>(j));
    p.standardError = std::sqrt(
        std::max(0.0, current.covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j))));
  }
  result.effects = std::move(acceptedCandidates);
  for (Candidate& c : lastRound) result.effects.push_back(std::move(c));
  result.final = summarise(current.residual);
  return result;
}

}  // namespace metrofit::diagnose
