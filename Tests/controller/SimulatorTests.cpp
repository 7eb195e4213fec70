// The simulator's core as a library: the headline claims of Docs/Controller.md.
#include "ControllerSimCore.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace drr;
using namespace drr::sim;

const SimResult& Find(const std::vector<SimResult>& rs, std::string_view c, std::string_view s) {
  for (const SimResult& r : rs)
    if (r.controller == c && r.scenario == s) return r;
  static SimResult none;
  ADD_FAILURE() << "missing " << c << "/" << s;
  return none;
}

class Headline : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    results = new std::vector<SimResult>(RunMatrix(AllLaws(), AllScenarios(), SimConfig{}));
  }
  static void TearDownTestSuite() { delete results; }
  static std::vector<SimResult>* results;
};
std::vector<SimResult>* Headline::results = nullptr;

TEST_F(Headline, RobustSettlesStepsWithin20Frames) {
  for (const char* s : {"step2x", "step-half", "vsync60"}) {
    const SimResult& r = Find(*results, "robust", s);
    EXPECT_GE(r.settleFrames, 0) << s;
    EXPECT_LE(r.settleFrames, 20) << s;
  }
  // and faster than the article law on the 2x step
  const SimResult& a = Find(*results, "article", "step2x");
  EXPECT_TRUE(a.settleFrames < 0 || a.settleFrames > Find(*results, "robust", "step2x").settleFrames);
}

TEST_F(Headline, RobustNeverChangesUnderAStillLoad) {
  for (Scenario s : AllScenarios()) EXPECT_EQ(Find(*results, "robust", ToString(s)).stillChanges, 0) << ToString(s);
  EXPECT_EQ(Find(*results, "robust", "still").changes, 0);
  // the article law swims where the others hold (spikes, nan, cpu-bound)
  int article = 0;
  for (Scenario s : AllScenarios()) article += Find(*results, "article", ToString(s)).stillChanges;
  EXPECT_GT(article, 0);
}

TEST_F(Headline, RobustHasFewerFramesOverBudgetThanUEStyleAndArticle) {
  const auto totals = Summarise(*results);
  int article = -1, ue = -1, robust = -1;
  for (const Totals& t : totals) {
    if (t.controller == "article") article = t.overBudget;
    if (t.controller == "ue-style") ue = t.overBudget;
    if (t.controller == "robust") robust = t.overBudget;
  }
  EXPECT_LT(robust, ue);
  EXPECT_LT(robust, article);
  EXPECT_LE(Find(*results, "robust", "step2x").overBudget, Find(*results, "ue-style", "step2x").overBudget);
}

TEST_F(Headline, RobustIgnoresSpikesNaNAndCpuBoundFrames) {
  for (const char* s : {"spikes", "nan", "cpu-bound", "still"}) {
    const SimResult& r = Find(*results, "robust", s);
    EXPECT_EQ(r.changes, 0) << s;
    EXPECT_EQ(r.settleFrames, 0) << s;
    EXPECT_EQ(r.overBudget, 0) << s;
  }
}

TEST(Simulator, DeterministicForASeed) {
  const auto a = RunMatrix({ControlLaw::Robust, ControlLaw::Article}, AllScenarios(), SimConfig{});
  const auto b = RunMatrix({ControlLaw::Robust, ControlLaw::Article}, AllScenarios(), SimConfig{});
  std::ostringstream ca, cb;
  WriteCsv(ca, a);
  WriteCsv(cb, b);
  EXPECT_EQ(ca.str(), cb.str());
  EXPECT_NE(ca.str().find("robust,step2x"), std::string::npos);
}

TEST(Simulator, SweepFindsTheAnalyticInstability) {
  const SimConfig base;
  const double alpha = ArticleAlpha(base.plant, base.target);
  const auto rows = SweepArticleGain(base, 4);
  ASSERT_EQ(rows.size(), 17u);
  for (const SweepRow& r : rows) {
    const bool unstable = r.verdict.rfind("unstable", 0) == 0;
    if (r.gain < 0.5 / alpha) {
      EXPECT_FALSE(unstable) << r.gain;  // 0 < 1 - 2 k alpha < 1: no alternation
    }
    if (r.gain > 1.5 / alpha) {
      EXPECT_TRUE(unstable) << r.gain;  // clearly past 1/alpha
    }
    EXPECT_NEAR(r.multiplier, 1.0 - 2.0 * r.gain * alpha, 1e-12);
  }
  std::ostringstream out;
  PrintSweep(out, rows, base);
  EXPECT_NE(out.str().find("First unstable gain"), std::string::npos);
}

TEST(Simulator, TableAndCsvHaveEveryRow) {
  const auto rs = RunMatrix({ControlLaw::Robust}, AllScenarios(), SimConfig{});
  std::ostringstream table, csv;
  PrintTable(table, rs);
  WriteCsv(csv, rs);
  for (Scenario s : AllScenarios()) {
    EXPECT_NE(table.str().find(std::string(ToString(s))), std::string::npos);
    EXPECT_NE(csv.str().find("robust," + std::string(ToString(s))), std::string::npos);
  }
}

}  // namespace
