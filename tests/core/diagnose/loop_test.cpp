// The shared closed loop (loop.h runLoop) on a scripted domain: which candidate is accepted, what is
// listed, when the loop stops, and how a stop by the observer ends it. The domain's numbers are
// written here, so the expected choices follow from the rules in loop.h alone.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "core/diagnose/loop.h"

namespace metrofit::diagnose {
namespace {

/// Candidates with fixed scores: a named effect "n:<s>" or the generic effect of structure "x"
/// passes when its score is below zero; accepting one removes it. The residual check reports a
/// structure against "x" until the generic effect of x is accepted.
class Scripted final : public LoopDomain {
 public:
  std::map<std::string, double> named;  ///< name -> score
  double genericScore = 1.0;
  bool xTaken = false;
  std::vector<std::string> acceptedNames;
  int finished = 0;
  std::map<std::string, std::vector<std::string>> variablesOf;  ///< named effect -> its variables
  double margin = 10.0;

  std::vector<std::string> namedVariables(const Candidate& c) const override {
    const auto it = variablesOf.find(c.name);
    return it == variablesOf.end() ? std::vector<std::string>{} : it->second;
  }
  double clearMargin() const override { return margin; }

  std::vector<std::string> namedCandidates(const std::set<std::string>& excluded) override {
    std::vector<std::string> out;
    if (excluded.count(kEveryNamedEffect)) return out;
    for (const auto& [n, s] : named)
      if (!excluded.count(n)) out.push_back(n);
    return out;
  }
  ResidualCheck roundCheck() override {
    ResidualCheck c;
    if (!xTaken) {
      StructureItem s;
      s.against = "x";
      s.form = DependenceForm::Linear;
      s.shape.against = "x";
      s.shape.form = DependenceForm::Linear;
      s.p = 1e-9;
      c.structure.push_back(s);
      c.white = false;
      c.tests.resize(4);
    }
    return c;
  }
  std::optional<LoopTrial> tryNamed(const std::string& name, int, std::size_t) override {
    return trial(name, named.at(name), std::nullopt);
  }
  std::optional<LoopTrial> tryGeneric(const GenericForm& g, double, int, std::size_t) override {
    return trial("unexplained:" + g.against, genericScore, g);
  }
  void accept(std::size_t, Candidate& c) override {
    acceptedNames.push_back(c.name);
    if (c.generic)
      xTaken = true;
    else
      named.erase(c.name);
  }
  double currentError() const override { return 1.0; }
  void finish(Diagnosis&, std::vector<Candidate*>, bool) override { ++finished; }
  double dataCriterion() const override { return 100.0; }

