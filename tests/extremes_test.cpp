// The arithmetic at its extremes (issue 13): where rays leave surfaces, and
// scenes far from the origin or at extreme scales. Each test asserts a bound
// measured on this code; docs/rendering-model.md#starting-new-rays-off-the-surface
// derives the offset these bounds are checked against.
#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/film.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "tests/extremes_scenes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <utility>

namespace prism {
namespace {

using test::Placement;

constexpr double kU = 0x1p-53; // unit round-off of a double

// The signed distance of `p` from the surface of `shape` along its normal,
// in long double (11 more bits than the hit point's arithmetic), from the
// stored numbers that define the surface for the intersection test.
long double surfaceDistance(const Sphere& s, const ShapeArrays&, const Vec3& p) {
  long double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const long double c = (long double)p[i] - s.center[i];
    d2 += c * c;
  }
  return std::sqrt(d2) - s.radius;
}

// F(x) / |grad F(x)| for the frame's implicit function: first order in the
// distance, which is all a distance of a few ulps needs.
template <class Implicit>
long double frameDistance(const Mat3& w, const Vec3& w0, const Vec3& p, Implicit f) {
  long double q[3];
  for (int i = 0; i < 3; ++i)
    q[i] = (long double)w[0][i] * p.x + (long double)w[1][i] * p.y + (long double)w[2][i] * p.z +
           w0[i];
  long double grad[3];
  const long double value = f(q, grad);
  long double g2 = 0;
  for (int j = 0; j < 3; ++j) { // world gradient: w^T grad
    long double g = 0;
    for (int i = 0; i < 3; ++i)
      g += (long double)w[j][i] * grad[i];
    g2 += g * g;
  }
  return g2 > 0 ? value / std::sqrt(g2) : 0;
}

long double surfaceDistance(const Ellipsoid& e, const ShapeArrays&, const Vec3& p) {
  return frameDistance(e.worldToObject, e.worldToObjectOffset, p,
                       [](const long double* q, long double* g) {
                         for (int i = 0; i < 3; ++i)
                           g[i] = 2 * q[i];
                         return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - 1;
                       });
}

long double surfaceDistance(const Cone& c, const ShapeArrays&, const Vec3& p) {
  const long double k = (long double)c.apexRadius - c.baseRadius;
  return frameDistance(c.worldToObject, c.worldToObjectOffset, p,
                       [&](const long double* q, long double* g) {
                         const long double r = c.baseRadius + k * q[2];
                         g[0] = 2 * q[0];
                         g[1] = 2 * q[1];
                         g[2] = -2 * k * r;
                         return q[0] * q[0] + q[1] * q[1] - r * r;
                       });
}

long double surfaceDistance(const Polygon& poly, const ShapeArrays&, const Vec3& p) {
  long double d = -(long double)poly.planeOffset, n2 = 0;
  for (int i = 0; i < 3; ++i) {
    d += (long double)poly.normal[i] * p[i];
    n2 += (long double)poly.normal[i] * poly.normal[i];
  }
  return d / std::sqrt(n2);
}

long double surfaceDistance(const Triangle& tri, const ShapeArrays& arrays, const Vec3& p) {
  const Vec3& a = arrays.meshVertices[tri.vertex[0]];
  const Vec3& b = arrays.meshVertices[tri.vertex[1]];
  const Vec3& c = arrays.meshVertices[tri.vertex[2]];
  long double e1[3], e2[3], n[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = (long double)b[i] - a[i];
    e2[i] = (long double)c[i] - a[i];
  }
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  long double d = 0, n2 = 0;
  for (int i = 0; i < 3; ++i) {
    d += n[i] * ((long double)p[i] - a[i]);
    n2 += n[i] * n[i];
  }
  return d / std::sqrt(n2);
}

// One primitive of each kind, of size about 1 around the origin, each
// sheared or tilted so that no coordinate is special.
const char* const kOneOfEachKind[] = {
    "sphere 0.1 -0.2 0.3 0.9",
    "push rotate 1 2 3 30 scale 1 0.3 2 rotate 3 -1 1 50 sphere 0 0 0 1 pop",
    "polygon 5  -1 -0.7 -0.19  0.9 -0.8 -0.02  1.1 0.4 0.24  0.2 1.0 0.27  -0.9 0.6 0.08",
    "push rotate 1 1 0 20 scale 1 1 0.6 cone 0 -1 0 0.8  0.1 1 0.1 0.3 pop",
    "triangle  -1 -0.8 0.2  1.2 -0.5 -0.3  0.1 1.1 0.4",
};

// The largest |distance of the computed hit point from the surface| over
// u (|point| + |origin| + roundoffScale), for rays from all around the
// primitive toward random points of its bounds (many of them grazing).
double worstRoundoffRatio(const Scene& scene, Placement at, std::mt19937_64& rng) {
  const PrimitiveRef ref = scene.allPrimitives().at(0);
  const Aabb box = scene.visit(ref, [&](const auto& s) { return boundsOf(s, scene.arrays()); });
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 4000; ++i) {
    Vec3 from(unit(rng), unit(rng), unit(rng));
    from = at.offset + at.scale * 4.0 * glm::normalize(from);
    const Vec3 toward =
        box.lo + (box.hi - box.lo) * (0.5 + 0.5 * Vec3(unit(rng), unit(rng), unit(rng)));
    const Ray ray{from, glm::normalize(toward - from)};
    double t;
    if (!intersectPrimitive(scene, ref, ray, Interval{}, t)) continue;
    const Vec3 p = ray.at(t);
    const SurfacePoint sp = scene.surfaceAt(ref, p);
    const long double d =
        scene.visit(ref, [&](const auto& s) { return surfaceDistance(s, scene.arrays(), p); });
    const double size = maxAbsComponent(p) + maxAbsComponent(ray.origin) + sp.roundoffScale;
    worst = std::max(worst, double(std::abs(d)) / (kU * size));
  }
  return worst;
}

