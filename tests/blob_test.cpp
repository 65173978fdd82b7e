// Blobs against hand-computed values: one component is the sphere of radius
// r sqrt(1 - sqrt(T / s)), hits and normals; two components on a line
// against an independent long double bisection and the closed form of the
// neck's waist; a thin neck whose field exceeds the threshold by 1e-9 hit by
// every ray through it, and a sweep of oblique rays through a neck against
// dense sampling in long double; negative components; tangent rays and rays
// from inside; far away, tiny and huge; rotated and stretched against the
// analytic ellipsoid; the crossings CSG uses; two components far apart as
// two spheres of the closed form; the .sc `blob` and its errors;
// the writers. The hierarchies against brute force: accel_test's
// BlobsMatchBruteForce.
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/crossings.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

namespace prism {
namespace {

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

// A scene holding one blob of `components` under x -> linear x + offset.
Scene blobScene(std::vector<BlobComponent> components, double threshold,
                const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0)) {
  Scene scene;
  SceneBuilder build(scene);
  EXPECT_FALSE(blobProblem(components, threshold));
  build.blob(makeBlob(components, threshold, linear, offset));
  return scene;
}

const Blob& theBlob(const Scene& s) { return s.shapes<Blob>().at(0); }

bool hit(const Scene& s, const Ray& r, double& t, Interval range = {}) {
  return intersect(theBlob(s), s.arrays(), r, range, t);
}

std::vector<Crossing> crossingsOf(const Scene& s, const Ray& r, Interval range = {}) {
  std::vector<Crossing> out;
  appendCrossings(theBlob(s), s.arrays(), r, range, out);
  return out;
}

// The field minus the threshold in long double, from the components as given
// (world coordinates).
long double excess(const std::vector<BlobComponent>& components, long double threshold,
                   const long double* p) {
  long double field = -threshold;
  for (const BlobComponent& c : components) {
    long double d2 = 0;
    for (int i = 0; i < 3; ++i) {
      const long double d = p[i] - (long double)c.center[i];
      d2 += d * d;
    }
    const long double g = 1 - d2 / ((long double)c.radius * c.radius);
    if (g > 0) field += c.strength * g * g;
  }
  return field;
}

long double excessAlong(const std::vector<BlobComponent>& components, long double threshold,
                        const Ray& r, long double t) {
  long double p[3];
  for (int i = 0; i < 3; ++i)
    p[i] = r.origin[i] + t * (long double)r.dir[i];
  return excess(components, threshold, p);
}

// The root of the excess in [a, b] (outside at a, inside at b), by bisection.
long double bisect(const std::vector<BlobComponent>& components, long double threshold,
                   const Ray& r, long double a, long double b) {
  for (int i = 0; i < 200 && b - a > 0; ++i) {
    const long double m = 0.5L * (a + b);
    if (m == a || m == b) break;
    (excessAlong(components, threshold, r, m) >= 0 ? b : a) = m;
  }
  return 0.5L * (a + b);
}

// The first entry of the ray into the blob by dense sampling of [0, length]
// in `steps` steps and bisection, or -1.
long double sampledHit(const std::vector<BlobComponent>& components, long double threshold,
                       const Ray& r, long double length, int steps) {
  long double before = 0;
  if (excessAlong(components, threshold, r, 0) >= 0) return 0;
  for (int i = 1; i <= steps; ++i) {
    const long double t = length * i / steps;
    if (excessAlong(components, threshold, r, t) >= 0)
      return bisect(components, threshold, r, before, t);
    before = t;
  }
  return -1;
}

// One component alone: the ball of radius r sqrt(1 - sqrt(T / s)).
TEST(Blob, OneComponentIsTheSphereOfTheClosedForm) {
  const Vec3 c(0.3, -0.2, 0.1);
  const double r = 1.5, s = 2.0, T = 0.5;
  const double R = r * std::sqrt(1.0 - std::sqrt(T / s)); // 1.5 sqrt(1/2)
  EXPECT_NEAR(R, 1.0606601717798212, 1e-15);
  const Scene scene = blobScene({{c, r, s}}, T);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 from = c + 5.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Vec3 toward = c + 1.2 * R * Vec3(u(rng), u(rng), u(rng));
    const Ray q = ray(from, toward - from);
    // The sphere's roots, by hand: |from - c + t d|^2 = R^2.
    const Vec3 oc = q.origin - c;
    const double b = glm::dot(oc, q.dir), disc = b * b - (glm::dot(oc, oc) - R * R);
    double t = 0;
    const bool got = hit(scene, q, t);
    if (std::abs(disc) < 1e-6) continue; // within 1e-6 of tangent: either
    ASSERT_EQ(got, disc > 0) << i;
    if (!got) continue;
    ++hits;
    EXPECT_NEAR(t, -b - std::sqrt(disc), 1e-9);
    const Vec3 p = q.at(t);
    test::expectCloseTo(outwardNormal(theBlob(scene), scene.arrays(), p), (p - c) / R, 1e-9);
    // And the far side, from the crossings.
    const std::vector<Crossing> cr = crossingsOf(scene, q);
    ASSERT_EQ(cr.size(), 2u);
    EXPECT_TRUE(cr[0].entering);
    EXPECT_FALSE(cr[1].entering);
    EXPECT_NEAR(cr[1].t, -b + std::sqrt(disc), 1e-9);
  }
  EXPECT_GT(hits, 1000);
}

