// tetra: a Sierpinski tetrahedron on a floor. A tetrahedron of level k is four
// of level k - 1, half its size, at its corners; level 0 is a solid of four
// triangles. So level k has 4^k tetrahedra and 4^(k+1) triangles. The holes
// let light and rays deep into the structure at every scale.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

long primitives(int level) { return (4L << (2 * level)) + 1; } // and the floor

// The face (a, b, c), wound so its front faces away from `opposite`.
void face(ScWriter& out, V3 a, V3 b, V3 c, V3 opposite) {
  if (dot(cross(b - a, c - a), opposite - a) > 0)
    out.triangle(a, c, b);
  else
    out.triangle(a, b, c);
}

void tetra(ScWriter& out, const V3 (&v)[4], int level) {
  if (level == 0) {
    face(out, v[0], v[1], v[2], v[3]);
    face(out, v[0], v[1], v[3], v[2]);
    face(out, v[0], v[2], v[3], v[1]);
    face(out, v[1], v[2], v[3], v[0]);
    return;
  }
  out.push();
  for (int k = 0; k < 4; ++k) {
    V3 w[4];
    for (int j = 0; j < 4; ++j)
      w[j] = 0.5 * (v[k] + v[j]); // the corner k of this half-size copy is v[k]
    tetra(out, w, level - 1);
  }
  out.pop();
}

void write(ScWriter& out, int level) {
  out.stage({.eye = {2.2, 2.9, 7.6},
             .lookat = {0, 1.2, 0},
             .fov = 40,
             .lights = {{{5, 9, 6}, 150}, {{-7, 5, 3}, 50}, {{2, 7, -8}, 40}},
             .background = {0.1, 0.12, 0.18},
             .ambient = 0.1});
  out.surface(metal(0.35, 0.38, 0.45, 0.3));
  groundSquare(out, 10);
  // A regular tetrahedron of edge 3.4 standing on the floor.
  const double edge = 3.4, h = edge * std::sqrt(2.0 / 3.0), rb = edge / std::sqrt(3.0);
  V3 v[4] = {{0, h, 0}};
  for (int k = 0; k < 3; ++k) {
    const double a = radians(90 + 120.0 * k);
    v[k + 1] = {rb * std::cos(a), 0.001, rb * std::sin(a)};
  }
  out.surface(plastic(0.9, 0.75, 0.35, 0.3, 40));
  tetra(out, v, level);
}

} // namespace

SpdKind tetraKind() {
  return {"tetra",
          "a Sierpinski tetrahedron of triangles on a mirror floor",
          "subdivisions (4^k tetrahedra, 4^(k+1) triangles + 1 polygon)",
          0,
          8,
          primitives,
          write};
}

} // namespace prism::spd
