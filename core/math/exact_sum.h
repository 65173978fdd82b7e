// The exact sum of non-negative finite floats, the same whatever order they
// are added in and however the additions are split between threads or
// processes: avgmax must be bit-for-bit the same for one process and for any
// number of MPI ranks (docs/distributed.md), and a double accumulated in
// pixel order cannot be split into parts and recombined without rounding
// differently.
//
// A float is m * 2^(e - 150) with an integer m < 2^24 and e its biased
// exponent (1 for subnormals), so the sum is kept as one integer count of
// m's per exponent: adding is integer addition, which is exact and
// associative, and two sums combine by adding their counts (an MPI_SUM over
// int64 is a valid reduction of them). Each count holds 2^39 additions before
// it could overflow: far more pixels than any picture has.
#pragma once

#include <array>
#include <bit>
#include <cstdint>

namespace prism {

class ExactSum {
public:
  static constexpr int kBins = 256; // one per biased float exponent

  // `x` must be finite and not negative (a negative zero counts as zero).
  void add(float x) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(x) & 0x7fffffffu;
    const std::uint32_t exponent = bits >> 23, fraction = bits & 0x7fffffu;
    if (exponent == 0)
      bins_[1] += fraction; // subnormal: the same scale as exponent 1
    else
      bins_[exponent] += std::int64_t(fraction | 0x800000u);
  }

  ExactSum& operator+=(const ExactSum& other) {
    for (int i = 0; i < kBins; ++i)
      bins_[std::size_t(i)] += other.bins_[std::size_t(i)];
    return *this;
  }

  // The sum as a double: a function of the exact value alone (so equal sums
  // give equal doubles), within a few units in the last place of it.
  double value() const;

  // For reductions across processes: kBins counts.
  std::int64_t* data() { return bins_.data(); }

private:
  std::array<std::int64_t, kBins> bins_{};
};

} // namespace prism
