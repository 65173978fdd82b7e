#include "core/math/exact_sum.h"

#include <cmath>

namespace prism {

double ExactSum::value() const {
  // Carries move each count's excess into the next exponent up, leaving the
  // unique form in which every count but the last is 0 or 1: the binary
  // digits of the sum. Summed from the smallest digit up in doubles, each
  // step rounds the same way for the same digits.
  std::array<std::int64_t, kBins> digits = bins_;
  for (std::size_t i = 1; i + 1 < digits.size(); ++i) {
    digits[i + 1] += digits[i] >> 1;
    digits[i] &= 1;
  }
  double sum = 0.0;
  for (std::size_t i = 1; i < digits.size(); ++i)
    if (digits[i] != 0) sum += std::ldexp(double(digits[i]), int(i) - 150);
  return sum;
}

} // namespace prism