// Two equal components at x = -a and a, radius 1, strength 1: on the y axis
// the field is 2 (1 - a^2 - y^2)^2, so the waist is y^2 = 1 - a^2 - sqrt(T/2);
// along the x axis the hit solves (1 - (x + a)^2)^2 + (1 - (x - a)^2)^2 = T
// (where both are inside), against long double bisection.
TEST(Blob, TwoComponentsOnALine) {
  const double a = 0.6, T = 0.5;
  const std::vector<BlobComponent> comps = {{{-a, 0, 0}, 1, 1}, {{a, 0, 0}, 1, 1}};
  const Scene scene = blobScene(comps, T);
  // The waist.
  const double waist = std::sqrt(1 - a * a - std::sqrt(T / 2)); // sqrt(0.14)
  double t = 0;
  ASSERT_TRUE(hit(scene, ray({0, -4, 0}, {0, 1, 0}), t));
  EXPECT_NEAR(t, 4 - waist, 1e-12);
  ASSERT_TRUE(hit(scene, ray({0, 0, 4}, {0, 0, -1}), t));
  EXPECT_NEAR(t, 4 - waist, 1e-12);
  // Along the axis: the outer side lies in only one sphere, (1 - (x - a)^2)^2
  // = T: x = a + sqrt(1 - sqrt(T)).
  ASSERT_TRUE(hit(scene, ray({4, 0, 0}, {-1, 0, 0}), t));
  EXPECT_NEAR(t, 4 - (a + std::sqrt(1 - std::sqrt(T))), 1e-12);
  // Oblique rays: against bisection from a dense sampling.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const Vec3 from = 4.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Ray q = ray(from, Vec3(1.4 * u(rng), 0.5 * u(rng), 0.5 * u(rng)) - from);
    const long double want = sampledHit(comps, T, q, 8, 4000);
    const bool got = hit(scene, q, t);
    ASSERT_EQ(got, want >= 0) << i;
    if (got) {
      EXPECT_NEAR(t, double(want), 1e-10) << i;
    }
  }
}

