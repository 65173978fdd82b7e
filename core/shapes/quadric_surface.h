// General quadric surfaces clipped by a box: the .sc `quadric`, the points
//   A x^2 + B y^2 + C z^2 + D xy + E yz + F xz + G x + H y + I z + J = 0
// of the quadric's own frame that lie in the clip box lo <= x <= hi, carried
// into the world by an affine map (the current transform), so paraboloids,
// hyperboloids, elliptic cones and cylinders of any section, in any pose.
//
// The surface is open (the box cuts it) and two-sided: it bounds no solid,
// so it is no CSG operand (no appendCrossings), and a ray leaving it can meet
// it again (kFlat is false). Its outward side is where the polynomial is
// positive (POV-Ray's convention: negative inside).
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/affine_frame.h"
#include "core/shapes/primitives.h"

#include <array>
#include <optional>
#include <string>

namespace prism {

struct Quadric {
  static constexpr const char* kName = "quadric";
  static constexpr bool kFlat = false; // open, two-sided: a ray can meet it again

  AffineFrame frame;
  // A, B, C, D (xy), E (yz), F (xz), G, H, I, J in the frame, as given times
  // a power of two (the same surface, exactly) that brings the largest of
  // |A| L^2 .. |F| L^2, |G| L .. |I| L, |J| into [1, 2), L the clip box's
  // largest coordinate: the intersection's numbers are then of order 1 at
  // any scale, and its products cannot overflow.
  std::array<double, 10> coef{1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0};
  int exponent = 0; // coef = given * 2^exponent (givenCoefficients undoes it)
  Vec3 lo{-1.0};    // the clip box in the frame
  Vec3 hi{1.0};
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  Aabb bounds; // the clip box's image: its 8 corners carried to the world
  std::uint32_t material = 0;
  Origin origin;
};

// Why these coefficients and clip corners cannot make a quadric (not finite,
// A to I all zero so there is no surface, a clip box without volume), or
// nothing if they can.
std::optional<std::string> quadricProblem(const std::array<double, 10>& coef, const Vec3& corner0,
                                          const Vec3& corner1);

// The quadric with these coefficients clipped by the box with opposite
// corners `corner0` and `corner1` (in any order), all in its own frame, then
// carried by x -> linear x + offset. Requires quadricProblem to find nothing
// and `linear` to be invertible; the coefficients are rescaled (see Quadric).
Quadric makeQuadric(const std::array<double, 10>& coef, const Vec3& corner0, const Vec3& corner1,
                    const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0));

// The coefficients as they were given (what the writers write).
std::array<double, 10> givenCoefficients(const Quadric& q);

// The polynomial and its gradient at a point of the frame.
double quadricValue(const Quadric& q, const Vec3& p);
Vec3 quadricGradient(const Quadric& q, const Vec3& p);

// The nearest t inside `range` where the ray meets the surface inside the
// clip box: the roots in increasing order, the first inside both kept (a ray
// may enter the box, pass a root outside it and meet the second inside). A
// tangent ray touches at its double root; a ray lying in the surface (a line
// of a cylinder or a cone) meets it nowhere.
bool intersect(const Quadric& q, const Ray& ray, Interval range, double& t);

// The unit normal toward the positive side: the frame's gradient carried by
// the inverse transpose. Where the gradient vanishes (a cone's apex, the line
// where two planes meet) the frame's z axis carried the same way.
Vec3 normalAt(const Quadric& q, const Vec3& point);

// Around the frame's z axis through the clip box's centre as a fraction of a
// turn (0.5 toward +x, growing toward +y, as for Cone), and the height in
// the box: u = turnFraction(x - cx, y - cy), v = (z - lo.z) / (hi.z - lo.z).
// Natural for the shapes written around z (dishes, towers, cones and
// cylinders along z).
Vec2 uvAt(const Quadric& q, const Vec3& point);

inline Aabb boundsOf(const Quadric& q) { return q.bounds; }

// True when the frame is the identity, so the quadric is written without a
// placing transform.
bool isUnplaced(const Quadric& q);

} // namespace prism
