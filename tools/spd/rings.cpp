// rings: a square pyramid of rings on a floor. A ring is a 12-sided loop of
// cylinders (open cones of equal radii) with a sphere at each corner to round
// the joints: 24 primitives. A pyramid of L layers (the level) has L^2 rings at
// the bottom, (L-1)^2 above them, ..., 1 at the top: L(L+1)(2L+1)/6 rings.
// Neighbouring rings lie in different planes, so the pyramid is a tangle of
// curved surfaces that shadow and reflect each other.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr int kSides = 12;
constexpr double kRing = 1.0, kTube = 0.17, kSpacing = 2.45;

long rings(int layers) { return long(layers) * (layers + 1) * (2 * layers + 1) / 6; }
long primitives(int layers) { return 2 * kSides * rings(layers) + 1; }

void ring(ScWriter& out, V3 centre, V3 axis) {
  const Frame f = frameAround(axis);
  V3 corners[kSides];
  for (int k = 0; k < kSides; ++k) {
    const double a = 2 * kPi * k / kSides;
    corners[k] = centre + kRing * std::cos(a) * f.u + kRing * std::sin(a) * f.v;
  }
  out.push();
  for (int k = 0; k < kSides; ++k) {
    out.sphere(corners[k], kTube);
    out.cone(corners[k], kTube, corners[(k + 1) % kSides], kTube);
  }
  out.pop();
}

void write(ScWriter& out, int layers) {
  const double size = kSpacing * layers; // width and height of the pyramid
  out.stage(
      {.eye = {1.2 * size + 2, 0.9 * size + 2, 1.75 * size + 3},
       .lookat = {0, 0.38 * size, 0},
       .fov = 40,
       .lights = {{{1.5 * size + 3, 2.5 * size + 4, 1.2 * size + 4}, 9 * (size + 2) * (size + 2)},
                  {{-2 * size - 4, 1.2 * size + 3, 1.5 * size + 3}, 4 * (size + 2) * (size + 2)}},
       .background = {0.05, 0.05, 0.08},
       .ambient = 0.08});
  out.surface(plastic(0.5, 0.5, 0.55, 0.3, 20));
  groundSquare(out, 3 * size + 6);
  const Surface colours[4] = {metal(0.9, 0.25, 0.2, 0.35), metal(0.25, 0.8, 0.3, 0.35),
                              metal(0.25, 0.4, 0.95, 0.35), metal(0.95, 0.8, 0.25, 0.35)};
  const V3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int layer = 0; layer < layers; ++layer) {
    const int side = layers - layer;
    out.surface(colours[layer % 4]);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const V3 centre{kSpacing * (i - 0.5 * (side - 1)), kRing + kTube + kSpacing * layer,
                        kSpacing * (j - 0.5 * (side - 1))};
        // The top ring stands, so it does not float above the layer below.
        ring(out, centre, axes[side == 1 ? 2 : (i + j + layer) % 3]);
      }
  }
}

} // namespace

SpdKind ringsKind() {
  return {"rings",
          "a pyramid of rings of spheres and cylinders on a floor",
          "layers of the pyramid (24 L(L+1)(2L+1)/6 + 1 primitives)",
          1,
          40,
          primitives,
          write};
}

} // namespace prism::spd
