// The exact sum behind avgmax (core/math/exact_sum.h): hand-computed sums a
// double accumulator gets wrong, the same value for any order and any split
// into parts, and the extremes of the float range.
#include "core/math/exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace prism {
namespace {

double sumOf(const std::vector<float>& values) {
  ExactSum sum;
  for (float v : values)
    sum.add(v);
  return sum.value();
}

TEST(ExactSum, KeepsWhatADoubleAccumulatorRoundsAway) {
  // 2^53 + 1 + 1: a double adding in this order rounds each 1 away (to
  // even) and ends at 2^53; the exact sum 2^53 + 2 is a double.
  const float big = std::ldexp(1.0f, 53);
  double naive = 0.0;
  for (float v : {big, 1.0f, 1.0f})
    naive += double(v);
  EXPECT_EQ(naive, std::ldexp(1.0, 53));
  EXPECT_EQ(sumOf({big, 1.0f, 1.0f}), std::ldexp(1.0, 53) + 2.0);
  EXPECT_EQ(sumOf({1.0f, 0.5f, 0.25f, 3.0f}), 4.75);
  EXPECT_EQ(sumOf({}), 0.0);
  EXPECT_EQ(sumOf({0.0f, -0.0f}), 0.0);
}

TEST(ExactSum, SubnormalsAndTheLargestFloatAddUpExactly) {
  const float tiny = std::numeric_limits<float>::denorm_min(); // 2^-149
  EXPECT_EQ(sumOf({tiny, tiny, tiny}), 3.0 * std::ldexp(1.0, -149));
  const float smallestNormal = std::numeric_limits<float>::min(); // 2^-126
  EXPECT_EQ(sumOf({smallestNormal, tiny}), std::ldexp(1.0, -126) + std::ldexp(1.0, -149));
  const float largest = std::numeric_limits<float>::max();
  // 1000 times the largest float: no overflow, the exact product.
  EXPECT_EQ(sumOf(std::vector<float>(1000, largest)), 1000.0 * double(largest));
}

TEST(ExactSum, AnyOrderAndAnySplitGiveTheSameDouble) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
  std::uniform_int_distribution<int> exponent(-140, 120);
  std::vector<float> values(20000);
  for (float& v : values)
    v = std::ldexp(mantissa(random), exponent(random));
  const double reference = sumOf(values);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(values.begin(), values.end(), random);
    EXPECT_EQ(sumOf(values), reference);
    // In three parts, as three processes would, combined in either order.
    ExactSum parts[3];
    for (std::size_t i = 0; i < values.size(); ++i)
      parts[(i * 7 + std::size_t(trial)) % 3].add(values[i]);
    ExactSum forward = parts[0], backward = parts[2];
    forward += parts[1];
    forward += parts[2];
    backward += parts[1];
    backward += parts[0];
    EXPECT_EQ(forward.value(), reference);
    EXPECT_EQ(backward.value(), reference);
  }
}

} // namespace
} // namespace prism
