// Every acceleration mode against brute force: the same nearest hit (found or
// not, t bit for bit, and which primitive, ties included) on many thousands of
// random rays over random scenes, with fixed seeds; rays that start on
// surfaces, run along the axes, lie in box faces or graze primitives; and
// any-hit agreeing with closest-hit on occlusion. Also the SAH builder's tree
// and the BVH's size.
#include "core/accel/bvh.h"
#include "core/accel/sah_builder.h"
#include "core/scene/camera.h"
#include "core/shapes/axis_frame.h"
#include "tools/scene_generators.h"

#include "scene_builder.h"
#include "test_expect.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

namespace prism {
namespace {

using test::addEllipsoid;
using test::addGroup;
using test::addIn;
using test::addMaterial;
using test::addPolygon;
using test::addSphere;
using test::randomUnit;

constexpr AccelKind kAccelerated[] = {AccelKind::Bvh, AccelKind::Groups};

// A direction that is axis-parallel three times in ten.
Vec3 randomDirection(std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(0, 9);
  const int k = pick(rng);
  if (k < 3) {
    Vec3 d(0.0);
    d[k] = pick(rng) < 5 ? -1.0 : 1.0;
    return d;
  }
  return randomUnit(rng);
}

// Spheres, ellipsoids and polygons (random triangles and n-gons, grid-aligned
// rectangles with shared edges, and exact duplicates for ties), spread over
// nested groups.
Scene randomScene(std::mt19937& rng, int primitives, int groups) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> cell(-12, 12), size(1, 5), axis(0, 2), kind(0, 9);
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  for (int g = 1; g <= groups; ++g) {
    std::uniform_int_distribution<int> parent(std::max(0, g - 3), g - 1);
    addGroup(scene, std::uint32_t(u(rng) < -0.6 ? 0 : parent(rng)));
  }
  std::uniform_int_distribution<std::uint32_t> pickGroup(0, std::uint32_t(scene.groups.size() - 1));
  for (int i = 0; i < primitives; ++i) {
    const std::uint32_t g = pickGroup(rng);
    const Vec3 c(8 * u(rng), 8 * u(rng), 8 * u(rng));
    switch (kind(rng)) {
    case 0:
    case 1: addSphere(scene, c, 0.05 + 1.5 * std::abs(u(rng)), mat, g); break;
    case 2: {
      Mat3 m;
      do
        m = Mat3(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)),
                 Vec3(u(rng), u(rng), u(rng)));
      while (std::abs(glm::determinant(m)) < 0.05);
      addEllipsoid(scene, 1.5 * m, c, mat, g);
      break;
    }
    case 3:
    case 4: { // grid-aligned rectangle: coplanar neighbours, shared edges, flat boxes
      const int a = axis(rng), b = (a + 1) % 3, cc = (a + 2) % 3;
      Vec3 lo(cell(rng) * 0.5, cell(rng) * 0.5, cell(rng) * 0.5);
      Vec3 p1 = lo, p2 = lo, p3 = lo;
      p1[b] += size(rng) * 0.5;
      p2[b] = p1[b];
      p2[cc] += size(rng) * 0.5;
      p3[cc] = p2[cc];
      addPolygon(scene, {lo, p1, p2, p3}, mat, g);
      break;
    }
    case 5: { // an exact duplicate of an earlier primitive: a tie to break
      if (!scene.shapes<Polygon>().empty() && u(rng) < 0) {
        const Polygon& p = scene.shapes<Polygon>()[std::size_t(
            std::abs(u(rng)) * double(scene.shapes<Polygon>().size() - 1))];
        std::vector<Vec3> v(scene.polygonVertices.begin() + p.firstVertex,
                            scene.polygonVertices.begin() + p.firstVertex + p.vertexCount);
        addPolygon(scene, v, mat, g);
      } else if (!scene.shapes<Sphere>().empty()) {
        const Sphere s = scene.shapes<Sphere>()[std::size_t(
            std::abs(u(rng)) * double(scene.shapes<Sphere>().size() - 1))];
        addSphere(scene, s.center, s.radius, mat, g);
      }
      break;
    }
    default: { // convex n-gon in a random plane, or a triangle
      const Vec3 n = randomUnit(rng);
      const Vec3 e1 =
          glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
      const Vec3 e2 = glm::cross(n, e1);
      const double r = 0.1 + 2 * std::abs(u(rng));
      const int count = 3 + int(std::abs(u(rng)) * 5);
      std::vector<Vec3> v;
      for (int k = 0; k < count; ++k) {
        const double a = 2 * std::numbers::pi * (k + 0.3 * u(rng)) / count;
        v.push_back(c + r * (std::cos(a) * e1 + std::sin(a) * e2));
      }
      if (!polygonProblem(v)) addPolygon(scene, v, mat, g);
      break;
    }
    }
  }
  return scene;
}

struct Tally {
  int queries = 0, hits = 0, ties = 0;
};

// One query against every accel: the same answer as brute force, and any-hit
// agrees with it. Returns brute force's answer.
bool expectSameHit(const Scene& scene, const std::vector<std::unique_ptr<Accel>>& accels,
                   const Accel& brute, const Ray& ray, Interval range, const PrimitiveRef* skip,
                   Tally& tally, Hit* out = nullptr) {
  ++tally.queries;
  Hit expected;
  const bool found = brute.closestHit(ray, range, skip, expected);
  EXPECT_EQ(brute.anyHit(ray, range, skip), found);
  for (const auto& accel : accels) {
    Hit h;
    const bool f = accel->closestHit(ray, range, skip, h);
    EXPECT_EQ(f, found) << "origin " << ray.origin.x << " " << ray.origin.y << " " << ray.origin.z
                        << " dir " << ray.dir.x << " " << ray.dir.y << " " << ray.dir.z;
    EXPECT_EQ(accel->anyHit(ray, range, skip), found);
    if (f && found) {
      EXPECT_EQ(h.t, expected.t);
      EXPECT_EQ(h.primitive, expected.primitive)
          << scene.describe(h.primitive) << " vs " << scene.describe(expected.primitive);
      // Nothing is hit before the nearest hit.
      Interval before = range;
      before.max = expected.t;
      EXPECT_FALSE(accel->anyHit(ray, before, skip));
    }
  }
  if (!found) return false;
  ++tally.hits;
  if (out != nullptr) *out = expected;
  // Count the ties the order of PrimitiveRef had to break.
  for (const PrimitiveRef& other : scene.allPrimitives()) {
    double t;
    if (other == expected.primitive || (skip != nullptr && other == *skip)) continue;
    if (intersectPrimitive(scene, other, ray, range, t) && t == expected.t) {
      EXPECT_TRUE(expected.primitive < other);
      ++tally.ties;
    }
  }
  return true;
}