// The field at the centre of the neck exceeds the threshold by 1e-9 of it:
// the waist is y^2 = 1 - a^2 - sqrt(T/2), about 1.6e-5 across, and every ray
// through it must hit, where the closed form says.
TEST(Blob, AThinNeckIsNeverMissed) {
  const double T = 0.5, eps = 1e-9;
  const double a = std::sqrt(1 - std::sqrt(T * (1 + eps) / 2));
  const std::vector<BlobComponent> comps = {{{-a, 0, 0}, 1, 1}, {{a, 0, 0}, 1, 1}};
  const Scene scene = blobScene(comps, T);
  const long double w2 = 1 - (long double)a * a - std::sqrt((long double)T / 2);
  ASSERT_GT(w2, 0);
  const long double waist = std::sqrt(w2);
  EXPECT_NEAR(double(waist), 1.58e-5, 0.02e-5);
  // In the plane x = 0 the field depends only on y^2 + z^2: rays along z at
  // height y meet the disc y^2 + z^2 < waist^2.
  for (int k = -99; k <= 99; ++k) {
    const long double y = waist * k / 100;
    const Ray q = ray({0, double(y), -1}, {0, 0, 1});
    double t = 0;
    ASSERT_TRUE(hit(scene, q, t)) << k;
    const long double want = 1 - std::sqrt(w2 - (long double)q.origin.y * q.origin.y);
    EXPECT_NEAR(t, double(want), 1e-9 + 1e-3 * double(waist)) << k;
    const std::vector<Crossing> c = crossingsOf(scene, q);
    ASSERT_EQ(c.size(), 2u) << k;
  }
  for (const double y : {1.01, 1.5, 3.0}) {
    double t = 0;
    EXPECT_FALSE(hit(scene, ray({0, double(waist) * y, -1}, {0, 0, 1}), t)) << y;
  }
}

// Oblique rays through the region of a neck 1e-4 over the threshold: no miss
// and no false hit against dense sampling in long double.
TEST(Blob, RaysThroughANeckAgreeWithDenseSampling) {
  const double T = 0.5, eps = 1e-4;
  const double a = std::sqrt(1 - std::sqrt(T * (1 + eps) / 2));
  const std::vector<BlobComponent> comps = {{{-a, 0, 0}, 1, 1}, {{a, 0, 0}, 1, 1}};
  const Scene scene = blobScene(comps, T);
  const double waist = std::sqrt(1 - a * a - std::sqrt(T / 2)); // 5e-3
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, misses = 0;
  for (int i = 0; i < 150; ++i) {
    const Vec3 dir = glm::normalize(Vec3(0.3 * u(rng), u(rng), u(rng)));
    const Vec3 through(0.5 * waist * u(rng), 2 * waist * u(rng), 2 * waist * u(rng));
    // From 0.2 before the neck, well inside both spheres, and outside the
    // blob.
    const Ray q{through - 0.2 * dir, dir};
    if (excessAlong(comps, T, q, 0) >= 0) continue;
    const long double want = sampledHit(comps, T, q, 0.4L, 200000);
    double t = 0;
    const bool got = hit(scene, q, t, Interval{0.0, 0.4});
    if (want >= 0) {
      ASSERT_TRUE(got) << i;
      EXPECT_NEAR(t, double(want), 1e-8) << i;
      ++hits;
    } else if (got) {
      // The sampling may step over a chord shorter than its step (2e-6): a
      // hit it did not see must be on the surface.
      EXPECT_NEAR(double(excessAlong(comps, T, q, t)), 0.0, 1e-12) << i;
    } else {
      ++misses;
    }
  }
  EXPECT_GT(hits, 30);
  EXPECT_GT(misses, 30);
}

