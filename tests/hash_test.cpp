// core/math/hash.h against splitmix64 values computed independently (Python,
// with the reference algorithm: state += 0x9e3779b97f4a7c15, then the
// finaliser's shifts 30, 27, 31 and multipliers), so a changed constant or
// shift shows here before it changes the jitter or a generated scene.
#include "core/math/hash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace prism {
namespace {

TEST(Hash, SplitMix64SequenceFromSeedZeroIsTheReference) {
  SplitMix64 rng(0);
  EXPECT_EQ(rng.next(), 0xe220a8397b1dcdafull);
  EXPECT_EQ(rng.next(), 0x6e789e6aa1b965f4ull);
  EXPECT_EQ(rng.next(), 0x06c45d188009454full);
}

TEST(Hash, SplitMix64SequenceFromAnotherSeed) {
  SplitMix64 rng(1234567);
  EXPECT_EQ(rng.next(), 0x599ed017fb08fc85ull);
  EXPECT_EQ(rng.next(), 0x2c73f08458540fa5ull);
}

TEST(Hash, SplitMix64OfAValueIsTheSequencesFirstOutput) {
  EXPECT_EQ(splitmix64(42), 0xbdd732262feb6e95ull);
  for (const std::uint64_t x : {0ull, 1ull, 42ull, ~0ull})
    EXPECT_EQ(splitmix64(x), SplitMix64(x).next());
}

TEST(Hash, FinaliserValues) {
  EXPECT_EQ(mix64(0), 0u); // the finaliser alone fixes zero; splitmix64 adds the gamma first
  EXPECT_EQ(mix64(1), 0x5692161d100b05e5ull);
  static_assert(mix64(1) == 0x5692161d100b05e5ull, "usable at compile time");
}

TEST(Hash, CombineIsOrderDependent) {
  EXPECT_EQ(hashCombine(hashCombine(0, 1), 2), 0xef30b01c2974aeebull);
  EXPECT_EQ(hashCombine(hashCombine(0, 2), 1), 0x3ec2d42f3a45cc6eull);
}

TEST(Hash, UnitFromBitsUsesTheTop53Bits) {
  EXPECT_EQ(unitFromBits(0), 0.0);
  EXPECT_EQ(unitFromBits(std::uint64_t(1) << 63), 0.5);
  EXPECT_EQ(unitFromBits(~0ull), 1.0 - std::ldexp(1.0, -53)); // never 1
  EXPECT_EQ(unitFromBits(0x7ff), 0.0);                        // the low 11 bits are dropped
}

TEST(Hash, UniformStaysInItsInterval) {
  SplitMix64 rng(7);
  for (int i = 0; i < 10000; ++i) {
    const double u = rng.uniform(-2.0, 3.0);
    EXPECT_GE(u, -2.0);
    EXPECT_LT(u, 3.0);
  }
  SplitMix64 a(0), b(0);
  EXPECT_EQ(a.uniform(), unitFromBits(b.next()));
}

} // namespace
} // namespace prism