// The range of query i: the whole ray, or one ending or starting at a random
// distance, by turns.
Interval variedRange(int i, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Interval range;
  if (i % 5 == 1) range.max = 2 + 20 * std::abs(u(rng));
  if (i % 5 == 2) range.min = 3 * std::abs(u(rng));
  return range;
}

// Every hierarchy, and the BVH a second time with its one-ray node test in
// SSE where the first takes AVX (on a processor that has it).
std::vector<std::unique_ptr<Accel>> accelerated(const Scene& scene) {
  std::vector<std::unique_ptr<Accel>> accels;
  for (AccelKind kind : kAccelerated)
    accels.push_back(makeAccel(scene, kind));
  Bvh::Options sse;
  sse.avx = false;
  accels.push_back(std::make_unique<Bvh>(scene, sse));
  return accels;
}

// A scene of one material and groups 1 to 6 nested below the top level
// (group g's parent is g / 2), for the tests of one kind below.
Scene nestedGroups(std::uint32_t& material) {
  Scene scene;
  material = addMaterial(scene, Material{});
  for (int g = 1; g <= 6; ++g)
    addGroup(scene, std::uint32_t(g / 2));
  return scene;
}

// The query over `range`, and when it hits, a secondary ray from the hit
// point in a random direction.
void expectSameHitAndFromIt(const Scene& scene, const std::vector<std::unique_ptr<Accel>>& accels,
                            const Accel& brute, const Ray& ray, Interval range, std::mt19937& rng,
                            Tally& tally) {
  Hit h;
  if (!expectSameHit(scene, accels, brute, ray, range, nullptr, tally, &h)) return;
  expectSameHit(scene, accels, brute, Ray{ray.at(h.t), randomDirection(rng)}, Interval{}, nullptr,
                tally);
}

TEST(Accel, EveryModeMatchesBruteForceOnRandomRays) {
  std::mt19937 rng(4004);
  std::uniform_real_distribution<double> u(-1, 1);
  Tally tally;
  int surfaceStarts = 0;
  for (int sceneIndex = 0; sceneIndex < 16; ++sceneIndex) {
    const Scene scene =
        randomScene(rng, 30 + 12 * sceneIndex, sceneIndex % 3 == 0 ? 0 : 3 * sceneIndex);
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    const std::vector<PrimitiveRef> prims = scene.allPrimitives();
    std::uniform_int_distribution<std::size_t> pick(0, prims.size() - 1);
    for (int i = 0; i < 800; ++i) {
      Ray ray{Vec3(14 * u(rng), 14 * u(rng), 14 * u(rng)), randomDirection(rng)};
      if (i % 2 == 0) { // aimed at a primitive's box centre, so most rays hit
        const Vec3 to = scene.bounds(prims[pick(rng)]).centroid();
        if (to != ray.origin) ray.dir = glm::normalize(to - ray.origin);
      }
      const Interval range = variedRange(i, rng);
      Hit h;
      if (!expectSameHit(scene, accels, *brute, ray, range, nullptr, tally, &h)) continue;
      // A secondary ray from exactly the point just hit, in every direction,
      // skipping the polygon it leaves half of the time (as the tracer does).
      const Ray onSurface{ray.at(h.t), randomDirection(rng)};
      const PrimitiveRef* skip =
          h.primitive.kind == kindOf<Polygon> && i % 2 == 0 ? &h.primitive : nullptr;
      expectSameHit(scene, accels, *brute, onSurface, Interval{}, skip, tally);
      ++surfaceStarts;
    }
  }
  EXPECT_GT(tally.queries, 10000);
  EXPECT_GT(tally.hits, 3000);
  EXPECT_GT(surfaceStarts, 2000);
  EXPECT_GT(tally.ties, 10); // the duplicates were really exercised
}

// Jacks: thin bars lying every way (cones the BVH bounds slice by slice, see
// core/accel/primitive_boxes.h), balls on their ends, some bars twice (ties).
// Rays aimed at the bars, leaving their surfaces, and grazing them.
TEST(Accel, SlicedConesMatchBruteForce) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  Tally tally;
  for (int sceneIndex = 0; sceneIndex < 6; ++sceneIndex) {
    Scene scene;
    const std::uint32_t mat = addMaterial(scene, Material{});
    for (int i = 0; i < 60 + 30 * sceneIndex; ++i) {
      const Vec3 c(6 * u(rng), 6 * u(rng), 6 * u(rng));
      const Vec3 half = (0.5 + 1.5 * unit(rng)) * randomUnit(rng);
      const double r = 0.02 + 0.08 * unit(rng), apexR = i % 4 == 0 ? 0.0 : r;
      for (int copy = 0; copy < (i % 7 == 0 ? 2 : 1); ++copy)
        addIn(scene, 0, [&](SceneBuilder& build) {
          Cone cone = makeCone(c - half, r, c + half, apexR);
          cone.material = mat;
          return build.add(cone);
        });
      addSphere(scene, c - half, 2 * r, mat);
      addSphere(scene, c + half, 2 * r, mat);
    }
    // Also the BVH that keeps the slices whatever memory they take, so they
    // are really there (several references to one cone).
    auto accels = accelerated(scene);
    accels.push_back(std::make_unique<Bvh>(scene, Bvh::Options{0}));
    EXPECT_GT(static_cast<const Bvh&>(*accels.back()).referenceCount(), scene.primitiveCount());
    const auto brute = makeAccel(scene, AccelKind::None);
    const std::vector<Cone>& cones = scene.shapes<Cone>();
    std::uniform_int_distribution<std::size_t> pick(0, cones.size() - 1);
    for (int i = 0; i < 600; ++i) {
      const Cone& target = cones[pick(rng)];
      // A point of the target's axis, and one on its side (in its frame: the
      // radius at that height along the frame's x axis).
      const double z = unit(rng);
      const Vec3 onAxis = target.objectToWorldOffset + z * target.objectToWorld[2];
      const double radius = (1 - z) * target.baseRadius + z * target.apexRadius;
      const Vec3 side = onAxis + radius * target.objectToWorld[0];
      const Vec3 from(10 * u(rng), 10 * u(rng), 10 * u(rng));
      const Vec3 aim = i % 3 == 0 ? side : onAxis;
      if (aim == from) continue;
      Hit h;
      const Ray ray{from, glm::normalize(aim - from)};
      if (expectSameHit(scene, accels, *brute, ray, Interval{}, nullptr, tally, &h))
        expectSameHit(scene, accels, *brute, Ray{ray.at(h.t), randomDirection(rng)}, Interval{},
                      nullptr, tally);
      // Along the side, tangent to it: the frame's y axis at that point.
      const Vec3 along = glm::normalize(target.objectToWorld[1]);
      expectSameHit(scene, accels, *brute, Ray{side - 5.0 * along, along}, Interval{}, nullptr,
                    tally);
    }
  }
  EXPECT_GT(tally.queries, 5000);
  EXPECT_GT(tally.hits, 2500);
  EXPECT_GT(tally.ties, 10); // the doubled bars
}

