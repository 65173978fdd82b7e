// gears: a square grid of meshing spur gears above a mirror floor. Each gear's
// top and bottom faces are single concave polygons of 144 vertices (36 teeth of
// 4 vertices: up the flank, across the tip, down the flank, along the root),
// joined by 144 side quads, one per outline edge: 146 polygons a gear. An
// n x n grid (the level) holds 146 n^2 + 1 polygons with the floor. These big
// concave polygons are the point of the scene: a ray that reaches one has to
// decide inside or outside against many edges.
#include "scene_parts.h"
#include "spd_kinds.h"

#include <vector>

namespace prism::spd {
namespace {

constexpr int kTeeth = 36;
constexpr double kRoot = 0.9, kTip = 1.0; // radii of the tooth outline
constexpr double kThickness = 0.25, kLift = 0.35;

long primitives(int level) { return 146L * level * level + 1; }

// The outline in the gear's plane, counterclockwise seen from above (angle
// growing from +x towards -z), turned by `phase` degrees. A tooth takes 10
// degrees: flank 3, tip 2, flank 3, root 2. Tooth and gap are the same shape,
// so a neighbour turned half a tooth meshes with it at the distance
// kRoot + kTip.
std::vector<V3> outline(V3 centre, double phase) {
  std::vector<V3> v;
  const double steps[4] = {0, 3, 5, 8};
  for (int t = 0; t < kTeeth; ++t)
    for (int k = 0; k < 4; ++k) {
      const double a = radians(phase + 10.0 * t + steps[k] - 4); // tooth centred on phase
      const double r = (k == 1 || k == 2) ? kTip : kRoot;
      v.push_back(centre + V3{r * std::cos(a), 0, -r * std::sin(a)});
    }
  return v;
}

void gear(ScWriter& out, V3 centre, double phase) {
  const std::vector<V3> bottom = outline(centre, phase);
  std::vector<V3> top;
  for (const V3& p : bottom)
    top.push_back(p + V3{0, kThickness, 0});
  out.push();
  out.polygon(top); // faces up
  out.polygon(std::vector<V3>(bottom.rbegin(), bottom.rend()));
  for (std::size_t i = 0; i < bottom.size(); ++i) {
    const std::size_t j = (i + 1) % bottom.size();
    out.polygon({bottom[i], bottom[j], top[j], top[i]}); // faces outwards
  }
  out.pop();
}

void write(ScWriter& out, int n) {
  const double spacing = kRoot + kTip, extent = spacing * n + 2;
  // Seen from above at about 50 degrees; the camera and lights move out with
  // the grid so the picture and its exposure stay alike at every size.
  out.stage({.eye = {0.12 * extent, 0.95 * extent, 0.85 * extent},
             .lookat = {0, 0, 0.03 * extent},
             .fov = 45,
             .lights = {{{0.6 * extent, 1.4 * extent, 0.9 * extent}, 3.2 * extent * extent},
                        {{-1.1 * extent, 0.9 * extent, 0.2 * extent}, 1.2 * extent * extent}},
             .background = {0.1, 0.1, 0.12},
             .ambient = 0.1});
  out.surface(metal(0.25, 0.28, 0.35, 0.55));
  groundSquare(out, 2 * extent);
  const Surface brass = metal(0.85, 0.65, 0.3, 0.3), steel = metal(0.6, 0.65, 0.72, 0.3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const bool odd = (i + j) % 2 == 1;
      out.surface(odd ? steel : brass);
      const V3 centre{spacing * (i - 0.5 * (n - 1)), kLift, spacing * (j - 0.5 * (n - 1))};
      gear(out, centre, odd ? 5 : 0);
    }
}

} // namespace

SpdKind gearsKind() {
  return {"gears",
          "a grid of meshing gears of concave 144-vertex polygons over a mirror",
          "gears per side of the grid (146 n^2 + 1 polygons)",
          1,
          40,
          primitives,
          write};
}

} // namespace prism::spd
