#include "core/shapes/torus.h"

#include "core/shapes/axis_frame.h"
#include "core/shapes/refine_root.h"
#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace prism {

namespace {

// The ray's line in the torus's frame, rescaled by a power of two so that
// major + minor lies in [1, 2) (exact: the polynomial's terms stay of order
// 1 for a torus of any size) and started at its point nearest the centre (so
// that a far-away origin leaves numbers of the torus's size, as for Cone). A
// point of the line is at + s dir; its ray parameter t = (shift + s) / speed.
struct FrameLine {
  Vec3 at;
  Vec3 dir; // unit
  double shift = 0.0;
  double speed = 1.0;
  double major = 0.0;
  double minor = 0.0;
};

FrameLine frameLine(const Torus& torus, const Ray& ray) {
  const double scale = torus.frameScale;
  const Vec3 o = (torus.worldToObject * ray.origin + torus.worldToObjectOffset) * scale;
  const Vec3 d = (torus.worldToObject * ray.dir) * scale;
  FrameLine line;
  line.speed = glm::length(d);
  line.dir = d / line.speed;
  line.shift = -glm::dot(o, line.dir);
  line.at = o + line.shift * line.dir;
  line.major = torus.major * scale;
  line.minor = torus.minor * scale;
  return line;
}

// The tube function (rho - R)^2 + z^2 - r^2 of a point of the line
// (negative inside the solid; near the surface 2 r times the distance from
// it) and its derivative along the line: the well-conditioned measure of
// which side a point is on (it errs by a few u R r). The quartic is this
// times a positive factor (see below), so the two agree on every sign, but
// evaluated from its coefficients the quartic loses its sign to cancellation
// near the inner rim.
FunctionValue tubeFunction(const FrameLine& line, double s) {
  const Vec3 p = line.at + s * line.dir;
  const double rho = std::sqrt(p.x * p.x + p.y * p.y);
  const double radial = rho - line.major;
  // d(rho)/ds = (p.x d.x + p.y d.y) / rho; on the axis rho has no slope (the
  // surface is far from it there) and the root finder bisects.
  const double rhoSlope = rho > 0.0 ? (p.x * line.dir.x + p.y * line.dir.y) / rho : 0.0;
  return {(radial - line.minor) * (radial + line.minor) + p.z * p.z,
          2.0 * (radial * rhoSlope + p.z * line.dir.z)};
}

// The real roots in (lo, hi) of A s^2 + B s + C (A > 0), in increasing
// order, in the stable form.
int quadraticRoots(double A, double B, double C, double lo, double hi, double* out) {
  const double disc = B * B - 4.0 * A * C;
  if (!(disc > 0.0)) return 0;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  double r0 = q / A, r1 = q != 0.0 ? C / q : r0;
  if (r0 > r1) std::swap(r0, r1);
  int n = 0;
  for (const double r : {r0, r1})
    if (r > lo && r < hi) out[n++] = r;
  return n;
}

// The quartic: with p = at + s dir (|dir| = 1), R = major, r = minor,
//   q(s) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 (p.x^2 + p.y^2)
//        = ((rho - R)^2 + z^2 - r^2) ((rho + R)^2 + z^2 - r^2),
// whose second factor is positive for a ring torus (r < R), so q has the
// sign of the tube function. Its real roots are isolated rather than
// computed in closed form: q is monotone between consecutive roots of q',
// which are themselves bracketed by the roots of the quadratic q''. Each
// stretch between critical points where the tube function changes sign holds
// exactly one crossing, found by safeguarded Newton on the tube function.
// A grazing ray's two close roots sit on either side of a critical point,
// where the sign is read from the well-conditioned tube function (and an error in
// the critical point's place changes the value there only to second order),
// so no crossing is lost to cancellation.
//
// visit(t, entering) is called for each crossing inside `range`, in
// increasing t, until it returns false; stretches wholly outside the range
// are not refined.
template <class Visit>
void visitCrossings(const Torus& torus, const Ray& ray, Interval range, Visit&& visit) {
  const FrameLine line = frameLine(torus, ray);
  const Vec3& o = line.at;
  const Vec3& d = line.dir;
  const double R = line.major, r = line.minor;

  // Cheap rejection and the stretch to search: inside the bounding sphere and
  // the slab |z| <= r, each widened a little so no touching point is cut off.
  constexpr double kWiden = 1.0 + 0x1p-20;
  const double reach = (R + r) * kWiden;
  const double half2 = reach * reach - glm::dot(o, o);
  if (!(half2 > 0.0)) return;
  double lo = -std::sqrt(half2), hi = -lo;
  const double slab = r * kWiden;
  if (d.z != 0.0) {
    double z0 = (-slab - o.z) / d.z, z1 = (slab - o.z) / d.z;
    if (z0 > z1) std::swap(z0, z1);
    lo = std::max(lo, z0);
    hi = std::min(hi, z1);
  } else if (std::abs(o.z) > slab) {
    return;
  }
  if (!(lo < hi)) return;

  // The coefficients of q(s) = s^4 + c3 s^3 + c2 s^2 + c1 s + c0 (c0 is not
  // needed: only q's derivatives are evaluated).
  const double b = glm::dot(o, d); // 0 up to round-off, kept for exactness
  const double c = glm::dot(o, o) + (R - r) * (R + r);
  const double axy = d.x * d.x + d.y * d.y;
  const double bxy = o.x * d.x + o.y * d.y;
  const double R2 = R * R;
  const double c3 = 4.0 * b;
  const double c2 = 4.0 * b * b + 2.0 * c - 4.0 * R2 * axy;
  const double c1 = 4.0 * b * c - 8.0 * R2 * bxy;

  // The critical points of q: the roots of q'(s) = 4 s^3 + 3 c3 s^2 + 2 c2 s
  // + c1, one in each stretch between the roots of q''/2 = 6 s^2 + 3 c3 s +
  // c2 where q' changes sign.
  const auto slope = [&](double s) {
    return FunctionValue{((4.0 * s + 3.0 * c3) * s + 2.0 * c2) * s + c1,
                         (12.0 * s + 6.0 * c3) * s + 2.0 * c2};
  };
  // Newton steps of 2^-40 leave errors of order 2^-80 (times the ratio of
  // the second derivative to the first): far below round-off. A critical
  // point's place matters even less (only to second order).
  constexpr double kSettled = 0x1p-40;
  double bends[4];
  int bendCount = 0;
  bends[bendCount++] = lo;
  bendCount += quadraticRoots(6.0, 3.0 * c3, c2, lo, hi, bends + 1);
  bends[bendCount++] = hi;

  // One crossing in each monotone stretch, from one critical point (or lo)
  // to the next (or hi), whose ends lie on different sides. The critical
  // points are found as the walk reaches them, so a nearest hit found early
  // costs no more of them. t grows with s (rounding keeps the order), so a
  // stretch ending before the range holds no crossing inside it.
  const auto distance = [&](double s) { return tubeFunction(line, s); };
  const auto tOf = [&](double s) { return (line.shift + s) / line.speed; };
  double from = lo;
  double fromValue = distance(lo).value;
  // False when the walk is done.
  const auto stretchTo = [&](double to) {
    if (!(tOf(from) < range.max)) return false;
    const double toValue = distance(to).value;
    const bool inside = fromValue < 0.0, next = toValue < 0.0;
    if (next != inside && tOf(to) > range.min) {
      // Started where the chord crosses zero: Newton then needs few steps.
      const double chord = from + (to - from) * (fromValue / (fromValue - toValue));
      const double t = tOf(refineRoot(distance, from, to, inside, chord, kSettled));
      if (range.contains(t) && !visit(t, next)) return false;
    }
    from = to;
    fromValue = toValue;
    return true;
  };
  double before = slope(lo).value;
  for (int i = 1; i < bendCount; ++i) {
    const double after = slope(bends[i]).value;
    if ((before < 0.0 && after > 0.0) || (before > 0.0 && after < 0.0)) {
      const double chord = bends[i - 1] + (bends[i] - bends[i - 1]) * (before / (before - after));
      if (!stretchTo(refineRoot(slope, bends[i - 1], bends[i], before < 0.0, chord, kSettled)))
        return;
    } else if (after == 0.0 && i + 1 < bendCount) {
      if (!stretchTo(bends[i])) return;
    }
    before = after;
  }
  stretchTo(hi);
}

} // namespace

