// lattice: an n x n x n cubic lattice of mirror spheres joined along the three
// axes by cylinders (open cones of equal radii), floating over a floor: n^3
// spheres, 3 n^2 (n - 1) cylinders and the floor. The lattice keeps its size,
// so a larger n packs it finer; inside it every ray meets a thicket of curved
// surfaces reflecting each other.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr double kSide = 6.0; // of the lattice, centre to centre of its corner spheres

long primitives(int n) { return long(n) * n * n + 3L * n * n * (n - 1) + 1; }

void write(ScWriter& out, int n) {
  const double step = kSide / (n - 1), sphere = 0.25 * step, rod = 0.08 * step;
  out.stage({.eye = {8.5, 7.2, 11.5},
             .lookat = {0, 0.2, 0},
             .fov = 42,
             .lights = {{{10, 14, 8}, 400}, {{-12, 5, 6}, 150}, {{0, -2, 14}, 60}},
             .background = {0.08, 0.08, 0.1},
             .ambient = 0.1});
  out.surface(plastic(0.5, 0.5, 0.55, 0.2, 15));
  groundSquare(out, 16, -0.5 * kSide - 1.2);
  auto at = [&](int i, int j, int k) {
    return V3{step * i - 0.5 * kSide, step * j - 0.5 * kSide, step * k - 0.5 * kSide};
  };
  // One group per layer of the lattice, for `--accel groups`.
  for (int j = 0; j < n; ++j) {
    out.push();
    out.surface(metal(0.8, 0.82, 0.88, 0.6));
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        out.sphere(at(i, j, k), sphere);
    out.surface(plastic(0.2, 0.45, 0.9, 0.3, 40));
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) {
        if (i + 1 < n) out.cone(at(i, j, k), rod, at(i + 1, j, k), rod);
        if (k + 1 < n) out.cone(at(i, j, k), rod, at(i, j, k + 1), rod);
        if (j + 1 < n) out.cone(at(i, j, k), rod, at(i, j + 1, k), rod);
      }
    out.pop();
  }
}

} // namespace

SpdKind latticeKind() {
  return {"lattice",
          "a cubic lattice of mirror spheres joined by cylinders",
          "spheres per edge of the cube (n^3 spheres + 3 n^2 (n-1) cylinders + 1 polygon)",
          2,
          60,
          primitives,
          write};
}

} // namespace prism::spd
