// The paired interval behind the report's verdicts: per-pair or per-block
// differences, mean +- t s / sqrt(n), and "cannot decide" where it spans the
// threshold.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/BenchCommon.h"

namespace {

TEST(PairedInterval, PerPairDifferencesByHand) {
  // Differences 1, 2, 3, 4: mean 2.5, s = sqrt(5/3), t(3) = 3.182.
  const drr::MeanCi d = drr::PairedDifferenceCi({11, 12, 13, 14}, {10, 10, 10, 10}, 4);
  EXPECT_DOUBLE_EQ(d.mean, 2.5);
  EXPECT_NEAR(d.halfWidth, 3.182 * std::sqrt(5.0 / 3.0) / 2.0, 1e-9);
}

TEST(PairedInterval, PairingRemovesTheSharedVariation) {
  // Two sequences that share a large frame-to-frame swing and differ by a
  // steady 0.5: unpaired intervals overlap, the paired one excludes 0.
  std::vector<double> a, b;
  for (int i = 0; i < 12; ++i) {
    const double swing = 5.0 * std::sin(i);
    a.push_back(30 + swing + 0.5 + 0.01 * (i % 3));
    b.push_back(30 + swing);
  }
  const drr::MeanCi ua = drr::BlockMeanCi(a, 6), ub = drr::BlockMeanCi(b, 6);
  EXPECT_GT(ua.mean - ua.halfWidth, 0);
  EXPECT_LT(ua.mean - ua.halfWidth, ub.mean + ub.halfWidth);  // the unpaired intervals overlap
  const drr::MeanCi d = drr::PairedDifferenceCi(a, b, 6);
  EXPECT_NEAR(d.mean, 0.51, 0.01);
  EXPECT_LT(d.halfWidth, 0.05);
  EXPECT_EQ(drr::SideOf(d, 0.0), 1);
}

TEST(PairedInterval, BlocksAverageConsecutivePairs) {
  // Six differences in three blocks of two: block means 1, 2, 3.
  const drr::MeanCi d = drr::PairedDifferenceCi({1, 1, 2, 2, 3, 3}, {0, 0, 0, 0, 0, 0}, 3);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  EXPECT_NEAR(d.halfWidth, 4.303 * 1.0 / std::sqrt(3.0), 1e-9);
}

TEST(PairedInterval, CannotDecideWhereTheIntervalSpansTheThreshold) {
  EXPECT_EQ(drr::SideOf({2.0, 0.5}, 1.0), 1);
  EXPECT_EQ(drr::SideOf({2.0, 0.5}, 3.0), -1);
  EXPECT_EQ(drr::SideOf({2.0, 0.5}, 1.8), 0);
  EXPECT_EQ(drr::SideOf({2.0, NAN}, 0.0), 0);
}

TEST(PairedInterval, NonFinitePairsAreLeftOut) {
  const drr::MeanCi d = drr::PairedDifferenceCi({1, NAN, 3, INFINITY}, {0, 0, 1, 0}, 2);
  EXPECT_DOUBLE_EQ(d.mean, 1.5);  // differences 1 and 2
  EXPECT_TRUE(std::isfinite(d.halfWidth));
  EXPECT_TRUE(std::isnan(drr::PairedDifferenceCi({1}, {0}, 2).halfWidth));
}

}  // namespace

namespace {

TEST(RoundSpread, LargestMinusSmallestOfTheFiniteRounds) {
  EXPECT_DOUBLE_EQ(drr::RoundSpread({1.5, 3.0, 2.0}), 1.5);
  EXPECT_DOUBLE_EQ(drr::RoundSpread({1.5, NAN, 2.0}), 0.5);
  EXPECT_TRUE(std::isnan(drr::RoundSpread({1.5})));  // one round: no spread of repeated runs
  EXPECT_TRUE(std::isnan(drr::RoundSpread({})));
}

}  // namespace
