// hfield: a height field of N x N squares, each cut into two triangles
// (2 N^2 triangles, N the level), over a square of side 12: a landscape summed
// from a few sines, with a mirror lake below height 0, grass above it and
// snow on the peaks. The surface is the same at every N, only finer.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

constexpr double kHalf = 6;

long primitives(int n) { return 2L * n * n; }

double height(double x, double z) {
  return 0.9 * std::sin(0.55 * x + 0.4) * std::cos(0.45 * z - 0.3) +
         0.45 * std::sin(1.1 * x + 0.9 * z + 1.3) + 0.22 * std::sin(2.3 * x - 1.9 * z + 0.2) +
         0.11 * std::cos(4.1 * x + 3.3 * z) + 0.2;
}

// Lake, grass or snow, by the mean height of a triangle.
int zone(double y) { return y < 0 ? 0 : (y < 1.0 ? 1 : 2); }

void write(ScWriter& out, int n) {
  out.stage({.eye = {0, 7.5, 13},
             .lookat = {0, 0, 0.5},
             .fov = 45,
             .lights = {{{-8, 12, 6}, 350}, {{10, 5, 8}, 90}},
             .background = {0.5, 0.65, 0.9},
             .ambient = 0.12});
  const Surface zones[3] = {metal(0.15, 0.3, 0.5, 0.6), plastic(0.3, 0.55, 0.2, 0.05, 10),
                            plastic(0.95, 0.95, 1.0, 0.2, 30)};
  const double step = 2 * kHalf / n;
  auto at = [&](int i, int j) {
    const double x = -kHalf + step * i, z = -kHalf + step * j;
    return V3{x, height(x, z), z};
  };
  int current = -1;
  auto use = [&](double meanY) {
    const int z = zone(meanY);
    if (z != current) out.surface(zones[current = z]);
  };
  for (int j = 0; j < n; ++j) {
    out.push(); // a row, for `--accel groups`
    current = -1;
    for (int i = 0; i < n; ++i) {
      const V3 p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
      // Both counterclockwise seen from above.
      use((p00.y + p11.y + p10.y) / 3);
      out.triangle(p00, p11, p10);
      use((p00.y + p01.y + p11.y) / 3);
      out.triangle(p00, p01, p11);
    }
    out.pop();
  }
}

} // namespace

SpdKind hfieldKind() {
  return {"hfield",
          "a height field of triangles: lake, grass and snow",
          "squares per side of the grid (2 N^2 triangles)",
          1,
          1000,
          primitives,
          write};
}

} // namespace prism::spd
