#include "core/texture/pattern.h"

#include "core/texture/noise.h"

#include <cmath>

namespace prism {

namespace {

constexpr double kPi = 3.14159265358979323846;

// floor(x) mod 2, as 0 or 1, without converting to an integer type (a
// coordinate divided by a small scale may be beyond any integer's range;
// beyond 2^53 every double is even and this gives 0).
double parity(double x) {
  const double f = std::floor(x);
  return f - 2.0 * std::floor(0.5 * f);
}

double fraction(double x) { return x - std::floor(x); }

// [0, 1], and 0 for NaN: nothing a pattern computes can reach a pixel as NaN.
double unitClamp(double v) { return v >= 0.0 ? (v <= 1.0 ? v : 1.0) : 0.0; }

} // namespace

double patternValue(TextureKind kind, const Vec3& p) {
  if (!isFinite(p)) return 0.0;
  switch (kind) {
  case TextureKind::None: return 0.0;
  case TextureKind::Checker: return parity(parity(p.x) + parity(p.y) + parity(p.z));
  case TextureKind::Stripes: return parity(p.x);
  case TextureKind::Gradient: return unitClamp(fraction(p.x));
  case TextureKind::Noise: return unitClamp(0.5 + 0.5 * fractalNoise(p));
  case TextureKind::Marble: {
    // 1 on thin veins where the sine crosses 0, falling steeply off them.
    const double s = 1.0 - std::abs(std::sin(kPi * (p.x + kMarbleSwirl * turbulence(p))));
    return unitClamp(s * s * s);
  }
  case TextureKind::Wood:
    return unitClamp(fraction(std::sqrt(p.x * p.x + p.y * p.y) + kWoodWobble * turbulence(p)));
  }
  return 0.0;
}

} // namespace prism
