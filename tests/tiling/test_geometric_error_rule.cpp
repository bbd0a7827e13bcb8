// The tiler's geometric error of a set of vertex deviations (pack_builder.hpp): all but the
// largest 3 % lie within it, and the largest within 2.5 times it.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "tiling/pack_builder.hpp"

namespace globe::tiling {
namespace {

TEST(GeometricErrorRule, NoDeviationsIsNoError) {
  std::vector<double> none;
  EXPECT_EQ(geometricErrorOfDeviations(none), 0.0);
  std::vector<double> flat(208, 0.0);
  EXPECT_EQ(geometricErrorOfDeviations(flat), 0.0);
}

TEST(GeometricErrorRule, FewerThanThirtyThreeVerticesKeepTheLargest) {
  std::vector<double> deviations{1.0, 7.0, 3.0};  // 3 % of 3 ignores none
  EXPECT_EQ(geometricErrorOfDeviations(deviations), 7.0);
}

TEST(GeometricErrorRule, UniformDeviationsGiveNearlyTheLargest) {
  std::vector<double> deviations(208);
  std::iota(deviations.begin(), deviations.end(), 1.0);  // 1..208 m
  std::shuffle(deviations.begin(), deviations.end(), std::mt19937{7});
  // 208 x 3 % = 6.24: the 6 largest (203..208) are ignored, 202 bounds the rest.
  EXPECT_EQ(geometricErrorOfDeviations(deviations), 202.0);
}

TEST(GeometricErrorRule, ALonePeakStillCountsTwoFifths) {
  std::vector<double> deviations(208, 2.0);
  deviations[100] = 500.0;  // one vertex: a pinnacle the parent cuts off
  EXPECT_DOUBLE_EQ(geometricErrorOfDeviations(deviations), 200.0);
}

TEST(GeometricErrorRule, ACliffEdgeOfAFewVerticesIsIgnoredDownToTwoFifths) {
  std::vector<double> deviations(208, 10.0);
  for (size_t k = 0; k < 6; ++k) deviations[k * 30] = 40.0;        // a cliff's edge: 6 vertices
  EXPECT_DOUBLE_EQ(geometricErrorOfDeviations(deviations), 16.0);  // 0.4 x 40 > 10
  deviations[7] = 40.0;  // a seventh: now more than 3 %, so the cliff is the error
  EXPECT_DOUBLE_EQ(geometricErrorOfDeviations(deviations), 40.0);
}

}  // namespace
}  // namespace globe::tiling