// Blobs (one primitive of several components, some negative) among spheres,
// in nested groups: rays at the components' centres and at random, and
// secondary rays from the points they hit.
TEST(Accel, BlobsMatchBruteForce) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uint32_t mat = 0;
  Scene scene = nestedGroups(mat);
  std::vector<Vec3> centres;
  for (int i = 0; i < 60; ++i) {
    const std::uint32_t g = std::uint32_t(i % 7);
    const Vec3 c(6 * u(rng), 6 * u(rng), 6 * u(rng));
    if (i % 10 == 9) {
      addSphere(scene, c, 0.5, mat, g);
      continue;
    }
    std::vector<BlobComponent> components;
    for (int k = 0; k < 1 + i % 4; ++k) {
      components.push_back({c + 0.6 * Vec3(u(rng), u(rng), u(rng)), 0.4 + 0.5 * std::abs(u(rng)),
                            k == 3 ? -0.5 : 1.0});
      centres.push_back(components.back().center);
    }
    const Mat3 linear =
        i % 3 == 0 ? Mat3(1.0) : Mat3(Vec3(1, 0.2, 0), Vec3(0, 0.7, 0.1), Vec3(0.3, 0, 1.2));
    PlacedBlob placed = makeBlob(components, 0.4, linear, c - linear * c);
    placed.blob.material = mat;
    addIn(scene, g, [&](SceneBuilder& build) { return build.blob(placed); });
  }
  const auto accels = accelerated(scene);
  const auto brute = makeAccel(scene, AccelKind::None);
  std::uniform_int_distribution<std::size_t> pick(0, centres.size() - 1);
  Tally tally;
  for (int i = 0; i < 2000; ++i) {
    Ray ray{Vec3(12 * u(rng), 12 * u(rng), 12 * u(rng)), randomDirection(rng)};
    if (i % 2 == 0) ray.dir = glm::normalize(centres[pick(rng)] - ray.origin);
    expectSameHitAndFromIt(scene, accels, *brute, ray, variedRange(i, rng), rng, tally);
  }
  EXPECT_GT(tally.hits, 800);
}

// Tori (whose test isolates a quartic's roots) among spheres, in nested
// groups, some interlocked: rays aimed through the holes (at the centres), at
// the inner rims, and secondary rays from the points they hit, in every
// direction and range.
TEST(Accel, ToriMatchBruteForce) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uint32_t mat = 0;
  Scene scene = nestedGroups(mat);
  std::vector<Vec3> rims;
  for (int i = 0; i < 120; ++i) {
    const std::uint32_t g = std::uint32_t(i % 7);
    const Vec3 c(6 * u(rng), 6 * u(rng), 6 * u(rng)), axis = randomUnit(rng);
    const double major = 0.3 + std::abs(u(rng)), minor = major * (0.01 + 0.8 * std::abs(u(rng)));
    if (i % 10 == 9) {
      addSphere(scene, c, major, mat, g);
      continue;
    }
    Torus t = makeTorus(c, axis, major, minor);
    t.material = mat;
    addIn(scene, g, [&](SceneBuilder& build) { return build.add(t); });
    Vec3 x, y;
    perpendicularPair(axis, x, y);
    rims.push_back(c + (major - minor) * x);
  }
  const auto accels = accelerated(scene);
  const auto brute = makeAccel(scene, AccelKind::None);
  const std::vector<PrimitiveRef> prims = scene.allPrimitives();
  std::uniform_int_distribution<std::size_t> pick(0, prims.size() - 1), rim(0, rims.size() - 1);
  Tally tally;
  for (int i = 0; i < 3000; ++i) {
    Ray ray{Vec3(12 * u(rng), 12 * u(rng), 12 * u(rng)), randomDirection(rng)};
    const Vec3 to = i % 3 == 0   ? scene.bounds(prims[pick(rng)]).centroid()
                    : i % 3 == 1 ? rims[rim(rng)] + 1e-9 * randomUnit(rng)
                                 : ray.origin + ray.dir;
    if (to != ray.origin) ray.dir = glm::normalize(to - ray.origin);
    expectSameHitAndFromIt(scene, accels, *brute, ray, variedRange(i, rng), rng, tally);
  }
  EXPECT_GT(tally.hits, 1500);
}