// A negative component subtracts: it bites into the positive one's ball.
TEST(Blob, NegativeComponents) {
  const double T = 0.25;
  const std::vector<BlobComponent> comps = {{{0, 0, 0}, 1, 1}, {{0.5, 0, 0}, 0.5, -1}};
  const Scene scene = blobScene(comps, T);
  const double R = std::sqrt(1 - std::sqrt(T)); // the positive one alone
  double t = 0;
  // From -x the negative sphere (x in [0, 1]) is not reached.
  ASSERT_TRUE(hit(scene, ray({-3, 0, 0}, {1, 0, 0}), t));
  EXPECT_NEAR(t, 3 - R, 1e-12);
  // From +x: (1 - x^2)^2 - (1 - 4 (x - 0.5)^2)^2 = T, by bisection in long
  // double: inside at x = 0 (1 - T > 0 with the negative term 0 at x = 0).
  const Ray q = ray({3, 0, 0}, {-1, 0, 0});
  const long double want = sampledHit(comps, T, q, 6, 60000);
  ASSERT_GE(want, 0);
  ASSERT_TRUE(hit(scene, q, t));
  EXPECT_NEAR(t, double(want), 1e-12);
  EXPECT_GT(t, 3.0 - R); // bitten: deeper than the ball alone
  // The bite's surface faces +x there.
  EXPECT_GT(outwardNormal(theBlob(scene), scene.arrays(), q.at(t)).x, 0.99);
  // A negative component as strong as the positive at the centre hollows it:
  // rays through the centre cross four times.
  const std::vector<BlobComponent> hollow = {{{0, 0, 0}, 1, 1}, {{0, 0, 0}, 0.5, -1}};
  const Scene h = blobScene(hollow, T);
  const std::vector<Crossing> c = crossingsOf(h, ray({-3, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(c.size(), 4u);
  EXPECT_TRUE(c[0].entering && !c[1].entering && c[2].entering && !c[3].entering);
  EXPECT_NEAR(c[0].t, 3 - R, 1e-12);
  EXPECT_NEAR(c[3].t, 3 + R, 1e-12);
}

// Tangent rays: 1e-9 inside the sphere of the closed form they cross twice,
// 1e-9 outside never; rays from inside leave once.
TEST(Blob, TangentRaysAndRaysFromInside) {
  const double T = 0.5, s = 2, r = 1;
  const double R = r * std::sqrt(1 - std::sqrt(T / s));
  const Scene scene = blobScene({{{0, 0, 0}, r, s}}, T);
  for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(0, 1, 0), glm::normalize(Vec3(1, 1, 1))}) {
    Vec3 side = glm::normalize(glm::cross(dir, Vec3(0.3, 0.5, 0.7)));
    const std::vector<Crossing> in =
        crossingsOf(scene, Ray{R * (1 - 1e-9) * side - 3.0 * dir, dir});
    ASSERT_EQ(in.size(), 2u);
    EXPECT_NEAR(in[0].t, 3 - R * std::sqrt(1 - (1 - 1e-9) * (1 - 1e-9)), 1e-9);
    EXPECT_TRUE(crossingsOf(scene, Ray{R * (1 + 1e-9) * side - 3.0 * dir, dir}).empty());
    // From the centre, and from just inside the surface.
    std::vector<Crossing> out = crossingsOf(scene, Ray{Vec3(0.0), dir});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_FALSE(out[0].entering);
    EXPECT_NEAR(out[0].t, R, 1e-12);
    out = crossingsOf(scene, Ray{-R * (1 - 1e-9) * dir, dir});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].t, 2 * R * (1 - 0.5e-9), 1e-12);
  }
}

// Far from the origin, and tiny and huge, the sphere of the closed form to a
// relative 1e-9.
TEST(Blob, FarAwayTinyAndHuge) {
  const double T = 0.5, s = 2;
  const double k = std::sqrt(1 - std::sqrt(T / s));
  for (const double size : {1e-6, 1.0, 1e6}) {
    for (const double away : {0.0, 1e6}) {
      const Vec3 c(away, -0.5 * away, 0.25 * away);
      const Scene scene = blobScene({{c, size, s}}, T);
      const Vec3 dir = glm::normalize(Vec3(1, 2, -2));
      const Vec3 from = c - 5.0 * size * dir + 0.3 * size * glm::normalize(Vec3(2, -1, 0));
      double t = 0;
      ASSERT_TRUE(hit(scene, Ray{from, dir}, t)) << size << " " << away;
      const double R = k * size, b = 0.3 * size;
      EXPECT_NEAR(t, 5 * size - std::sqrt(R * R - b * b), 1e-9 * (size + away)) << size;
    }
  }
}

