// teapot: a teapot of smooth triangles on a mirror checkerboard of 8 x 8
// polygons. Like the Utah teapot it is 32 bicubic pieces: the bottom, the
// body (two), the rim, the lid and its knob are cubic profiles turned about
// the vertical axis, each in four quarters (24 pieces); the handle and the
// spout are tubes along two cubic curves each, each tube in two halves (8
// pieces). Its shape is ours, drawn to look like the classic teapot, not the
// Newell data. Each piece is cut into n x n quads of two triangles (n is the
// level), with the vertex normals of the exact surface; at the two poles, the
// centre of the bottom and the top of the knob, a quad has one triangle. So
// the teapot has 64 n^2 - 8 n triangles, and the scene 64 polygons more.
#include "scene_parts.h"
#include "spd_kinds.h"

namespace prism::spd {
namespace {

// A planar cubic Bezier curve: x is the distance from the axis (or the x of
// the tube's centre line), y the height.
struct Cubic {
  double p[4][2];
  void at(double t, double& x, double& y) const { eval(t, x, y, false); }
  void slope(double t, double& dx, double& dy) const { eval(t, dx, dy, true); }

private:
  void eval(double t, double& x, double& y, bool derivative) const {
    const double s = 1 - t;
    double w[4];
    if (derivative) {
      w[0] = -3 * s * s, w[1] = 3 * s * s - 6 * s * t, w[2] = 6 * s * t - 3 * t * t,
      w[3] = 3 * t * t;
    } else {
      w[0] = s * s * s, w[1] = 3 * s * s * t, w[2] = 3 * s * t * t, w[3] = t * t * t;
    }
    x = y = 0;
    for (int k = 0; k < 4; ++k)
      x += w[k] * p[k][0], y += w[k] * p[k][1];
  }
};

// Profiles turned about the axis, from the centre of the bottom to the top of
// the knob; consecutive curves meet with a common tangent direction.
constexpr Cubic kProfiles[6] = {
    {{{0, 0}, {0.5, 0}, {1.0, 0}, {1.5, 0}}},                 // bottom (pole at its start)
    {{{1.5, 0}, {2.0, 0.05}, {2.0, 0.75}, {2.0, 1.2}}},       // lower body
    {{{2.0, 1.2}, {2.0, 1.85}, {1.65, 2.3}, {1.45, 2.4}}},    // upper body
    {{{1.45, 2.4}, {1.55, 2.45}, {1.55, 2.55}, {1.4, 2.55}}}, // rim
    {{{1.4, 2.55}, {1.0, 2.55}, {0.45, 2.8}, {0.2, 3.0}}},    // lid
    {{{0.2, 3.0}, {0.6, 3.05}, {0.5, 3.35}, {0, 3.35}}},      // knob (pole at its end)
};

// Centre lines of the tubes, in the plane z = 0: handle at -x, spout at +x.
constexpr Cubic kHandle[2] = {
    {{{-1.6, 2.1}, {-2.5, 2.25}, {-3.0, 2.0}, {-2.85, 1.5}}},
    {{{-2.85, 1.5}, {-2.7, 1.0}, {-2.3, 0.65}, {-1.7, 0.6}}},
};
constexpr Cubic kSpout[2] = {
    {{{1.7, 0.8}, {2.5, 0.9}, {2.6, 1.5}, {2.8, 2.0}}},
    {{{2.8, 2.0}, {2.96, 2.4}, {3.1, 2.5}, {3.3, 2.55}}},
};

long primitives(int n) { return 64L * n * n - 8L * n + 64; }

// A point and its unit normal.
struct Vertex {
  V3 p, n;
};

// Writes the n x n quads of a patch given by `at(u, v)`, u and v in [0, 1],
// whose normal (du x dv) points outwards; quads with a collapsed edge (a pole)
// get their one proper triangle.
template <class At> void patch(ScWriter& out, int n, At at) {
  auto same = [](V3 a, V3 b) { return length(a - b) < 1e-12; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vertex a = at(double(i) / n, double(j) / n), b = at(double(i + 1) / n, double(j) / n),
                   c = at(double(i + 1) / n, double(j + 1) / n),
                   d = at(double(i) / n, double(j + 1) / n);
      if (!same(b.p, c.p)) out.ptriangle(a.p, a.n, b.p, b.n, c.p, c.n);
      if (!same(a.p, d.p)) out.ptriangle(a.p, a.n, c.p, c.n, d.p, d.n);
    }
}

// A quarter (from angle `phi0`) of the profile turned about the y axis.
Vertex turned(const Cubic& profile, double phi0, double u, double v) {
  double r, y, dr, dy;
  profile.at(u, r, y);
  profile.slope(u, dr, dy);
  const double phi = phi0 + 0.5 * kPi * v;
  // d/du x d/dphi is r (dy cos, -dr, dy sin): outwards while the profile
  // climbs or moves inwards, as ours does.
  return {{r * std::cos(phi), y, r * std::sin(phi)},
          normalize({dy * std::cos(phi), -dr, dy * std::sin(phi)})};
}

// Half (from angle `theta0`) of an elliptical tube around the centre line
// `line`, with half-widths a (in the plane of the line) and b (across it),
// both multiplied by `taper(u)`.
template <class Taper>
Vertex tube(const Cubic& line, double a, double b, Taper taper, double theta0, double u, double v) {
  double x, y, dx, dy;
  line.at(u, x, y);
  line.slope(u, dx, dy);
  const double len = std::sqrt(dx * dx + dy * dy);
  // With the tangent t, n = (t.y, -t.x) and z make the frame (t, n, z)
  // right-handed, so d/du x d/dtheta points outwards.
  const V3 normal{dy / len, -dx / len, 0}, across{0, 0, 1};
  const double theta = theta0 + kPi * v, s = taper(u);
  const V3 p = V3{x, y, 0} + s * a * std::cos(theta) * normal + s * b * std::sin(theta) * across;
  // The cross-section lies in the plane normal to the line, so the surface
  // normal is the ellipse's normal (exactly so while the taper is constant).
  return {p, normalize(std::cos(theta) / a * normal + std::sin(theta) / b * across)};
}

void write(ScWriter& out, int n) {
  out.stage({.eye = {6.5, 6.2, 11},
             .lookat = {0.2, 1.1, 0},
             .fov = 36,
             .lights = {{{-6, 11, 8}, 220}, {{9, 6, 3}, 70}, {{0, 8, -9}, 40}},
             .background = {0.08, 0.09, 0.12},
             .ambient = 0.1});
  // The checkerboard, a little below the bottom so the two do not coincide.
  const Surface squares[2] = {metal(0.85, 0.2, 0.15, 0.45), metal(0.9, 0.9, 0.85, 0.45)};
  constexpr double kSquare = 1.5, kFloor = -0.005;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      out.surface(squares[(i + j) % 2]); // stored once however often given
      const double x0 = kSquare * (i - 4), z0 = kSquare * (j - 4), x1 = x0 + kSquare,
                   z1 = z0 + kSquare;
      out.polygon({{x0, kFloor, z1}, {x1, kFloor, z1}, {x1, kFloor, z0}, {x0, kFloor, z0}});
    }
  out.surface(plastic(0.92, 0.9, 0.82, 0.25, 40));
  out.push();
  for (const Cubic& profile : kProfiles)
    for (int q = 0; q < 4; ++q)
      patch(out, n, [&](double u, double v) { return turned(profile, 0.5 * kPi * q, u, v); });
  auto constant = [](double) { return 1.0; };
  for (int k = 0; k < 2; ++k)
    for (int h = 0; h < 2; ++h)
      patch(out, n, [&](double u, double v) {
        return tube(kHandle[k], 0.11, 0.2, constant, kPi * h, u, v);
      });
  for (int k = 0; k < 2; ++k)
    for (int h = 0; h < 2; ++h) {
      // From 0.42 at the body to 0.17 at the mouth, over both curves.
      auto taper = [k](double u) { return 1 - 0.6 * (0.5 * (k + u)); };
      patch(out, n,
            [&](double u, double v) { return tube(kSpout[k], 0.42, 0.42, taper, kPi * h, u, v); });
    }
  out.pop();
}

} // namespace

SpdKind teapotKind() {
  return {"teapot",
          "a teapot of 32 pieces of smooth triangles on a mirror checkerboard",
          "quads per side of each piece (64 n^2 - 8 n triangles + 64 polygons)",
          1,
          64,
          primitives,
          write};
}

} // namespace prism::spd