TEST(Accel, RaysInBoxFacesAlongEdgesAndGrazingPrimitives) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  Tally tally;
  for (int sceneIndex = 0; sceneIndex < 8; ++sceneIndex) {
    const Scene scene = randomScene(rng, 80 + 20 * sceneIndex, sceneIndex * 2);
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    const std::vector<PrimitiveRef> prims = scene.allPrimitives();
    std::uniform_int_distribution<std::size_t> pick(0, prims.size() - 1);
    std::uniform_int_distribution<int> axis(0, 2);
    for (int i = 0; i < 400; ++i) {
      const PrimitiveRef target = prims[pick(rng)];
      const Aabb box = scene.bounds(target);
      // A point on a face of the primitive's box, a ray lying in that face's
      // plane (axis-parallel or not) or running along one of its edges.
      const int a = axis(rng);
      Vec3 o = box.lo + Vec3(unit(rng), unit(rng), unit(rng)) * box.extent();
      o[a] = i % 2 == 0 ? box.lo[a] : box.hi[a];
      Vec3 d = randomUnit(rng);
      d[a] = 0.0;
      if (i % 3 == 0) {
        d = Vec3(0.0);
        d[(a + 1) % 3] = u(rng) < 0 ? -1 : 1;
        o[(a + 2) % 3] = u(rng) < 0 ? box.lo[(a + 2) % 3] : box.hi[(a + 2) % 3]; // an edge
      }
      if (glm::dot(d, d) == 0.0) continue;
      d = glm::normalize(d);
      expectSameHit(scene, accels, *brute, Ray{o - 20.0 * d, d}, Interval{}, nullptr, tally);
      // Straight at a box corner, and at a polygon's vertex.
      const Vec3 corner(u(rng) < 0 ? box.lo.x : box.hi.x, u(rng) < 0 ? box.lo.y : box.hi.y,
                        u(rng) < 0 ? box.lo.z : box.hi.z);
      const Vec3 from(15 * u(rng), 15 * u(rng), 15 * u(rng));
      if (corner != from)
        expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(corner - from)}, Interval{},
                      nullptr, tally);
      if (target.kind == kindOf<Polygon>) {
        const Polygon& p = scene.shapes<Polygon>()[target.index];
        const Vec3 v = scene.polygonVertices[p.firstVertex + std::uint32_t(i) % p.vertexCount];
        if (v != from)
          expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(v - from)}, Interval{},
                        nullptr, tally);
      }
      // Tangent to a sphere: through the point at exactly its radius off the
      // centre, perpendicular to the offset.
      if (target.kind == kindOf<Sphere>) {
        const Sphere& s = scene.shapes<Sphere>()[target.index];
        const Vec3 n = randomUnit(rng);
        Vec3 t = glm::cross(n, randomUnit(rng));
        if (glm::dot(t, t) > 1e-6) {
          t = glm::normalize(t);
          expectSameHit(scene, accels, *brute, Ray{s.center + s.radius * n - 10.0 * t, t},
                        Interval{}, nullptr, tally);
        }
      }
    }
  }
  EXPECT_GT(tally.queries, 5000);
  EXPECT_GT(tally.hits, 1500);
}

// A height field of n x n squares, two mesh triangles each over shared
// vertices (a ray through an edge or a vertex meets two to six triangles at
// one t), wavy and tilted, with loose triangles of their own vertices
// crossing it and a few spheres: leaves of several triangles, which the BVH
// tests together, and leaves of mixed kinds. The corners of the squares are
// returned, to aim at.
Scene triangleField(std::mt19937& rng, int n, double size, const Vec3& centre,
                    std::vector<Vec3>& corners) {
  std::uniform_real_distribution<double> u(-1, 1);
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  SceneBuilder build(scene);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = size * (double(i) / n - 0.5), z = size * (double(j) / n - 0.5);
      const Vec3 v = centre + Vec3(x, 0.1 * size * std::sin(7.0 * x / size) + 0.02 * x, z);
      scene.meshVertices.push_back(v);
      corners.push_back(v);
    }
  auto at = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      build.meshTriangle({at(i, j), at(i + 1, j + 1), at(i + 1, j)}, nullptr, mat, Origin{});
      build.meshTriangle({at(i, j), at(i, j + 1), at(i + 1, j + 1)}, nullptr, mat, Origin{});
    }
  for (int k = 0; k < n * n / 4; ++k) {
    const Vec3 a = centre + 0.5 * size * Vec3(u(rng), 0.2 * u(rng), u(rng));
    const std::array<Vec3, 3> v{a, a + 0.1 * size * randomUnit(rng),
                                a + 0.1 * size * randomUnit(rng)};
    if (!triangleProblem(v[0], v[1], v[2])) build.triangle(v, nullptr, mat, Origin{});
    if (k % 8 == 0) addSphere(scene, a, 0.02 * size, mat);
  }
  return scene;
}

// Mesh triangles, which the BVH tests up to four at a time
// (core/accel/packets.h), against brute force's one by one: rays at
// the field's vertices and edges (ties between neighbours), grazing it, from
// its surface, and at scales from 1e-5 to 1e6 and far from the origin.
TEST(Accel, TriangleMeshesMatchBruteForce) {
  struct Placement {
    double size;
    Vec3 centre;
  };
  const Placement placements[] = {
      {10.0, Vec3(0.0)}, {1e-5, Vec3(0.0)}, {1e6, Vec3(0.0)}, {1.0, Vec3(3e4, -2e4, 1e4)}};
  constexpr int n = 24; // squares per side
  std::mt19937 rng(2612);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  std::uniform_int_distribution<int> cell(0, n - 1), side(0, 2);
  Tally tally;
  for (const Placement& place : placements) {
    std::vector<Vec3> corners;
    const Scene scene = triangleField(rng, n, place.size, place.centre, corners);
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    for (int i = 0; i < 700; ++i) {
      const Vec3 from = place.centre + place.size * Vec3(u(rng), 0.3 + unit(rng), u(rng));
      // A vertex, the middle of an edge (or of a square's diagonal), or a
      // point inside a square.
      const int ci = cell(rng), cj = cell(rng), s = side(rng);
      const Vec3 a = corners[std::size_t(ci * (n + 1) + cj)];
      const Vec3 b = corners[std::size_t((ci + (s != 1)) * (n + 1) + cj + (s != 0))];
      const Vec3 c = corners[std::size_t((ci + 1) * (n + 1) + cj)];
      Vec3 to = a;
      if (i % 3 == 1) to = 0.5 * (a + b);
      if (i % 3 == 2) to = a + 0.5 * unit(rng) * (b - a) + 0.5 * unit(rng) * (c - a);
      if (to == from) continue;
      Ray ray{from, glm::normalize(to - from)};
      if (i % 10 == 9) ray.dir = glm::normalize(Vec3(u(rng), 1e-3 * u(rng), u(rng))); // grazing
      const Interval range = i % 7 == 3 ? Interval{0.0, glm::length(to - from)} : Interval{};
      Hit h;
      if (!expectSameHit(scene, accels, *brute, ray, range, nullptr, tally, &h)) continue;
      // From the point hit, on, skipping the triangle left half of the time.
      const Ray onSurface{ray.at(h.t), randomDirection(rng)};
      expectSameHit(scene, accels, *brute, onSurface, Interval{},
                    i % 2 == 0 ? &h.primitive : nullptr, tally);
    }
  }
  EXPECT_GT(tally.queries, 4000);
  EXPECT_GT(tally.hits, 2000);
  EXPECT_GT(tally.ties, 100); // rays through shared edges and vertices
}