// A rotated, translated, non-uniformly scaled single component is an
// ellipsoid: scale 2 1 1 then a quarter turn about z puts its long axis
// along world y.
TEST(Blob, TransformedLikeTheAnalyticEllipsoid) {
  const Scene scene = parseScene(
      "push translate 1 2 3 rotate 0 0 1 90 scale 2 1 1 blob 0.5 1  0 0 0  1 2 pop", "t.sc");
  const Blob& b = theBlob(scene);
  EXPECT_TRUE(b.placed);
  const double R = std::sqrt(1 - std::sqrt(0.25));
  double t = 0;
  ASSERT_TRUE(hit(scene, ray({-9, 2, 3}, {1, 0, 0}), t));
  EXPECT_NEAR(t, 10 - R, 1e-12);
  ASSERT_TRUE(hit(scene, ray({1, -8, 3}, {0, 1, 0}), t));
  EXPECT_NEAR(t, 10 - 2 * R, 1e-12);
  // Normals: the gradient of (x-1)^2/R^2 + (y-2)^2/(2R)^2 + (z-3)^2/R^2.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 100; ++i) {
    const Vec3 from = Vec3(1, 2, 3) + 6.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Ray q = ray(from, Vec3(1, 2, 3) + 0.3 * Vec3(u(rng), u(rng), u(rng)) - from);
    ASSERT_TRUE(hit(scene, q, t));
    const Vec3 p = q.at(t) - Vec3(1, 2, 3);
    EXPECT_NEAR(p.x * p.x / (R * R) + p.y * p.y / (4 * R * R) + p.z * p.z / (R * R), 1.0, 1e-12);
    const Vec3 want = glm::normalize(Vec3(p.x, p.y / 4, p.z));
    test::expectCloseTo(outwardNormal(b, scene.arrays(), q.at(t)), want, 1e-9);
  }
  // Under a similarity the components are moved into the world: no frame.
  const Scene similar = parseScene(
      "push translate 1 2 3 rotate 1 1 1 40 scale 2 2 2 blob 0.5 1  1 0 0  1 2 pop", "t.sc");
  const Blob& sb = theBlob(similar);
  EXPECT_FALSE(sb.placed);
  const BlobComponent& c = similar.blobComponents.at(0);
  EXPECT_NEAR(c.radius, 2.0, 1e-15);
  EXPECT_NEAR(glm::length(c.center - Vec3(1, 2, 3)), 2.0, 1e-14);
  ASSERT_TRUE(
      intersect(sb, similar.arrays(), Ray{c.center + Vec3(0, 0, 9), {0, 0, -1}}, Interval{}, t));
  EXPECT_NEAR(t, 9 - 2 * R, 1e-12);
}

// Two components far apart are two spheres: four crossings, alternating,
// and the range clips them.
TEST(Blob, CrossingsOfTwoSeparateComponents) {
  const double T = 0.5, s = 2;
  const double R = std::sqrt(1 - std::sqrt(T / s));
  const Scene scene = blobScene({{{0, 0, 0}, 1, s}, {{3, 0, 0}, 1, s}}, T);
  const Ray q = ray({-5, 0, 0}, {1, 0, 0});
  std::vector<Crossing> c = crossingsOf(scene, q);
  ASSERT_EQ(c.size(), 4u);
  const double want[] = {5 - R, 5 + R, 8 - R, 8 + R};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c[i].t, want[i], 1e-12);
    EXPECT_EQ(c[i].entering, i % 2 == 0);
    EXPECT_EQ(c[i].part, 0u);
  }
  c = crossingsOf(scene, q, Interval{5.0, 8.0});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 5 + R, 1e-12);
  EXPECT_FALSE(c[0].entering);
  EXPECT_NEAR(c[1].t, 8 - R, 1e-12);
  double t = 0;
  ASSERT_TRUE(hit(scene, q, t, Interval{5.0, 100.0}));
  EXPECT_NEAR(t, 5 + R, 1e-12);
  EXPECT_FALSE(hit(scene, q, t, Interval{5.0 + R + 1e-6, 8.0 - R - 1e-6}));
}

