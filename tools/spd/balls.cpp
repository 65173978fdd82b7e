// balls: a sphereflake on a ground square. Every sphere carries nine spheres a
// third its size, touching it on the side away from its parent: six in a ring
// a little above its equator and three higher up, so a flake of level L holds
// 1 + 9 + ... + 9^L = (9^(L+1) - 1) / 8 spheres. Each sphere with children is
// a push/pop group around them, the hierarchy `--accel groups` follows.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

long spheresUpTo(int level) {
  long count = 0, layer = 1;
  for (int k = 0; k <= level; ++k, layer *= 9)
    count += layer;
  return count;
}

long primitives(int level) { return spheresUpTo(level) + 1; } // and the ground

// The sphere at `centre` and its descendants; `axis` (unit) points away from
// its parent.
void flake(ScWriter& out, V3 centre, double radius, V3 axis, int level) {
  out.sphere(centre, radius);
  if (level == 0) return;
  const Frame f = frameAround(axis);
  const double child = radius / 3, reach = radius + child;
  out.push();
  // The ring sits 10 degrees above the equator so the children of a root on
  // the ground stay clear of it; the upper three fill the gaps of the ring.
  for (int k = 0; k < 6; ++k) {
    const V3 d = direction(f, radians(80), radians(60.0 * k));
    flake(out, centre + reach * d, child, d, level - 1);
  }
  for (int k = 0; k < 3; ++k) {
    const V3 d = direction(f, radians(35), radians(120.0 * k + 30));
    flake(out, centre + reach * d, child, d, level - 1);
  }
  out.pop();
}

void write(ScWriter& out, int level) {
  out.stage({.eye = {4.2, 3.1, 5.4},
             .lookat = {0, 0.95, 0},
             .fov = 40,
             .lights = {{{6, 9, 5}, 160}, {{-7, 4, 6}, 50}, {{1, 3, -8}, 30}},
             .background = {0.06, 0.08, 0.14},
             .ambient = 0.08});
  out.surface(plastic(0.55, 0.55, 0.5, 0.1, 10));
  groundSquare(out, 12);
  out.surface(metal(0.9, 0.72, 0.45, 0.5));
  flake(out, {0, 1, 0}, 1, {0, 1, 0}, level);
}

} // namespace

SpdKind ballsKind() {
  return {"balls",
          "a sphereflake of reflective spheres on a ground square",
          "levels of children (1 + 9 + ... + 9^L spheres)",
          0,
          7,
          primitives,
          write};
}

} // namespace prism::spd