TEST(Accel, AnyHitAgreesWithClosestHitOnOcclusion) {
  // Shadow-ray queries as the tracer makes them: from a point on a surface to
  // a light, the range ending at the light.
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> u(-1, 1);
  int occluded = 0, clear = 0;
  for (int sceneIndex = 0; sceneIndex < 6; ++sceneIndex) {
    const Scene scene = randomScene(rng, 150, 10);
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Groups, AccelKind::None}) {
      const auto accel = makeAccel(scene, kind);
      std::mt19937 local{std::uint32_t(sceneIndex)};
      std::uniform_real_distribution<double> v(-1, 1);
      for (int i = 0; i < 800; ++i) {
        const Vec3 from(12 * v(local), 12 * v(local), 12 * v(local));
        const Vec3 light(12 * v(local), 12 * v(local), 12 * v(local));
        const double length = glm::length(light - from);
        if (length == 0.0) continue;
        const Ray ray{from, (light - from) / length};
        const Interval range{0.0, length};
        Hit h;
        const bool blocked = accel->closestHit(ray, range, nullptr, h);
        EXPECT_EQ(accel->anyHit(ray, range, nullptr), blocked) << accelKindName(kind);
        // The blocker it names really lies on the ray inside the range.
        PrimitiveRef blocker{kindOf<Sphere>, 0xffffffffu};
        EXPECT_EQ(accel->anyHit(ray, range, nullptr, &blocker), blocked);
        if (blocked) {
          double t;
          EXPECT_TRUE(intersectPrimitive(scene, blocker, ray, range, t));
          EXPECT_LT(h.t, length);
          // With the range ending just before the blocker, nothing blocks.
          EXPECT_FALSE(accel->anyHit(ray, Interval{0.0, h.t}, nullptr));
          // Skipping the blocker: any-hit is exactly "is there another one".
          Hit second;
          EXPECT_EQ(accel->anyHit(ray, range, &h.primitive),
                    accel->closestHit(ray, range, &h.primitive, second));
        }
        (blocked ? occluded : clear) += kind == AccelKind::Bvh;
      }
    }
  }
  EXPECT_GT(occluded, 500);
  EXPECT_GT(clear, 500);
  (void)u;
}

TEST(Accel, GeneratedScenesMatchBruteForce) {
  std::mt19937 rng(2025);
  std::uniform_real_distribution<double> u(-1, 1);
  Tally tally;
  for (const Scene& scene :
       {makePolygonSoup(3000, 7), makeScaledPolygonSoup(3000, 5), makeSphereflake(820)}) {
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    for (int i = 0; i < 600; ++i) {
      const Vec3 from(3 * u(rng), 3 * u(rng), 3 * u(rng));
      const Vec3 to(u(rng), u(rng), u(rng));
      const Ray ray{from, i % 3 == 0 ? randomDirection(rng) : glm::normalize(to - from)};
      Hit h;
      if (expectSameHit(scene, accels, *brute, ray, Interval{}, nullptr, tally, &h)) {
        const Ray onSurface{ray.at(h.t), randomDirection(rng)};
        expectSameHit(scene, accels, *brute, onSurface, Interval{},
                      h.primitive.kind == kindOf<Polygon> ? &h.primitive : nullptr, tally);
      }
    }
  }
  EXPECT_GT(tally.hits, 500);
}

