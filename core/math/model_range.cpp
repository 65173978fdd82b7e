#include "core/math/model_range.h"

#include <algorithm>

namespace prism {

namespace {

// The Frobenius norm, scaled by the largest entry so no square under- or
// overflows.
double frobenius(const Mat3& m) {
  double largest = 0.0;
  for (int i = 0; i < 3; ++i)
    largest = std::max({largest, std::abs(m[i].x), std::abs(m[i].y), std::abs(m[i].z)});
  if (!(largest > 0.0) || !std::isfinite(largest)) return largest;
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 c = m[i] / largest;
    sum += glm::dot(c, c);
  }
  return largest * std::sqrt(sum);
}

} // namespace

double stretchRatioBound(const Mat3& m) {
  // Scaled by a power of two (exactly) so the inverse cannot overflow merely
  // because the map is uniformly tiny.
  const double size = frobenius(m);
  if (!(size > 0.0) || !std::isfinite(size)) return std::numeric_limits<double>::infinity();
  const Mat3 unit = m * std::ldexp(1.0, -std::ilogb(size));
  const double det = glm::determinant(unit);
  if (!(det != 0.0) || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  return frobenius(unit) * frobenius(glm::inverse(unit));
}

} // namespace prism
