// splitmix64 (Steele, Lea and Flood; Vigna's reference code): the one mixing
// function behind every hash and random sequence Prism makes itself, the
// material table's key hash, the sub-pixel jitter and the scene generators.
// Fixed integer arithmetic, so the same numbers on every platform and standard
// library (std::hash and std::*_distribution are not). Header only, standard
// library only, so the generators in tools/ that link nothing can use it.
#pragma once

#include <cstdint>

namespace prism {

// The increment of splitmix64's state: 2^64 divided by the golden ratio, odd.
inline constexpr std::uint64_t kSplitMixGamma = 0x9e3779b97f4a7c15ull;

// splitmix64's finaliser: every input bit affects every output bit.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// The output of a splitmix64 generator whose state was `x` before its step:
// a hash of one 64-bit value.
constexpr std::uint64_t splitmix64(std::uint64_t x) { return mix64(x + kSplitMixGamma); }

// Folds `value` into the running hash `seed` (order matters).
constexpr std::uint64_t hashCombine(std::uint64_t seed, std::uint64_t value) {
  return mix64(seed ^ value);
}

// The top 53 bits as a double in [0, 1): every value a multiple of 2^-53.
constexpr double unitFromBits(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

// The splitmix64 random sequence from `seed`.
class SplitMix64 {
public:
  explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}
  constexpr std::uint64_t next() { return mix64(state_ += kSplitMixGamma); }
  constexpr double uniform() { return unitFromBits(next()); } // [0, 1)
  constexpr double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
  std::uint64_t state_;
};

} // namespace prism