// Eye rays as the renderer bundles them (8x8 pixel blocks, 4x4 sub-pixel
// grids), from cameras inside and around randomized scenes, and bundles that
// cannot walk together (mixed signs, axis-parallel rays, two origins, one
// ray): every ray gets brute force's nearest hit.
TEST(Accel, BundlesOfRaysMatchBruteForce) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(-1, 1);
  int together = 0, apart = 0, rays = 0, hits = 0;
  auto expectBundle = [&](const Scene& scene, const std::vector<std::unique_ptr<Accel>>& accels,
                          const Accel& brute, const std::vector<Ray>& bundle) {
    (walksTogether(bundle) ? together : apart) += 1;
    for (const auto& accel : accels) {
      std::vector<Hit> got(bundle.size());
      const std::uint64_t found = accel->closestHits(bundle, got);
      for (std::size_t i = 0; i < bundle.size(); ++i) {
        Hit expected;
        const bool f = brute.closestHit(bundle[i], Interval{}, nullptr, expected);
        ASSERT_EQ((found >> i & 1u) != 0, f) << "ray " << i << " of " << bundle.size();
        if (!f) continue;
        EXPECT_EQ(got[i].t, expected.t);
        EXPECT_EQ(got[i].primitive, expected.primitive)
            << scene.describe(got[i].primitive) << " vs " << scene.describe(expected.primitive);
        hits += accel.get() == accels.front().get();
      }
      rays += int(bundle.size()) * (accel.get() == accels.front().get());
    }
  };
  std::vector<Scene> scenes;
  for (int i = 0; i < 3; ++i)
    scenes.push_back(randomScene(rng, 400, 12));
  scenes.push_back(makeScaledPolygonSoup(2000, 3));
  scenes.push_back(makeSphereflake(400));
  std::vector<Vec3> corners;
  scenes.push_back(triangleField(rng, 24, 10.0, Vec3(0.0), corners)); // leaves of triangles
  for (const Scene& scene : scenes) {
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    for (int view = 0; view < 6; ++view) {
      CameraSpec spec;
      spec.eye = Vec3(14 * u(rng), 14 * u(rng), 14 * u(rng)) * (view % 3 == 0 ? 0.3 : 1.0);
      spec.lookat = Vec3(2 * u(rng), 2 * u(rng), 2 * u(rng));
      spec.fov = 20 + 60 * std::abs(u(rng));
      if (glm::length(glm::cross(spec.lookat - spec.eye, spec.up)) < 1e-6) continue;
      const Camera camera(spec, 48, 40);
      for (int by = 0; by < 40; by += 8)
        for (int bx = 0; bx < 48; bx += 8) {
          std::vector<Ray> block, grid;
          for (int y = by; y < by + 8; ++y)
            for (int x = bx; x < bx + 8; ++x)
              block.push_back(camera.eyeRay(x + 0.5, y + 0.5));
          expectBundle(scene, accels, *brute, block);
          for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
              grid.push_back(camera.eyeRay(bx + (i + 0.5) / 4.0, by + (j + 0.5) / 4.0));
          expectBundle(scene, accels, *brute, grid);
        }
    }
    // Axis-parallel rays (a zero component), mixed signs, two origins, one ray.
    const Vec3 o(0.5, -0.25, 11.0);
    expectBundle(scene, accels, *brute,
                 {Ray{o, {0, 0, -1}}, Ray{o, glm::normalize(Vec3(0.1, 0.1, -1))}});
    expectBundle(
        scene, accels, *brute,
        {Ray{o, glm::normalize(Vec3(-0.1, 0.1, -1))}, Ray{o, glm::normalize(Vec3(0.1, 0.1, -1))}});
    expectBundle(scene, accels, *brute,
                 {Ray{o, Vec3(0, 0, -1)}, Ray{o + Vec3(0.5, 0, 0), Vec3(0, 0, -1)}});
    expectBundle(scene, accels, *brute, {Ray{o, glm::normalize(Vec3(0.05, 0.02, -1))}});
  }
  EXPECT_GT(together, 500); // most bundles took the shared walk
  EXPECT_GE(apart, 20);
  EXPECT_GT(hits, rays / 4);

  // Directions that are not finite never walk together; more than a bundle
  // holds is refused, not overrun.
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(
      walksTogether(std::vector<Ray>{Ray{Vec3(0.0), {0, 0, -1}}, Ray{Vec3(0.0), {inf, 1, -1}}}));
  const Scene scene = makeSphereflake(10);
  const auto bvh = makeAccel(scene, AccelKind::Bvh);
  const std::vector<Ray> tooMany(Accel::kMaxBundle + 1, Ray{Vec3(0, 0, 9), Vec3(0.01, 0.01, -1)});
  std::vector<Hit> hitsOut(tooMany.size());
  EXPECT_THROW((void)bvh->closestHits(tooMany, hitsOut), std::length_error);
}

TEST(Accel, DegenerateInputs) {
  Tally tally;
  // No primitives at all.
  {
    const Scene empty;
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Groups, AccelKind::None}) {
      const auto accel = makeAccel(empty, kind);
      Hit h;
      EXPECT_FALSE(accel->closestHit(Ray{Vec3(0.0), Vec3(0, 0, 1)}, Interval{}, nullptr, h));
      EXPECT_FALSE(accel->anyHit(Ray{Vec3(0.0), Vec3(0, 0, 1)}, Interval{}, nullptr));
    }
  }
  // One primitive: the root is a leaf.
  {
    Scene scene;
    const std::uint32_t mat = addMaterial(scene, Material{});
    addSphere(scene, Vec3(0, 0, -5), 1.0, mat);
    const auto bvh = makeAccel(scene, AccelKind::Bvh);
    Hit h;
    ASSERT_TRUE(bvh->closestHit(Ray{Vec3(0.0), Vec3(0, 0, -1)}, Interval{}, nullptr, h));
    EXPECT_EQ(h.t, 4.0);
    EXPECT_FALSE(bvh->anyHit(Ray{Vec3(0.0), Vec3(0, 0, 1)}, Interval{}, nullptr));
  }
  // 200 identical spheres (centroids cannot be told apart: median splits), and
  // spheres at exponentially growing distances (SAH would make a deep chain).
  {
    Scene scene;
    const std::uint32_t mat = addMaterial(scene, Material{});
    for (int i = 0; i < 200; ++i)
      addSphere(scene, Vec3(1, 2, 3), 0.5, mat);
    for (int i = 0; i < 300; ++i)
      addSphere(scene, Vec3(std::ldexp(1.0, i / 4), 0, 0), 0.25, mat);
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
      const Vec3 target = i % 2 == 0 ? Vec3(1, 2, 3) : Vec3(std::ldexp(1.0, i % 60), 0, 0);
      const Vec3 from = target + Vec3(5 * u(rng), 5 * u(rng), 5 * u(rng));
      if (from == target) continue;
      expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(target - from)}, Interval{},
                    nullptr, tally);
    }
    EXPECT_GT(tally.ties, 400); // every hit on the 200 copies is a tie
  }
}

// Rays that start 1e15 to 4e16 away from a unit sphere (as a ray reflected
// inside a sphere of radius 4e16 does): the sphere's test, relative to its
// centre, may hit where the box test, rounding bound - origin at that
// distance, missed the box. Found by fuzzing; boxes are widened by boxSlack.
TEST(Accel, RaysFromFarAwayAgreeWithBruteForce) {
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  addSphere(scene, Vec3(0.0), 1.0, mat);
  addSphere(scene, Vec3(3, 0, 0), 1.0, mat);
  addSphere(scene, Vec3(0, 3, 0), 0.5, mat);
  addPolygon(scene, {{-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}}, mat);
  for (int i = 0; i < 40; ++i)
    addSphere(scene, Vec3(1e3 * i, 0, 0), 0.25, mat); // an inner node or two
  const auto accels = accelerated(scene);
  const auto brute = makeAccel(scene, AccelKind::None);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.5, 1.5), scale(15.0, 16.7);
  Tally tally;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 from = randomUnit(rng) * std::pow(10.0, scale(rng));
    const Vec3 target(u(rng), u(rng), u(rng));
    expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(target - from)}, Interval{},
                  nullptr, tally);
  }
  EXPECT_GT(tally.hits, 500);
}

