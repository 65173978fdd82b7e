// mount: a fractal mountain with four glass spheres hovering in front of it.
// A hexagon of six triangles around the summit is split k times (the level),
// each split cutting every triangle into four at its edges' midpoints and
// raising or lowering each new midpoint at random by an amount proportional
// to its edge's length: 6 * 4^k triangles and 4 spheres.
//
// A midpoint's height depends only on its edge (the two end heights, and a
// random number hashed from the midpoint's lattice position), so the two
// triangles sharing an edge move it alike and the surface has no cracks. The
// position is hashed on the lattice of the finest level, so a point gets the
// same number at every level: larger levels refine the same mountain.
#include "core/math/hash.h"

#include "scene_parts.h"
#include "spd_kinds.h"

#include <cstdint>

namespace prism::spd {
namespace {

constexpr double kRadius = 10;     // of the hexagon
constexpr double kSummit = 6.0;    // height of its centre; the rim is at 0
constexpr double kRoughness = 0.2; // displacement / edge length, at most
constexpr int kMaxLevel = 8;

long primitives(int level) { return (6L << (2 * level)) + 4; } // and the spheres

// A point of the triangular lattice in axial coordinates (q along +x, r at 60
// degrees from it), with its height.
struct LatticePoint {
  long q, r;
  double height;
};

// Hash-random in [-1, 1), the same for the same lattice point.
double jitter(long q, long r) {
  const std::uint64_t h =
      hashCombine(hashCombine(0x6d6f756e74ull, std::uint64_t(q)), std::uint64_t(r));
  return 2 * unitFromBits(splitmix64(h)) - 1;
}

class Mountain {
public:
  Mountain(ScWriter& out, int level)
      : out_(out), scale_(kRadius / double(1L << level)), keyStep_(1L << (kMaxLevel - level)) {}

  // The triangle (a, b, c), counterclockwise from above, split `level` times.
  void triangle(const LatticePoint& a, const LatticePoint& b, const LatticePoint& c, int level) {
    if (level == 0) {
      out_.triangle(world(a), world(b), world(c));
      return;
    }
    const LatticePoint ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    triangle(a, ab, ca, level - 1);
    triangle(ab, b, bc, level - 1);
    triangle(ca, bc, c, level - 1);
    triangle(ab, bc, ca, level - 1);
  }

private:
  LatticePoint midpoint(const LatticePoint& a, const LatticePoint& b) const {
    const long q = (a.q + b.q) / 2, r = (a.r + b.r) / 2; // exact: ends are an even step apart
    const double edge = length(world(a) - world(b));
    return {q, r,
            0.5 * (a.height + b.height) + kRoughness * edge * jitter(q * keyStep_, r * keyStep_)};
  }
  // Angles grow from +x towards -z, counterclockwise seen from above.
  V3 world(const LatticePoint& p) const {
    const double q = double(p.q), r = double(p.r);
    return {scale_ * (q + 0.5 * r), p.height, -scale_ * (0.8660254037844386 * r)};
  }

  ScWriter& out_;
  double scale_; // world length of one lattice step
  long keyStep_; // lattice steps of the finest level in one of this level
};

void write(ScWriter& out, int level) {
  out.stage({.eye = {2, 5, 27},
             .lookat = {0, 2.2, 0},
             .fov = 40,
             .lights = {{{-14, 22, 12}, 900}, {{16, 8, 14}, 260}},
             .background = {0.45, 0.6, 0.85},
             .ambient = 0.12});
  out.surface(matte(0.55, 0.5, 0.42));
  const long n = 1L << level;
  const long corner[6][2] = {{n, 0}, {0, n}, {-n, n}, {-n, 0}, {0, -n}, {n, -n}};
  Mountain mountain(out, level);
  const LatticePoint summit{0, 0, kSummit};
  for (int k = 0; k < 6; ++k) {
    const long* a = corner[k];
    const long* b = corner[(k + 1) % 6];
    mountain.triangle(summit, {a[0], a[1], 0}, {b[0], b[1], 0}, level);
  }
  out.surface(glass());
  out.sphere({-4.2, 2.6, 8.5}, 0.9);
  out.sphere({-1.4, 3.4, 9.5}, 0.7);
  out.sphere({1.5, 3.0, 9.2}, 1.0);
  out.sphere({4.4, 2.4, 8}, 0.7);
}

} // namespace

SpdKind mountKind() {
  return {"mount",
          "a fractal mountain of triangles with four glass spheres",
          "midpoint subdivisions (6 * 4^k triangles + 4 spheres)",
          0,
          kMaxLevel,
          primitives,
          write};
}

} // namespace prism::spd