// Two components whose balls of influence (radius r) are 4 apart, more than
// 2 + 1: each one's field is zero everywhere the other's is not, so the blob
// is exactly two spheres of radius r sqrt(1 - sqrt(T / s)), by hand with
// T = 0.25: r = 2, s = 1 gives 2 sqrt(1 - 1/2) = sqrt(2); r = 1, s = 4 gives
// sqrt(1 - 1/4) = sqrt(3) / 2. Hits, normals and crossings of rays at each
// and through both, against the spheres' roots and (p - c) / R.
TEST(Blob, FarApartComponentsAreTwoSpheres) {
  const double T = 0.25;
  const Vec3 ca(1, 2, -1), cb(1 + 2.4, 2, -1 + 3.2); // |cb - ca| = 4
  const double ra = std::sqrt(2.0), rb = std::sqrt(3.0) / 2;
  const Scene scene = blobScene({{ca, 2, 1}, {cb, 1, 4}}, T);
  const Blob& b = theBlob(scene);
  // The spheres' entry and exit along `q` by hand: |o - c + t d|^2 = R^2.
  struct Chord {
    double in, out;
  };
  auto chord = [](const Ray& q, const Vec3& c, double R) {
    const Vec3 oc = q.origin - c;
    const double m = glm::dot(oc, q.dir), disc = m * m - (glm::dot(oc, oc) - R * R);
    EXPECT_GT(disc, 0.0);
    return Chord{-m - std::sqrt(disc), -m + std::sqrt(disc)};
  };
  // The hit, its normal and both crossings of a ray that meets one sphere.
  auto expectOneSphere = [&](const Ray& q, const Vec3& c, double R) {
    const Chord want = chord(q, c, R);
    double t = 0;
    ASSERT_TRUE(hit(scene, q, t));
    EXPECT_NEAR(t, want.in, 1e-12);
    test::expectCloseTo(outwardNormal(b, scene.arrays(), q.at(t)), (q.at(want.in) - c) / R, 1e-12);
    const std::vector<Crossing> cr = crossingsOf(scene, q);
    ASSERT_EQ(cr.size(), 2u);
    EXPECT_TRUE(cr[0].entering);
    EXPECT_FALSE(cr[1].entering);
    EXPECT_NEAR(cr[0].t, want.in, 1e-12);
    EXPECT_NEAR(cr[1].t, want.out, 1e-12);
    test::expectCloseTo(outwardNormal(b, scene.arrays(), q.at(cr[1].t)), (q.at(want.out) - c) / R,
                        1e-12);
  };
  // Down onto each, through its centre and 0.6 of its radius off it, and
  // from the side, slanted.
  const Vec3 da = glm::normalize(Vec3(0.3, 0, 1)), db = glm::normalize(Vec3(-0.2, 0, 1));
  for (const double off : {0.0, 0.6}) {
    expectOneSphere(ray(ca + Vec3(off * ra, 5, 0), {0, -1, 0}), ca, ra);
    expectOneSphere(ray(cb + Vec3(0, 5, off * rb), {0, -1, 0}), cb, rb);
    expectOneSphere(Ray{ca - 5.0 * da + Vec3(0, off * ra, 0), da}, ca, ra);
    expectOneSphere(Ray{cb - 5.0 * db + Vec3(0, off * rb, 0), db}, cb, rb);
  }
  // Straight down between them: no hit.
  double t = 0;
  EXPECT_FALSE(hit(scene, ray(0.5 * (ca + cb) + Vec3(0, 5, 0), {0, -1, 0}), t));
  EXPECT_TRUE(crossingsOf(scene, ray(0.5 * (ca + cb) + Vec3(0, 5, 0), {0, -1, 0})).empty());
  // Through both: along the line of the centres, and parallel to it 0.5
  // away (perpendicular to cb - ca), from beyond a's side.
  const Vec3 axis = (cb - ca) / 4.0;
  for (const double off : {0.0, 0.5}) {
    const Ray q{ca - 5.0 * axis + Vec3(0, off, 0), axis};
    const Chord a = chord(q, ca, ra), bb = chord(q, cb, rb);
    if (off == 0.0) { // the hand values: 5 -+ sqrt(2) and 9 -+ sqrt(3) / 2
      EXPECT_NEAR(a.in, 5 - ra, 1e-14);
      EXPECT_NEAR(bb.out, 9 + rb, 1e-14);
    }
    ASSERT_TRUE(hit(scene, q, t));
    EXPECT_NEAR(t, a.in, 1e-12);
    test::expectCloseTo(outwardNormal(b, scene.arrays(), q.at(t)), (q.at(a.in) - ca) / ra, 1e-12);
    // The second sphere, from between them.
    ASSERT_TRUE(hit(scene, q, t, Interval{0.5 * (a.out + bb.in), 100.0}));
    EXPECT_NEAR(t, bb.in, 1e-12);
    test::expectCloseTo(outwardNormal(b, scene.arrays(), q.at(t)), (q.at(bb.in) - cb) / rb, 1e-12);
    const std::vector<Crossing> cr = crossingsOf(scene, q);
    ASSERT_EQ(cr.size(), 4u) << off;
    const double want[] = {a.in, a.out, bb.in, bb.out};
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(cr[i].t, want[i], 1e-12) << off << " " << i;
      EXPECT_EQ(cr[i].entering, i % 2 == 0) << off << " " << i;
    }
  }
}