// The derivation promises a round-off of at most a few dozen u times the
// size (docs/rendering-model.md); the offset is 512 u of it. Measured: the
// worst ratio over all kinds and placements is 3.5 u (a polygon; printed), so
// the offset clears the round-off more than 100 times over; the test allows 16.
TEST(RayOffset, HitPointRoundoffStaysFarBelowTheOffset) {
  const double offsetUnits = kRayOffsetRoundoff / kU;
  ASSERT_EQ(offsetUnits, 512.0);
  std::mt19937_64 rng(13);
  for (const char* shape : kOneOfEachKind)
    for (const Placement at : {Placement{1, 0}, Placement{1e-4, 1e4}, Placement{1e4, 0},
                               Placement{1e-6, 1e4}, Placement{1, 1e6}, Placement{1e-3, -7}}) {
      const Scene scene = test::placedScene(shape, at, "kind.sc");
      const double worst = worstRoundoffRatio(scene, at, rng);
      std::printf("%-40.40s scale %g offset %g: worst round-off %.2f u\n", shape, at.scale,
                  at.offset, worst);
      EXPECT_LT(worst, 16.0) << shape << " at scale " << at.scale << " offset " << at.offset;
    }
}

// A feature of size s at distance D from the origin: the glass-and-mirror
// room (units of about 1) scaled by s and moved by D on every axis, against
// the same room at the origin, at 64 x 64, depth 5, threshold 0.1. Measured
// (the share of pixels within 2 levels, the worst pixel):
//   s / D      1e-4 / 1e4      1e-5 / 1e5      1e-6 / 1e4 (1e-10, the claimed limit)
//   now        99.98%, 5       99.02%, 16      99.05%, 16
//   1e-9 offset 79.96%, 105    0.15%, 127      0.15%, 127
// At 1e-8 only antialiasing decisions flip. At 1e-10 the same 1% of pixels
// change at both placements: coordinates there carry 6 digits of the room,
// and a ray bent by the glass sphere and the mirror lands on another side of
// an edge; the offset is about 2e-13 D there, 0.2% of the feature.
TEST(RayOffset, SmallGlassAndMirrorSceneFarFromTheOriginKeepsItsPicture) {
  RenderSettings settings;
  settings.width = settings.height = 64;
  settings.threads = 2;
  const auto home =
      test::picture(test::placedScene(test::kGlassAndMirror, {}, "room.sc"), settings);
  for (const Placement at : {Placement{1e-4, 1e4}, Placement{1e-5, 1e5}, Placement{1e-6, 1e4}}) {
    const auto far =
        test::picture(test::placedScene(test::kGlassAndMirror, at, "room.sc"), settings);
    const test::Agreement a = test::compare(home, far, 2);
    std::printf("scale %g at %g: %.2f%% within 2 levels, worst %d\n", at.scale, at.offset,
                100.0 * a.within, a.worst);
    const bool atTheLimit = at.scale / at.offset < 1e-9;
    EXPECT_GE(a.within, atTheLimit ? 0.985 : 0.999) << "scale " << at.scale << " at " << at.offset;
    EXPECT_LE(a.worst, atTheLimit ? 32 : 8) << "scale " << at.scale << " at " << at.offset;
  }
}

// Every shipped scene placed at scale 1e-4 and 1e4, and at 1e-4 moved 1e4
// away (features of 1e-3 at 1e4: 1e-7), against itself at scale 1, at 80 x 60.
// Measured: at both scales every pixel of every scene is exactly the same;
// moved far away, 99.96% of glass.sc's pixels and 99.98% of forest.sc's are
// within 2 levels (worst 9 and 4: antialiasing decisions that flip), the other
// scenes' all within 1. The test allows 1 level at the two scales and 0.5% of
// the pixels beyond 2 levels far away.
TEST(RayOffset, ShippedScenesKeepTheirPictureAtExtremeScales) {
  RenderSettings settings;
  settings.width = 80;
  settings.height = 60;
  settings.threads = 2;
  const std::string dir = std::string(PRISM_SOURCE_DIR) + "/scenes/";
  for (const char* name : {"glass.sc", "table.sc", "chex.sc", "tree.sc", "forest.sc"}) {
    const std::string body = std::string("include ") + name + "\n";
    const auto unit = test::picture(test::placedScene(body, {}, dir + "wrap.sc"), settings);
    for (const Placement at : {Placement{1e-4, 0}, Placement{1e4, 0}, Placement{1e-4, 1e4}}) {
      const auto got = test::picture(test::placedScene(body, at, dir + "wrap.sc"), settings);
      const test::Agreement a = test::compare(unit, got, 2);
      const test::Agreement exact = test::compare(unit, got, 1);
      std::printf("%-10s scale %g at %g: %.2f%% within 1 level, %.2f%% within 2, worst %d\n", name,
                  at.scale, at.offset, 100.0 * exact.within, 100.0 * a.within, a.worst);
      if (at.offset == 0.0) {
        EXPECT_LE(a.worst, 1) << name << " scale " << at.scale;
      } else {
        EXPECT_GE(a.within, 0.995) << name << " scale " << at.scale << " at " << at.offset;
      }
    }
  }
}

} // namespace
} // namespace prism