 private:
  static LoopTrial trial(const std::string& name, double score, std::optional<GenericForm> g) {
    LoopTrial t;
    t.candidate.name = name;
    t.candidate.score = score;
    t.candidate.generic = g;
    t.candidate.setEvidence({Phrase("scripted")});
    t.estimable = true;
    t.passes = score < 0.0;
    t.complexity = 2.0;
    return t;
  }
};

std::vector<std::string> names(const Diagnosis& d) {
  std::vector<std::string> out;
  for (const Candidate& c : d.effects) out.push_back(c.name + (c.accepted ? "*" : ""));
  return out;
}

TEST(SharedLoop, NamedBeforeGenericThenBestScoreUntilNonePasses) {
  Scripted s;
  s.named = {{"a", -5.0}, {"b", -20.0}, {"c", 3.0}};
  s.genericScore = -100.0;  // the best score, but a passing name comes first
  LoopStyle style;
  const LoopRun r = runLoop(s, style, {}, nullptr, Diagnosis{});
  EXPECT_EQ(s.acceptedNames, (std::vector<std::string>{"b", "a", "unexplained:x"}));
  // Accepted ones, then the last round's candidates (nothing passed there).
  EXPECT_EQ(names(r.diagnosis), (std::vector<std::string>{"b*", "a*", "unexplained:x*", "c"}));
  EXPECT_EQ(r.diagnosis.effects[0].round, 0);
  EXPECT_EQ(r.diagnosis.effects[2].round, 2);
  EXPECT_EQ(r.diagnosis.effects[3].round, 3);
  EXPECT_DOUBLE_EQ(r.bic, 100.0 + 3 * 2.0);
  EXPECT_EQ(s.finished, 1);
  EXPECT_FALSE(r.stopped);
}

// Issue 32 item 5 (a): a named effect is not accepted in a round where a generic effect of the
// same variable explains clearly more (its score lower by more than the domain's margin).
TEST(SharedLoop, AGenericOfTheSameVariableThatExplainsClearlyMoreIsTakenBeforeTheName) {
  Scripted s;
  s.named = {{"n", -20.0}, {"m", -15.0}};
  s.variablesOf = {{"n", {"x"}}};  // "m" is of another variable
  s.genericScore = -100.0;         // 80 below "n": clearly more than the margin 10
  LoopStyle style;
  style.listEveryRound = true;
  style.markAccepted = true;
  const LoopRun r = runLoop(s, style, {}, nullptr, Diagnosis{});
  // Round 0: "n" is not taken, "m" (no generic of its variable) is; the generic of x in round 1.
  ASSERT_GE(s.acceptedNames.size(), 2u);
  EXPECT_EQ(s.acceptedNames[0], "m");
  EXPECT_EQ(s.acceptedNames[1], "unexplained:x");
  const Candidate& n0 = r.diagnosis.effects[1];
  ASSERT_EQ(n0.name, "n");
  EXPECT_FALSE(n0.accepted);
  EXPECT_NE(
      n0.evidence.find("not taken: the generic unexplained:x of the same variable explains clearly more"),
      std::string::npos)
      << n0.evidence;
  // Without "m": the generic is accepted in the first round, and "n" may pass afterwards.
  Scripted t;
  t.named = {{"n", -20.0}};
  t.variablesOf = {{"n", {"x"}}};
  t.genericScore = -100.0;
  runLoop(t, LoopStyle{}, {}, nullptr, Diagnosis{});
  EXPECT_EQ(t.acceptedNames, (std::vector<std::string>{"unexplained:x", "n"}));
}

TEST(SharedLoop, AGenericWithinTheMarginLeavesTheNameFirst) {
  Scripted s;
  s.named = {{"n", -20.0}};
  s.variablesOf = {{"n", {"x"}}};
  s.genericScore = -29.0;  // 9 below: not clearly more with the margin 10
  runLoop(s, LoopStyle{}, {}, nullptr, Diagnosis{});
  EXPECT_EQ(s.acceptedNames, (std::vector<std::string>{"n", "unexplained:x"}));
  Scripted o;  // a generic of another variable never displaces a name
  o.named = {{"n", -20.0}};
  o.variablesOf = {{"n", {"y"}}};
  o.genericScore = -100.0;
  runLoop(o, LoopStyle{}, {}, nullptr, Diagnosis{});
  EXPECT_EQ(o.acceptedNames, (std::vector<std::string>{"n", "unexplained:x"}));
}

TEST(SharedLoop, EveryRoundListedAndMarked) {
  Scripted s;
  s.named = {{"a", -5.0}, {"b", -20.0}};
  LoopStyle style;
  style.listEveryRound = true;
  style.markAccepted = true;
  style.stopAtMaxRounds = true;
  style.maxRounds = 1;
  const LoopRun r = runLoop(s, style, {}, nullptr, Diagnosis{});
  EXPECT_EQ(names(r.diagnosis), (std::vector<std::string>{"a", "b*", "unexplained:x"}));
  EXPECT_EQ(r.diagnosis.effects[1].evidence, "accepted: scripted");
  EXPECT_EQ(r.diagnosis.effects[0].evidence, "scripted; passed, but b explains more");
  EXPECT_EQ(r.diagnosis.effects[2].evidence, "scripted");  // did not pass
}

TEST(SharedLoop, TiesAreNamedAndMaxRoundsOnlyLists) {
  Scripted s;
  s.named = {{"a", -7.0}, {"b", -7.0}};
  LoopStyle style;
  style.maxRounds = 1;  // round 1 is tried and listed, nothing accepted in it
  const LoopRun r = runLoop(s, style, {}, nullptr, Diagnosis{});
  EXPECT_EQ(names(r.diagnosis), (std::vector<std::string>{"a*", "b", "unexplained:x"}));
  EXPECT_EQ(r.diagnosis.effects[0].evidence, "scripted; indistinguishable from b with these data");
}

TEST(SharedLoop, ExcludedNamesAreNotTried) {
  Scripted s;
  s.named = {{"a", -5.0}};
  s.genericScore = -1.0;
  const LoopRun r = runLoop(s, LoopStyle{}, {kEveryNamedEffect}, nullptr, Diagnosis{});
  EXPECT_EQ(s.acceptedNames, std::vector<std::string>{"unexplained:x"});
}

TEST(SharedLoop, AStopAfterACandidateEndsTheLoopWithANote) {
  Scripted s;
  s.named = {{"a", -5.0}, {"b", -20.0}};
  int calls = 0;
  FunctionObserver stop([&](const IterationSummary&) {
    return ++calls >= 1 ? ObserverDecision::Stop : ObserverDecision::Continue;
  });
  LoopStyle style;
  style.listEveryRound = true;
  style.candidateComponent = "rmse";
  const LoopRun r = runLoop(s, style, {}, &stop, Diagnosis{});
  EXPECT_TRUE(r.stopped);
  EXPECT_TRUE(s.acceptedNames.empty());
  EXPECT_EQ(names(r.diagnosis), std::vector<std::string>{"a"});  // the one tried before the stop
  ASSERT_EQ(r.diagnosis.notes.size(), 1u);
  EXPECT_EQ(r.diagnosis.notes[0], "cancelled");
  EXPECT_EQ(s.finished, 1);
}

}  // namespace
TEST(Loop, OpenNamedEffectsAreTheNotAcceptedNotExcludedInOrder) {
  const std::vector<std::string> names{"a", "b", "c", "d"};
  EXPECT_EQ(openNamedEffects(names, {false, true, false, false}, {"d"}),
            (std::vector<std::string>{"a", "c"}));
  EXPECT_EQ(openNamedEffects(names, {}, {}), names);  // nothing accepted yet
  EXPECT_TRUE(openNamedEffects(names, {false, false, false, false}, {kEveryNamedEffect}).empty());
}

}  // namespace metrofit::diagnose