TorusCrossings torusCrossings(const Torus& torus, const Ray& ray, Interval range) {
  TorusCrossings out;
  visitCrossings(torus, ray, range, [&](double t, bool entering) {
    out.t[out.count] = t;
    out.entering[out.count] = entering;
    return ++out.count < 4;
  });
  return out;
}

bool intersect(const Torus& torus, const Ray& ray, Interval range, double& t) {
  bool found = false;
  visitCrossings(torus, ray, range, [&](double crossing, bool) {
    t = crossing;
    found = true;
    return false;
  });
  return found;
}

std::optional<std::string> torusProblem(const Vec3& center, const Vec3& axis, double major,
                                        double minor) {
  if (!isFinite(center) || !isFinite(axis) || !std::isfinite(major) || !std::isfinite(minor))
    return "not finite";
  if (!(major > 0.0) || !(minor > 0.0)) return "the radii must be positive";
  if (!(minor < major))
    return "the minor radius must be less than the major radius (horn and spindle tori are not "
           "supported)";
  if (axis == Vec3(0.0)) return "the axis is zero";
  const double scale = maxAbsComponent(axis);
  if (!std::isfinite(glm::length(axis / scale) * scale)) return "the axis is too long";
  return std::nullopt;
}

Torus makeTorus(const Vec3& center, const Vec3& axis, double major, double minor,
                const Mat3& linear, const Vec3& offset) {
  Torus torus;
  // A unit frame keeps the radii in world units.
  placeFrame(torus, frameAround(axis), center, linear, offset);
  torus.major = major;
  torus.minor = minor;
  torus.frameScale = std::ldexp(1.0, -std::ilogb(major + minor));
  torus.roundoff = frameRoundoffScale(torus.objectToWorld, torus.worldToObject,
                                      torus.objectToWorldOffset, major + minor);
  // The solid is the circle of radius major plus a ball of radius minor, so
  // along world axis i it reaches major sqrt(X_i^2 + Y_i^2) (the circle's
  // image) plus minor |row i| (the ball's) from the centre: the exact box.
  const Mat3& m = torus.objectToWorld;
  for (int i = 0; i < 3; ++i) {
    const double half =
        major * std::hypot(m[0][i], m[1][i]) + minor * std::hypot(m[0][i], m[1][i], m[2][i]);
    torus.bounds.lo[i] = torus.objectToWorldOffset[i] - half;
    torus.bounds.hi[i] = torus.objectToWorldOffset[i] + half;
  }
  return torus;
}