TEST(Blob, BoundsAndCoordinates) {
  const Scene scene = blobScene({{{0, 0, 0}, 1, 2}, {{3, 0, 0}, 2, -1}, {{0, 1, 0}, 0.5, 1}}, 0.5);
  const Blob& b = theBlob(scene);
  // The union of the positive components' spheres.
  test::expectVecNear(b.bounds.lo, {-1, -1, -1}, 1e-15);
  test::expectVecNear(b.bounds.hi, {1, 1.5, 1}, 1e-15);
  // Spherical about the strongest component (as a sphere's: y up, u = 0.75
  // toward +x): the first ball's point on +x.
  const double R = std::sqrt(1 - std::sqrt(0.25));
  const Vec2 uv = uvAt(b, scene.arrays(), Vec3(R, 0, 0));
  EXPECT_NEAR(uv.x, 0.75, 1e-12);
  EXPECT_NEAR(uv.y, 0.5, 1e-12);
  EXPECT_NEAR(uvAt(b, scene.arrays(), Vec3(0, -R, 0)).y, 0.0, 1e-12);
  EXPECT_EQ(scene.kindCounts(), "1 blob");
}

TEST(Blob, ScLanguage) {
  const Scene s = parseScene("blob 0.5 2\n  -0.5 0 0  1 1\n  0.5 0 0  1 1\n"
                             "push translate 0 0 5 scale 1 1 2 blob 1 1  0 0 0  1 3 pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Blob>().size(), 2u);
  EXPECT_EQ(s.kindCounts(), "2 blobs");
  EXPECT_EQ(s.blobComponents.size(), 3u);
  EXPECT_EQ(s.shapes<Blob>()[1].firstComponent, 2u);
  EXPECT_EQ(s.shapes<Blob>()[0].threshold, 0.5);
  EXPECT_TRUE(s.shapes<Blob>()[1].placed);
  EXPECT_EQ(s.describe({kindOf<Blob>, 0}), "blob #0 (t.sc:1)");
}

TEST(Blob, ScLanguageErrors) {
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  0 0 0 1"),
            "t.sc:1:1: error: blob: expected S1 but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 2  0 0 0 1 1\nsphere 0 0 0 1"),
            "t.sc:2:1: error: blob: expected X2 (a number) but found 'sphere'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0 1  0 0 0 1 1"),
            "t.sc:1:6: error: blob: THRESHOLD must be positive, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("blob -1 1  0 0 0 1 1"),
            "t.sc:1:6: error: blob: THRESHOLD must be positive, found '-1'");
  EXPECT_EQ(test::sceneErrorsOf("blob inf 1  0 0 0 1 1"),
            "t.sc:1:6: error: blob: THRESHOLD is not a finite number ('inf')");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 0"),
            "t.sc:1:10: error: blob: N must be an integer from 1 to 100000, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1.5  0 0 0 1 1"),
            "t.sc:1:10: error: blob: N must be an integer from 1 to 100000, found '1.5'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 2  0 0 0 1 1  1 0 nan 1 1"),
            "t.sc:1:28: error: blob: Z2 is not a finite number ('nan')");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 2  0 0 0 1 1  1 0 0 0 1"),
            "t.sc:1:30: error: blob: R2 must be positive, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  0 0 0 -1 1"),
            "t.sc:1:19: error: blob: R1 must be positive, found '-1'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  0 0 0 1 0"),
            "t.sc:1:21: error: blob: S1 must not be zero, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  0 0 0 1 -1"),
            "t.sc:1:1: error: blob: no component has a positive strength");
  EXPECT_EQ(test::sceneErrorsOf("blob 1 2  0 0 0 1 0.5  1 0 0 1 0.5"),
            "t.sc:1:1: error: blob: the positive strengths add up to at most the threshold, so "
            "the field never reaches it");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  0 0 0 1 1 2"),
            "t.sc:1:23: error: expected a command but found the number '2' (too many numbers "
            "for the command before it?)");
  EXPECT_EQ(test::sceneErrorsOf("blob 0.5 1  2e30 0 0 1 1"),
            "t.sc:1:1: error: blob: lies outside the supported range: world coordinates (after "
            "the current transform) must be within +-1e30");
  EXPECT_EQ(test::sceneErrorsOf("push scale 1 1 1e-11 blob 0.5 1  0 0 0 1 1 pop"),
            "t.sc:1:22: error: blob: the current transform stretches it too unevenly: one "
            "direction more than 1e10 times another");
}