// The BVH tests a ray's nodes in single precision where the ray allows it
// (core/accel/bvh.cpp, FloatNodeTest): small things far from the origin,
// where a float origin is coarser than the things; tiny and huge scenes;
// direction components so small that 1/d is near float's limit; and, on the
// double-precision path, origins beyond 2^100, components below 2^-100 and
// ranges that start before the origin. Rays from around each cluster and
// from the points they hit, the whole ray and ranges that end or start
// inside the cluster.
TEST(Accel, SinglePrecisionNodeTestsMissNothingAtAnyScale) {
  struct Cluster {
    double size;   // the things' spread
    double offset; // how far from the origin (on every axis)
  };
  const Cluster clusters[] = {{1.0, 0.0},  {1e-3, 1e7},  {1e-6, 3e4}, {1e-30, 0.0}, {1e-30, 1e-25},
                              {1e25, 0.0}, {1e27, 2e29}, {2e-9, 1.0}, {1e26, 3e30}, {1e-31, 0.0}};
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  for (const Cluster& c : clusters) {
    SCOPED_TRACE("size " + std::to_string(c.size) + " offset " + std::to_string(c.offset));
    Scene scene;
    const std::uint32_t mat = addMaterial(scene, Material{});
    const Vec3 centre(c.offset);
    auto at = [&] { return centre + c.size * Vec3(u(rng), u(rng), u(rng)); };
    std::vector<Vec3> corners; // the triangles' vertices: corners of their boxes
    for (int i = 0; i < 150; ++i) {
      addSphere(scene, at(), c.size * (0.01 + 0.05 * unit(rng)), mat);
      if (c.size < 1e-6 * c.offset) continue; // a triangle too small to be one there
      const Vec3 a = at();
      const Vec3 e1 = 0.1 * c.size * randomUnit(rng), e2 = 0.1 * c.size * randomUnit(rng);
      addPolygon(scene, {a, a + e1, a + e1 + e2}, mat);
      corners.insert(corners.end(), {a, a + e1, a + e1 + e2});
    }
    const auto accels = accelerated(scene);
    const auto brute = makeAccel(scene, AccelKind::None);
    Tally tally;
    for (int i = 0; i < 1500; ++i) {
      const Vec3 from = centre + 3.0 * c.size * randomUnit(rng);
      Vec3 dir = glm::normalize(at() - from);
      // Now and then a component near float's limits for 1/d: 1e-25 is taken
      // in single precision, 1e-35 (below 2^-100) in double.
      if (i % 7 == 3) dir[i % 3] = (i % 2 ? 1e-25 : -1e-35);
      Interval range;
      if (i % 5 == 1) range.max = c.size * (2.0 + 2.0 * unit(rng));
      if (i % 5 == 2) range.min = c.size * (2.0 + unit(rng));
      if (i % 11 == 4) range.min = -c.size * unit(rng); // the double path
      expectSameHitAndFromIt(scene, accels, *brute, Ray{from, dir}, range, rng, tally);
    }
    // From near the world's origin, far from a cluster that is far from it,
    // through the triangles' vertices: the ray just clips the boxes' corners,
    // where a relative error of t (which grows with the distance travelled)
    // is what the float test must allow for.
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Vec3 from = c.size * Vec3(u(rng), u(rng), u(rng));
      expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(corners[i] - from)}, Interval{},
                    nullptr, tally);
    }
    EXPECT_GT(tally.hits, 200);
  }
}

// A polygon whose vertices lie a little off its plane (the readers accept
// 1e-3 of its size) is hit on the plane, which may pass outside the box of
// the vertices: that box culled hits the polygon's own test finds.
TEST(Accel, SlightlyNonPlanarPolygonsAreNeverCulled) {
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  // A tall thin quad, one vertex 0.9e-3 of the size off the others' plane.
  addPolygon(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0.0018 * 2.83}, {-1, 1, 0}}, mat);
  for (int i = 0; i < 40; ++i)
    addSphere(scene, Vec3(10.0 + i, 0, 0), 0.25, mat);
  const auto accels = accelerated(scene);
  const auto brute = makeAccel(scene, AccelKind::None);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Tally tally;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 target(u(rng), u(rng), 0.0);
    const Vec3 from = target + 4.0 * randomUnit(rng);
    expectSameHit(scene, accels, *brute, Ray{from, glm::normalize(target - from)}, Interval{},
                  nullptr, tally);
  }
  // Near (-1, -1) the plane dips below z = 0, the vertices' lowest: rays
  // running level just below it never enter the vertices' box, yet hit.
  std::uniform_real_distribution<double> y(-1.0, -0.5), z(-1e-3, -1e-4);
  const int before = tally.hits;
  for (int i = 0; i < 2000; ++i) {
    expectSameHit(scene, accels, *brute, Ray{Vec3(-3.0, y(rng), z(rng)), Vec3(1, 0, 0)}, Interval{},
                  nullptr, tally);
  }
  EXPECT_GT(tally.hits - before, 200);
  EXPECT_GT(tally.hits, 1000);
}

// Four unit cubes at x = 0, 2, 4 and 6: the parent box (7 x 1 x 1) has half
// area 15, two cubes' box 7, three cubes' 11, one cube 3. Alone, a leaf of
// the four costs 0.8 x 4 = 3.2 and the cheapest split (two and two)
// 1 + 0.8 x (7 x 2 + 7 x 2) / 15 = 2.49, so it splits. Tested as one packet
// (cost 1.5) the leaf costs 0.8 x 1.5 = 1.2 against 1 + 0.8 x (7 x 1.5 + 7 x
// 1.5) / 15 = 2.12 for any split: a leaf. With the last cube not packed the
// leaf costs 0.8 x (1.5 + 1) = 2.0 and the cheapest split (that cube alone)
// 1 + 0.8 x (11 x 1.5 + 3 x 1) / 15 = 2.04: a leaf still.
TEST(SahBuilder, PacketsMakeALeafOfWhatAloneWouldSplit) {
  std::vector<Aabb> boxes;
  for (int i = 0; i < 4; ++i) {
    Aabb b;
    b.extend(Vec3(2.0 * i, 0, 0));
    b.extend(Vec3(2.0 * i + 1, 1, 1));
    boxes.push_back(b);
  }
  SahOptions packets;
  packets.packetSize = 4;
  packets.packetCost = 1.5;
  EXPECT_GT(buildSahTree(boxes).nodes.size(), 1u);
  EXPECT_GT(buildSahTree(boxes, packets).nodes.size(), 1u); // no box is packed
  const SahTree packed = buildSahTree(boxes, packets, {true, true, true, true});
  ASSERT_EQ(packed.nodes.size(), 1u);
  EXPECT_EQ(packed.nodes[0].count, 4u);
  EXPECT_EQ(buildSahTree(boxes, packets, {true, true, true, false}).nodes.size(), 1u);
  // Packets of one cost as much as the primitive alone: the split again.
  packets.packetSize = 1;
  packets.packetCost = 1.0;
  EXPECT_GT(buildSahTree(boxes, packets, {true, true, true, true}).nodes.size(), 1u);
}

