// jacks: jacks scattered on a floor, each three crossed cylinders (open cones
// of equal radii) with a sphere on each of the six ends: 9 primitives a jack,
// and the floor. The level is the number of jacks; they are spread over a
// disc whose area grows with their number, each turned at random and resting
// on the floor on its lowest end, so they cross and touch one another.
#include "core/math/hash.h"

#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr double kArm = 0.5, kRod = 0.045, kBall = 0.1;

long primitives(int jacks) { return 9L * jacks + 1; }

// A rotation drawn uniformly (Shoemake's unit quaternion from three uniform
// numbers), as the images of the three axes.
void randomAxes(SplitMix64& rng, V3 (&axes)[3]) {
  const double u1 = rng.uniform(), u2 = 2 * kPi * rng.uniform(), u3 = 2 * kPi * rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3),
               w = b * std::cos(u3);
  axes[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  axes[1] = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  axes[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
}

void write(ScWriter& out, int jacks) {
  // About 0.55 jacks per unit of area, whatever their number.
  const double radius = std::sqrt(jacks / (0.55 * kPi)) + 0.5, view = radius + 1.5;
  out.stage({.eye = {0.25 * view, 1.05 * view + 1, 1.35 * view + 1},
             .lookat = {0, 0, 0.1 * view},
             .fov = 45,
             .lights = {{{0.8 * view, 2 * view, 1.2 * view}, 6 * view * view},
                        {{-1.8 * view, 1.2 * view, 0.5 * view}, 2 * view * view}},
             .background = {0.06, 0.06, 0.08},
             .ambient = 0.1});
  out.surface(metal(0.3, 0.35, 0.4, 0.35));
  groundSquare(out, 3 * view);
  const Surface colours[3] = {metal(0.9, 0.2, 0.15, 0.3), metal(0.2, 0.5, 0.95, 0.3),
                              metal(0.95, 0.8, 0.2, 0.3)};
  SplitMix64 rng(0x6a61636b73);
  for (int j = 0; j < jacks; ++j) {
    const double r = radius * std::sqrt(rng.uniform()), a = 2 * kPi * rng.uniform();
    V3 axes[3];
    randomAxes(rng, axes);
    double lowest = 0;
    for (const V3& axis : axes)
      lowest = std::fmax(lowest, kArm * std::fabs(axis.y));
    const V3 centre{r * std::cos(a), kBall + lowest, r * std::sin(a)};
    out.push();
    out.surface(colours[j % 3]);
    for (const V3& axis : axes) {
      const V3 end0 = centre - kArm * axis, end1 = centre + kArm * axis;
      out.cone(end0, kRod, end1, kRod);
      out.sphere(end0, kBall);
      out.sphere(end1, kBall);
    }
    out.pop();
  }
}

} // namespace

SpdKind jacksKind() {
  return {"jacks",
          "jacks of three cylinders and six balls scattered on a floor",
          "jacks (9 J + 1 primitives)",
          1,
          200000,
          primitives,
          write};
}

} // namespace prism::spd
