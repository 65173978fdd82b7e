// Refining a bracketed root of a function of one variable: safeguarded
// Newton (Numerical Recipes' rtsafe), shared by the kinds whose crossings are
// roots of polynomials (tori, blobs).
#pragma once

#include <cmath>

namespace prism {

// A function's value and its derivative at a point.
struct FunctionValue {
  double value;
  double slope;
};

// The root of f (which returns a FunctionValue) in [a, b], where f is negative at a
// exactly when `negativeAtA` and of the other sign at b: Newton steps while
// they stay in the bracket and shrink fast, bisection otherwise, from
// `start` if it lies inside. Stops after a Newton step shorter than
// `settled` (the step after it would be of the order of its square), or at
// the precision of the numbers (the callers keep |x| <= 2, so an absolute
// 2^-56 is a tenth of their round-off).
template <class F>
double refineRoot(F f, double a, double b, bool negativeAtA, double start, double settled) {
  double x = start > a && start < b ? start : 0.5 * (a + b);
  double step = b - a;
  for (int i = 0; i < 200; ++i) {
    const FunctionValue v = f(x);
    if (v.value == 0.0) return x;
    ((v.value < 0.0) == negativeAtA ? a : b) = x;
    if (b - a <= 0x1p-56) break;
    const double newton = v.slope != 0.0 ? v.value / v.slope : 0.0;
    double next = x - newton;
    if (v.slope != 0.0 && next > a && next < b && std::abs(newton) < 0.5 * std::abs(step)) {
      if (std::abs(newton) <= settled) return next;
      step = newton;
    } else {
      next = 0.5 * (a + b);
      step = 0.5 * (b - a);
      if (!(next > a && next < b)) break;
    }
    if (next == x) break;
    x = next;
  }
  return x;
}

} // namespace prism