TEST(Blob, WriterRoundTrip) {
  const std::string text = "surface 0.5 0.6 0.7  0.3 0.4 0.2  20 1.5\n"
                           "blob 0.5 3  -0.5 0 0  1 1  0.5 0 0  1 1  0 0.3 0  0.4 -0.5\n"
                           "push translate 1 0 0 rotate 1 2 3 40 scale 1 2 0.5\n"
                           "  blob 0.25 2  0 0 0  1 1  0.7 0 0  0.5 2\n"
                           "pop\n";
  const Scene a = parseScene(text, "t.sc");
  std::ostringstream out;
  writeScene(out, a);
  EXPECT_NE(out.str().find("blob 0.5 3\n  -0.5 0 0  1 1\n  0.5 0 0  1 1\n  0 0.3 0  0.4 -0.5\n"),
            std::string::npos)
      << out.str();
  const Scene b = parseScene(out.str(), "t2.sc");
  ASSERT_EQ(b.shapes<Blob>().size(), 2u) << out.str();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const Blob& ba = a.shapes<Blob>()[k];
    const Blob& bb = b.shapes<Blob>()[k];
    EXPECT_EQ(a.material({kindOf<Blob>, k}), b.material({kindOf<Blob>, k}));
    EXPECT_EQ(ba.threshold, bb.threshold);
    EXPECT_EQ(ba.placed, bb.placed);
    ASSERT_EQ(ba.componentCount, bb.componentCount);
    for (std::uint32_t i = 0; i < ba.componentCount; ++i) {
      const BlobComponent& ca = a.blobComponents[ba.firstComponent + i];
      const BlobComponent& cb = b.blobComponents[bb.firstComponent + i];
      EXPECT_EQ(ca.center, cb.center);
      EXPECT_EQ(ca.radius, cb.radius);
      EXPECT_EQ(ca.strength, cb.strength);
    }
    test::expectVecNear(ba.bounds.lo, bb.bounds.lo, 1e-12);
    test::expectVecNear(ba.bounds.hi, bb.bounds.hi, 1e-12);
    for (int i = 0; i < 200; ++i) {
      const Ray q = ray(Vec3(u(rng), u(rng), u(rng)) * 4.0, Vec3(u(rng), u(rng), u(rng)));
      std::vector<Crossing> ca, cb;
      appendCrossings(ba, a.arrays(), q, Interval{}, ca);
      appendCrossings(bb, b.arrays(), q, Interval{}, cb);
      if (ca.size() != cb.size()) continue; // within round-off of tangent
      for (std::size_t j = 0; j < ca.size(); ++j)
        EXPECT_NEAR(ca[j].t, cb[j].t, 1e-9);
    }
  }
}

TEST(Blob, ConvertWritesPovRayBlob) {
  const Scene s = parseScene("blob 0.5 2  -0.5 0 0  1 1  0.5 0 0  1 -0.25\n"
                             "push scale 1 2 1 blob 0.5 1  0 0 0  1 1 pop\n",
                             "t.sc");
  std::ostringstream out;
  writePov(out, s);
  EXPECT_NE(out.str().find("blob { threshold 0.5\n"
                           "  sphere { <-0.5, 0, 0>, 1, strength 1 }\n"
                           "  sphere { <0.5, 0, 0>, 1, strength -0.25 }\n"
                           "  sturm material { Prism_M0 }\n}\n"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("blob { threshold 0.5\n"
                           "  sphere { <0, 0, 0>, 1, strength 1 }\n"
                           "  sturm matrix <1, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0> material { "
                           "Prism_M0 }\n}\n"),
            std::string::npos)
      << out.str();
}

} // namespace
} // namespace prism