TEST(SahBuilder, EveryBoxInExactlyOneLeafInsideItsAncestors) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 5000; ++i) {
    Aabb b;
    const Vec3 c(100 * u(rng), 10 * u(rng), u(rng));
    b.extend(c);
    b.extend(c + Vec3(std::abs(u(rng)), std::abs(u(rng)), i % 7 == 0 ? 0.0 : std::abs(u(rng))));
    boxes.push_back(b);
  }
  const SahTree tree = buildSahTree(boxes);
  ASSERT_FALSE(tree.nodes.empty());
  std::vector<int> seen(boxes.size(), 0);
  // Walk from the root, checking containment.
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const SahTree::Node& n = tree.nodes[stack.back()];
    stack.pop_back();
    if (n.leaf()) {
      EXPECT_LE(n.count, SahOptions{}.maxLeaf);
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const Aabb& b = boxes[tree.order[i]];
        ++seen[tree.order[i]];
        for (int a = 0; a < 3; ++a) {
          EXPECT_LE(n.box.lo[a], b.lo[a]);
          EXPECT_GE(n.box.hi[a], b.hi[a]);
        }
      }
      continue;
    }
    for (std::uint32_t c : {n.left, n.right}) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(n.box.lo[a], tree.nodes[c].box.lo[a]);
        EXPECT_GE(n.box.hi[a], tree.nodes[c].box.hi[a]);
      }
      stack.push_back(c);
    }
  }
  for (int s : seen)
    EXPECT_EQ(s, 1);
  EXPECT_LT(tree.depth, 60);
}

TEST(Generators, TheScaledSoupIsTheSoupAtAFinerGrainStoredInSpatialOrder) {
  for (std::size_t n : {1000u, 8000u}) {
    const Scene scaled = makeScaledPolygonSoup(n);
    const Scene random = makePolygonSoup(n);
    ASSERT_EQ(scaled.shapes<Polygon>().size(), n);
    ASSERT_EQ(random.shapes<Polygon>().size(), n);
    // Circumradius three quarters of the mean spacing (8 / n)^(1/3).
    const double radius = 0.75 * std::cbrt(8.0 / double(n));
    auto centre = [](const Scene& s, std::size_t i) {
      const Vec3* v = &s.polygonVertices[s.shapes<Polygon>()[i].firstVertex];
      return (v[0] + v[1] + v[2]) / 3.0;
    };
    double stepScaled = 0.0, stepRandom = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 c = centre(scaled, i);
      EXPECT_LE(maxAbsComponent(c), 1.0);
      EXPECT_NEAR(glm::distance(c, scaled.polygonVertices[scaled.shapes<Polygon>()[i].firstVertex]),
                  radius, 1e-12);
      if (i > 0) {
        stepScaled += glm::distance(c, centre(scaled, i - 1));
        stepRandom += glm::distance(centre(random, i), centre(random, i - 1));
      }
    }
    // Neighbours in memory are neighbours in space: consecutive centres lie a
    // few spacings apart, where random order puts them about a cube apart.
    EXPECT_LT(stepScaled / double(n - 1), 4.0 * std::cbrt(8.0 / double(n)));
    EXPECT_GT(stepRandom / double(n - 1), 1.0);
  }
}

// The tests above compare both node tests with brute force where the
// processor has AVX; this says whether they did.
TEST(Bvh, TakesTheAvxNodeTestWhereTheProcessorHasIt) {
  Scene scene;
  addSphere(scene, Vec3(0.0), 1.0, addMaterial(scene, Material{}));
  Bvh::Options sse;
  sse.avx = false;
  EXPECT_FALSE(Bvh(scene, sse).usesAvx());
#if defined(__x86_64__)
  EXPECT_EQ(Bvh(scene).usesAvx(), bool(__builtin_cpu_supports("avx")));
#else
  EXPECT_FALSE(Bvh(scene).usesAvx());
#endif
}

// The hierarchy itself (nodes and references) takes at most 64 bytes a
// primitive; the packets' copies of triangles' and small polygons' data
// (core/accel/packets.h) come on top, for the scenes that have them: a
// triangle as a polygon takes 13 doubles (its plane's four, its corners'
// nine), and 8 bytes say where its packet is.
TEST(Bvh, AtMost64BytesPerPrimitive) {
  for (const Scene& scene : {makePolygonSoup(20000, 3), makeSphereflake(20000)}) {
    const Bvh bvh(scene);
    const auto perPrimitive = [&](std::size_t bytes) {
      return double(bytes) / double(scene.primitiveCount());
    };
    EXPECT_LE(perPrimitive(bvh.hierarchyBytes()), 64.0);
    const bool polygons = !scene.shapes<Polygon>().empty();
    EXPECT_LE(perPrimitive(bvh.memoryBytes() - bvh.hierarchyBytes()),
              polygons ? 13.0 * 8.0 + 8.0 + 1.0 : 0.0); // (1: the padding)
    EXPECT_GT(bvh.nodeCount(), 0u);
  }
}

// keepNearest's next double up agrees with the C library's at every kind of value.
TEST(KeepNearest, NextUpIsNextafterTowardInfinity) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const double x :
       {0.0, -0.0, std::numeric_limits<double>::denorm_min(),
        -std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), 1.0, -1.0,
        0.1, 1e300, -1e-300, std::numeric_limits<double>::max(),
        -std::numeric_limits<double>::max(), inf, -inf})
    EXPECT_EQ(std::bit_cast<std::uint64_t>(nextUp(x)),
              std::bit_cast<std::uint64_t>(std::nextafter(x, inf)))
        << x;
  EXPECT_TRUE(std::isnan(nextUp(std::numeric_limits<double>::quiet_NaN())));
}

} // namespace
} // namespace prism