Vec3 normalAt(const Torus& torus, const Vec3& point) {
  const Vec3 p = torus.worldToObject * point + torus.worldToObjectOffset;
  const double rho = std::sqrt(p.x * p.x + p.y * p.y);
  // From the nearest point of the centre circle; on the axis (never on the
  // surface of a ring torus) along it.
  Vec3 g = rho > 0.0 ? Vec3(p.x * (1.0 - torus.major / rho), p.y * (1.0 - torus.major / rho), p.z)
                     : Vec3(0.0, 0.0, 1.0);
  if (g == Vec3(0.0)) g = Vec3(p.x, p.y, 0.0);
  g = torus.normalToWorld * (g / maxAbsComponent(g));
  return glm::normalize(g / maxAbsComponent(g));
}

Vec2 uvAt(const Torus& torus, const Vec3& point) {
  constexpr double kPi = 3.14159265358979323846;
  const Vec3 p = torus.worldToObject * point + torus.worldToObjectOffset;
  const double rho = std::sqrt(p.x * p.x + p.y * p.y);
  double v = std::atan2(p.z, rho - torus.major) / (2.0 * kPi);
  if (v < 0.0) v += 1.0;
  return {0.5 + std::atan2(p.y, p.x) / (2.0 * kPi), std::min(v, 1.0)};
}

bool isRound(const Torus& torus) {
  const Mat3& m = torus.objectToWorld;
  const double lx = glm::length(m[0]);
  return hasRoundSections(m) && std::abs(glm::length(m[2]) - lx) <= 1e-12 * lx;
}

} // namespace prism
