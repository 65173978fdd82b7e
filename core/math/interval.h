// An open range of ray parameters (min, max). Every intersection query takes one,
// so the valid part of a ray is decided in a single place.
#pragma once

#include <limits>

namespace prism {

struct Interval {
  double min = 0.0;
  double max = std::numeric_limits<double>::infinity();

  bool contains(double t) const { return min < t && t < max; }
};

} // namespace prism
