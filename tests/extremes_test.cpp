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
#include <initializer_list>
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

long double surfaceDistance(const Torus& t, const ShapeArrays&, const Vec3& p) {
  const long double R = t.major, r = t.minor;
  return frameDistance(t.worldToObject, t.worldToObjectOffset, p,
                       [&](const long double* q, long double* g) {
                         // (rho - R)^2 + z^2 - r^2: the tube's factor of the quartic.
                         const long double rho = std::sqrt(q[0] * q[0] + q[1] * q[1]);
                         g[0] = 2 * (rho - R) * q[0] / rho;
                         g[1] = 2 * (rho - R) * q[1] / rho;
                         g[2] = 2 * q[2];
                         return (rho - R) * (rho - R) + q[2] * q[2] - r * r;
                       });
}

// The field minus the threshold over its gradient's length.
long double surfaceDistance(const Blob& b, const ShapeArrays& arrays, const Vec3& p) {
  return frameDistance(b.frame.worldToObject, b.frame.worldToObjectOffset, p,
                       [&](const long double* q, long double* g) {
                         long double field = -(long double)b.threshold;
                         g[0] = g[1] = g[2] = 0;
                         for (const BlobComponent& c : componentsOf(b, arrays)) {
                           long double w[3], w2 = 0;
                           for (int i = 0; i < 3; ++i) {
                             w[i] = (q[i] - c.center[i]) / c.radius;
                             w2 += w[i] * w[i];
                           }
                           const long double k = 1 - w2;
                           if (!(k > 0)) continue;
                           field += c.strength * k * k;
                           for (int i = 0; i < 3; ++i)
                             g[i] -= 4 * c.strength * k * w[i] / c.radius;
                         }
                         return field;
                       });
}

// The distance from the nearest of the planes q[axis] = at of a frame.
long double framePlanesDistance(const Mat3& w, const Vec3& w0, const Vec3& p,
                                std::initializer_list<std::pair<int, double>> planes) {
  long double nearest = INFINITY;
  for (const auto& [axis, at] : planes) {
    const long double d =
        frameDistance(w, w0, p, [axis = axis, at = at](const long double* q, long double* g) {
          g[0] = g[1] = g[2] = 0;
          g[axis] = 1;
          return q[axis] - at;
        });
    if (std::abs(d) < std::abs(nearest)) nearest = d;
  }
  return nearest;
}

long double surfaceDistance(const Box& b, const ShapeArrays&, const Vec3& p) {
  const AffineFrame& f = b.frame;
  return framePlanesDistance(
      f.worldToObject, f.worldToObjectOffset, p,
      {{0, b.lo.x}, {0, b.hi.x}, {1, b.lo.y}, {1, b.hi.y}, {2, b.lo.z}, {2, b.hi.z}});
}

long double surfaceDistance(const Disc& d, const ShapeArrays&, const Vec3& p) {
  return framePlanesDistance(d.frame.worldToObject, d.frame.worldToObjectOffset, p, {{2, 0.0}});
}

// The nearest of the side and the caps' planes.
long double surfaceDistance(const CappedCone& c, const ShapeArrays& arrays, const Vec3& p) {
  const long double side = surfaceDistance(c.side, arrays, p);
  const long double caps = framePlanesDistance(c.side.worldToObject, c.side.worldToObjectOffset, p,
                                               {{2, 0.0}, {2, 1.0}});
  return std::abs(side) < std::abs(caps) ? side : caps;
}

long double surfaceDistance(const Quadric& quadric, const ShapeArrays&, const Vec3& p) {
  const AffineFrame& f = quadric.frame;
  return frameDistance(f.worldToObject, f.worldToObjectOffset, p,
                       [&](const long double* q, long double* g) {
                         long double k[10];
                         for (int i = 0; i < 10; ++i)
                           k[i] = quadric.coef[i];
                         g[0] = 2 * k[0] * q[0] + k[3] * q[1] + k[5] * q[2] + k[6];
                         g[1] = 2 * k[1] * q[1] + k[3] * q[0] + k[4] * q[2] + k[7];
                         g[2] = 2 * k[2] * q[2] + k[4] * q[1] + k[5] * q[0] + k[8];
                         return k[0] * q[0] * q[0] + k[1] * q[1] * q[1] + k[2] * q[2] * q[2] +
                                k[3] * q[0] * q[1] + k[4] * q[1] * q[2] + k[5] * q[0] * q[2] +
                                k[6] * q[0] + k[7] * q[1] + k[8] * q[2] + k[9];
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

// A closed mesh's surface near a point is the nearest triangle's.
long double surfaceDistance(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& p) {
  return surfaceDistance(trianglesOf(m, arrays)[nearestTriangle(m, arrays, p)], arrays, p);
}

// A CSG node's surface lies on its leaves' surfaces: the nearest of them.
long double surfaceDistance(const Csg& node, const ShapeArrays& arrays, const Vec3& p) {
  long double best = std::numeric_limits<long double>::infinity();
  for (const CsgOperand& operand : operandsOf(node, arrays)) {
    std::visit(
        [&](const auto& s) {
          long double d;
          if constexpr (std::is_same_v<std::decay_t<decltype(s)>, CsgNodeIndex>)
            d = surfaceDistance(arrays.csgNodes[s.index], arrays, p);
          else
            d = surfaceDistance(s, arrays, p);
          best = std::min(best, std::abs(d));
        },
        operand.shape);
  }
  return best;
}

// One primitive of each kind, of size about 1 around the origin, each
// sheared or tilted so that no coordinate is special.
const char* const kOneOfEachKind[] = {
    "sphere 0.1 -0.2 0.3 0.9",
    "push rotate 1 2 3 30 scale 1 0.3 2 rotate 3 -1 1 50 sphere 0 0 0 1 pop",
    "polygon 5  -1 -0.7 -0.19  0.9 -0.8 -0.02  1.1 0.4 0.24  0.2 1.0 0.27  -0.9 0.6 0.08",
    "push rotate 1 1 0 20 scale 1 1 0.6 cone 0 -1 0 0.8  0.1 1 0.1 0.3 pop",
    "triangle  -1 -0.8 0.2  1.2 -0.5 -0.3  0.1 1.1 0.4",
    // Sheared hard: a disc 1e-4 thick, turned, then squashed along another axis.
    "push scale 3 1 0.5 rotate 1 1 1 40 scale 1 1 1e-4 sphere 0 0 0 1 pop",
    "push scale 3 1 0.5 rotate 1 1 1 40 scale 1 1 1e-3 cone 0 0 0 1  0 0 1 0.5 pop",
    "push rotate 2 -1 1 35 scale 1 0.7 1.2 torus 0.1 0 -0.1  0.3 1 0.2  0.8 0.25 pop",
    "torus 0 0 0  0 0 1  1 1e-3",
    // The solids: world-aligned and turned and stretched.
    "box -0.9 -0.8 -0.7  0.8 0.9 0.6",
    "push rotate 1 2 3 30 scale 1 0.3 2 rotate 3 -1 1 50 box -0.9 -0.8 -0.7  0.8 0.9 0.6 pop",
    "push rotate 1 1 0 20 scale 1 1 0.6 disc 0.1 -0.1 0.2  1 2 3  0.9 pop",
    "cylinder 0 -1 0.1  0.2 1 0  0.7",
    "push rotate 1 1 0 20 scale 1 1 0.6 capped_cone 0 -1 0 0.8  0.1 1 0.1 0.3 pop",
    "push scale 3 1 0.5 rotate 1 1 1 40 scale 1 1 1e-3 capped_cone 0 0 0 1  0 0 1 0 pop",
    // Quadrics: a paraboloid turned and stretched, a skewed hyperboloid.
    "push rotate 1 2 3 30 scale 1 0.6 1.3 quadric 1 1 0 0 0 0 0 0 -1 0  -0.9 -0.8 -0.1  0.8 0.9 "
    "0.9 pop",
    "quadric 1 1 -1 0.2 0 0.1 0 0 0 -0.3  -0.9 -0.8 -0.7  0.8 0.9 0.6",
    // CSG: a turned box with a sphere taken out of it.
    "push rotate 1 2 3 30 csg difference box -0.9 -0.8 -0.7  0.8 0.9 0.6 "
    "sphere 0.5 0.4 0.3 0.7 end pop",
    // Blobs: three components, one subtracting; then rotated and stretched.
    "blob 0.5 3  -0.3 0 0.1  0.8 1  0.4 0.1 0  0.7 1  0 0.3 0.2  0.4 -0.5",
    "push rotate 1 2 3 30 scale 1 0.3 2 blob 0.5 2  -0.3 0 0.1  0.8 1  0.4 0.1 0  0.7 1 pop",
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

// Each shipped scene placed at scale 1e-4 and 1e4, and at 1e-4 moved 1e4
// away (features of 1e-3 at 1e4: 1e-7), against itself at scale 1, at 80 x 60.
// Measured: at both scales every pixel of every scene is exactly the same;
// moved far away, at least 99.94% of the pixels are within 2 levels (the
// worst: glass.sc 9, csg.sc 9, quadrics.sc 7, torus.sc 5; antialiasing
// decisions that flip), table, chex, tree, solids and blobs all within 1. The test
// allows 1 level at the two scales and 0.5% of the pixels beyond 2 levels far
// away. forest.sc (ten trees of tree.sc, placed by the same kind of transforms
// this test composes) is left out: it costs three quarters of the test's time
// and met the same bounds (99.98%, worst 4) when it was in.
class ShippedSceneAtExtremeScales : public testing::TestWithParam<const char*> {};

TEST_P(ShippedSceneAtExtremeScales, KeepsItsPicture) {
  RenderSettings settings;
  settings.width = 80;
  settings.height = 60;
  settings.threads = 2;
  const std::string dir = std::string(PRISM_SOURCE_DIR) + "/scenes/";
  const std::string name = GetParam();
  const std::string body = "include " + name + "\n";
  const auto unit = test::picture(test::placedScene(body, {}, dir + "wrap.sc"), settings);
  for (const Placement at : {Placement{1e-4, 0}, Placement{1e4, 0}, Placement{1e-4, 1e4}}) {
    const auto got = test::picture(test::placedScene(body, at, dir + "wrap.sc"), settings);
    const test::Agreement a = test::compare(unit, got, 2);
    const test::Agreement exact = test::compare(unit, got, 1);
    std::printf("%-12s scale %g at %g: %.2f%% within 1 level, %.2f%% within 2, worst %d\n",
                name.c_str(), at.scale, at.offset, 100.0 * exact.within, 100.0 * a.within, a.worst);
    if (at.offset == 0.0) {
      EXPECT_LE(a.worst, 1) << name << " scale " << at.scale;
    } else {
      EXPECT_GE(a.within, 0.995) << name << " scale " << at.scale << " at " << at.offset;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RayOffset, ShippedSceneAtExtremeScales,
                         testing::Values("glass.sc", "table.sc", "chex.sc", "tree.sc", "solids.sc",
                                         "torus.sc", "quadrics.sc", "csg.sc", "blobs.sc"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           const std::string name = param.param;
                           return name.substr(0, name.find('.'));
                         });

// ---------------------------------------------------------------------------
// Rays through vertices and edges, surfaces at extreme sizes

// Rays aimed at the vertices and edges of a closed convex solid (the faces
// given) from outside, each in a direction that goes on into the solid there
// (within 17 degrees of the direction to its centre: inside the solid's
// corner at every vertex and edge of a cube or an octahedron). Each must meet
// the solid no farther than the point aimed at; returns how many do not,
// through vertices, edge midpoints and points a third along edges, of 64
// rays each per face corner.
std::array<int, 3> missesThroughVerticesAndEdges(const Scene& scene,
                                                 const std::vector<std::vector<Vec3>>& faces) {
  const auto accel = makeAccel(scene, AccelKind::Groups);
  Vec3 centre(0.0);
  int count = 0;
  for (const std::vector<Vec3>& face : faces)
    for (const Vec3& v : face) {
      centre += v;
      ++count;
    }
  centre /= double(count);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::array<int, 3> misses{};
  for (const std::vector<Vec3>& face : faces)
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Vec3& a = face[i];
      const Vec3& b = face[(i + 1) % face.size()];
      for (int which = 0; which < 3; ++which)
        for (int k = 0; k < 64; ++k) {
          const Vec3 target = which == 0 ? a : which == 1 ? 0.5 * (a + b) : a + 0.3 * (b - a);
          Vec3 tilt(unit(rng), unit(rng), unit(rng));
          tilt = 0.3 * tilt / std::max(1.0, glm::length(tilt));
          const Vec3 from = target + 12.0 * glm::normalize(glm::normalize(target - centre) + tilt);
          const Ray ray{from, glm::normalize(target - from)};
          Hit hit;
          if (!accel->closestHit(ray, Interval{}, nullptr, hit) ||
              !(hit.t <= glm::length(target - from) * (1.0 + 1e-12))) {
            ++misses[std::size_t(which)];
            continue;
          }
          EXPECT_TRUE(isFinite(scene.surfaceAt(hit.primitive, ray.at(hit.t)).outward));
        }
    }
  return misses;
}

// A closed octahedron of mesh triangles, turned and moved so that no
// coordinate is special: the watertight test leaves no hole at a vertex or
// along an edge (1536 rays of each sort).
TEST(Watertight, RaysIntoAClosedMeshThroughVerticesAndEdgesAlwaysHit) {
  const Scene scene = parseScene(R"(
push rotate 1 2 3 17 translate 0.3 -0.2 0.1
triangle  1 0 0  0 1 0  0 0 1    triangle  0 1 0  -1 0 0  0 0 1
triangle  -1 0 0  0 -1 0  0 0 1  triangle  0 -1 0  1 0 0  0 0 1
triangle  0 1 0  1 0 0  0 0 -1   triangle  -1 0 0  0 1 0  0 0 -1
triangle  0 -1 0  -1 0 0  0 0 -1 triangle  1 0 0  0 -1 0  0 0 -1
pop
)",
                                 "octahedron.sc");
  std::vector<std::vector<Vec3>> faces;
  for (const Triangle& tri : scene.shapes<Triangle>())
    faces.push_back({scene.meshVertices[tri.vertex[0]], scene.meshVertices[tri.vertex[1]],
                     scene.meshVertices[tri.vertex[2]]});
  ASSERT_EQ(faces.size(), 8u);
  EXPECT_EQ(missesThroughVerticesAndEdges(scene, faces), (std::array<int, 3>{0, 0, 0}));
}

// A cube of six polygons, turned and moved so that no coordinate is special.
Scene turnedCubeOfPolygons() {
  return parseScene(R"(
push rotate 3 -1 2 29 translate 5 1 -2
polygon 4  -1 -1 -1  -1 1 -1  1 1 -1  1 -1 -1
polygon 4  -1 -1 1  1 -1 1  1 1 1  -1 1 1
polygon 4  -1 -1 -1  1 -1 -1  1 -1 1  -1 -1 1
polygon 4  -1 1 -1  -1 1 1  1 1 1  1 1 -1
polygon 4  -1 -1 -1  -1 -1 1  -1 1 1  -1 1 -1
polygon 4  1 -1 -1  1 1 -1  1 1 1  1 -1 1
pop
)",
                    "cube.sc");
}

// The same for a cube of six polygons, each tested alone in the ray's frame
// (core/shapes/polygon.cpp). In each polygon's own plane projection, as
// before, 734 of 1536 rays through vertices, 602 through edge midpoints and
// 634 a third along edges passed between the faces.
TEST(Watertight, RaysIntoAClosedCubeOfPolygonsThroughVerticesAndEdgesAlwaysHit) {
  const Scene scene = turnedCubeOfPolygons();
  std::vector<std::vector<Vec3>> faces;
  for (const Polygon& poly : scene.shapes<Polygon>())
    faces.emplace_back(scene.polygonVertices.begin() + poly.firstVertex,
                       scene.polygonVertices.begin() + poly.firstVertex + poly.vertexCount);
  ASSERT_EQ(faces.size(), 6u);
  EXPECT_EQ(missesThroughVerticesAndEdges(scene, faces), (std::array<int, 3>{0, 0, 0}));
}

// Rays aimed exactly at the vertices, edge midpoints and points a third along
// the edges of a turned cube of polygons, from outside: of the faces turned
// toward the ray, exactly one contains it (none: a hole; two: a double hit),
// each polygon tested on its own.
TEST(Watertight, RaysThroughACubesEdgesAndCornersEnterThroughExactlyOneFace) {
  const Scene scene = turnedCubeOfPolygons();
  const auto& polygons = scene.shapes<Polygon>();
  ASSERT_EQ(polygons.size(), 6u);
  Vec3 centre(0.0);
  for (const Vec3& v : scene.polygonVertices)
    centre += v;
  centre /= double(scene.polygonVertices.size());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int rays = 0;
  std::array<int, 3> entries{}; // rays entering through 0, 1, 2 or more faces
  for (const Polygon& face : polygons) {
    const Vec3* v = scene.polygonVertices.data() + face.firstVertex;
    for (std::uint32_t i = 0; i < face.vertexCount; ++i) {
      const Vec3 a = v[i], b = v[(i + 1) % face.vertexCount];
      for (const Vec3 target : {a, 0.5 * (a + b), a + (b - a) / 3.0}) {
        for (int k = 0; k < 32; ++k) {
          Vec3 tilt(unit(rng), unit(rng), unit(rng));
          tilt = 0.3 * tilt / std::max(1.0, glm::length(tilt));
          const Vec3 from = target + 12.0 * glm::normalize(glm::normalize(target - centre) + tilt);
          const Ray ray{from, glm::normalize(target - from)};
          int inside = 0;
          for (const Polygon& p : polygons) {
            double t = 0.0;
            if (glm::dot(p.normal, ray.dir) < 0.0 &&
                intersect(p, scene.polygonVertices.data(), ray, Interval{}, t))
              ++inside;
          }
          ++entries[std::size_t(std::min(inside, 2))];
          ++rays;
        }
      }
    }
  }
  EXPECT_EQ(entries[1], rays) << entries[0] << " holes, " << entries[2] << " double hits";
}

// One diffuse polygon (colour C, kd) in the plane z = 0 lit by one light of
// intensity E straight above the hit point: L = C kd (A + E / h^2), exactly
// what a tracer of any precision must give, for polygons of extreme shape.
Color litPolygon(const std::string& polygon, double lightHeight, const Vec3& at) {
  std::ostringstream text;
  text.precision(17);
  text << "ambient 0.1 0.1 0.1\nsurface 1 0.5 0.25 0.8 0 0 1 1\n"
       << polygon << "\nlight " << at.x << ' ' << at.y << ' ' << lightHeight << "  1 1 1\n";
  const Scene scene = parseScene(text.str(), "lit.sc");
  const auto accel = makeAccel(scene, AccelKind::Groups);
  Tracer tracer(scene, *accel, 5);
  RayCounts counts;
  const Color c = tracer.trace({at + Vec3(0.0, 0.0, 3.0), Vec3(0.0, 0.0, -1.0)}, 1, counts);
  EXPECT_EQ(counts.shadow, 1u) << polygon;
  return c;
}

TEST(ExtremeSurfaces, HugeThinAndCoincidentPolygonsShadeExactly) {
  const Color cKd = Color(1.0, 0.5, 0.25) * 0.8;
  const auto expected = [&](double h) { return cKd * (0.1 + 1.0 / (h * h)); };
  const auto expectNear = [](const Color& got, const Color& want, const std::string& what) {
    EXPECT_TRUE(isFinite(got)) << what;
    EXPECT_LE(maxAbsComponent(got - want), 1e-12 * maxAbsComponent(want)) << what;
  };
  // 2e8 units across, lit from 1 unit above: the hit point is 1e8 from the
  // edges but near the origin, so its round-off is that of small numbers.
  expectNear(litPolygon("polygon 4  -1e8 -1e8 0  1e8 -1e8 0  1e8 1e8 0  -1e8 1e8 0", 1.0,
                        Vec3(0.3, 0.2, 0.0)),
             expected(1.0), "2e8 wide");
  // The same far from the origin: the light 1e-3 above a point 1e8 away.
  expectNear(
      litPolygon("polygon 4  0 0 0  2e8 0 0  2e8 2e8 0  0 2e8 0", 1e-3, Vec3(1.5e8, 1.25e8, 0.0)),
      expected(1e-3), "2e8 wide, lit at 1e8");
  // Aspect 1e6: 1 unit long, 1e-6 wide.
  expectNear(litPolygon("polygon 4  0 0 0  1 0 0  1 1e-6 0  0 1e-6 0", 1.0, Vec3(0.5, 0.5e-6, 0.0)),
             expected(1.0), "aspect 1e6");
  // Two coincident polygons: the first in the file is seen and lit, and the
  // second, though a shadow ray starts a few hundred ulps above it, never
  // blocks the light (it lies below the start).
  expectNear(litPolygon("polygon 4  -1 -1 0  1 -1 0  1 1 0  -1 1 0\n"
                        "surface 0 1 0 0.8 0 0 1 1\npolygon 4  -1 -1 0  1 -1 0  1 1 0  -1 1 0",
                        1.0, Vec3(0.3, 0.2, 0.0)),
             expected(1.0), "coincident");
  // A light 1e-150 above the surface: E / h^2 = 1e300, still a double.
  expectNear(litPolygon("polygon 4  -1 -1 0  1 -1 0  1 1 0  -1 1 0", 1e-150, Vec3(0.3, 0.2, 0.0)),
             expected(1e-150), "light 1e-150 above");
}

// Traces the centre ray of every pixel of a size x size picture (the first
// scene's camera) in two scenes, to the depths given, and calls f(radiance in
// the first, radiance in the second, the second's counts): for scenes that
// should look the same.
template <class F>
void forEachPixelOfBoth(const Scene& first, int firstDepth, const Scene& second, int secondDepth,
                        int size, F f) {
  const auto firstAccel = makeAccel(first, AccelKind::Groups);
  const auto secondAccel = makeAccel(second, AccelKind::Groups);
  Tracer firstTracer(first, *firstAccel, firstDepth);
  Tracer secondTracer(second, *secondAccel, secondDepth);
  const Camera cam(first.camera, size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Ray ray = cam.eyeRay(x + 0.5, y + 0.5);
      RayCounts firstCounts, secondCounts;
      const Color a = firstTracer.trace(ray, 1, firstCounts);
      const Color b = secondTracer.trace(ray, 1, secondCounts);
      f(a, b, secondCounts);
    }
}

// Glass of index 1 that transmits everything and reflects nothing bends no
// ray and adds nothing: the pixels it covers are those of the scene without
// it. Ambient light only, since the glass would still cast a shadow.
TEST(ExtremeSurfaces, GlassOfIndexOneLeavesThePictureUnchanged) {
  const std::string room = "ambient 1 1 1\nsurface 0.2 0.6 0.9 0.9 0 0 1 1\n"
                           "polygon 4  -4 -4 -3  4 -4 -3  4 4 -3  -4 4 -3\n"
                           "surface 0.9 0.3 0.1 0.9 0 0 1 1\nsphere 0.4 0.3 -2 0.5\n"
                           "cone -0.8 -1 -1.5 0.3  -0.6 1 -2 0.2\n";
  const std::string glass = "surface 1 1 1  0 0 1  0 1\nsphere 0 0 0 1\n";
  int through = 0;
  forEachPixelOfBoth(parseScene(room, "room.sc"), 5, parseScene(room + glass, "room.sc"), 7, 48,
                     [&](const Color& want, const Color& got, const RayCounts& counts) {
                       through += counts.transmitted > 0 ? 1 : 0;
                       EXPECT_LE(maxAbsComponent(got - want), 1e-12);
                     });
  EXPECT_GT(through, 300); // the glass does cover a good part of the picture
}

// ---------------------------------------------------------------------------
// Degenerate pictures and cameras

// 1 x 1, 1 x N and N x 1 pictures at threshold 0 and 1 and depth 1 and 5:
// a pixel without neighbours on a side is compared only with those it has, so
// a 1 x 1 picture is never supersampled, and every pixel's first-pass value
// is the trace of its centre ray (computed here with a Tracer of its own).
TEST(Degenerate, OneByOneAndOneByNPicturesAtEveryThresholdAndDepth) {
  const Scene scene = test::placedScene(test::kGlassAndMirror, {}, "room.sc");
  const auto accel = makeAccel(scene, AccelKind::Groups);
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 9}, std::pair{9, 1}})
    for (const double thresh : {0.0, 1.0})
      for (const int depth : {1, 5}) {
        RenderSettings settings;
        settings.width = w;
        settings.height = h;
        settings.thresh = thresh;
        settings.maxDepth = depth;
        settings.threads = 2;
        const RenderResult r = render(scene, *accel, settings);
        ASSERT_EQ(r.film.pixelCount(), std::size_t(w * h));
        if (w * h == 1) {
          EXPECT_EQ(r.supersampledPixels, 0);
        }
        Tracer tracer(scene, *accel, depth);
        const Camera cam(scene.camera, w, h);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            RayCounts counts;
            const Rgb want = toRgb(tracer.trace(cam.eyeRay(x + 0.5, y + 0.5), 1, counts));
            EXPECT_EQ(r.film.centre[r.film.index(x, y)], want)
                << w << "x" << h << " " << x << "," << y << " depth " << depth;
            EXPECT_TRUE(std::isfinite(r.film.radiance[r.film.index(x, y)].x));
          }
      }
}

// The eye at the centre of a glass sphere (ir 1.5, all transmitted): every eye
// ray leaves it along the normal, where refraction bends nothing, so the
// picture is the room's without the sphere (no shadow ray of the room passes
// through the small sphere around the eye).
TEST(Degenerate, EyeInsideAGlassSphereSeesTheRoomUnbent) {
  const std::string glass = "surface 1 1 1  0 0 1  0 1.5\nsphere 0 1.6 6 0.3\n";
  const Scene plain = test::placedScene(test::kGlassAndMirror, {}, "room.sc");
  const Scene inside = test::placedScene(std::string(test::kGlassAndMirror) + glass, {}, "room.sc");
  int same = 0;
  // The way out of the sphere takes one more level of depth.
  forEachPixelOfBoth(plain, 5, inside, 6, 40,
                     [&](const Color& want, const Color& got, const RayCounts& counts) {
                       EXPECT_TRUE(isFinite(got));
                       EXPECT_GE(counts.transmitted, 1u);
                       same += maxAbsComponent(got - want) <= 1e-9 * (1.0 + maxAbsComponent(want));
                     });
  EXPECT_EQ(same, 1600);
}

// A camera looking down to within 1e-7 rad of its `up` vector still has an
// orthonormal frame: the centre ray points at `lookat` and the top and bottom
// rows are the field of view apart.
TEST(Degenerate, CameraLookingAlmostAlongUp) {
  for (const double tilt : {1e-3, 1e-7}) {
    CameraSpec spec;
    spec.eye = Vec3(0.0, 10.0, 0.0);
    spec.lookat = Vec3(10.0 * tilt, 0.0, 0.0); // 10 below, tilt * 10 aside
    spec.up = Vec3(0.0, 1.0, 0.0);
    spec.fov = 40.0;
    const Camera cam(spec, 64, 48);
    const Vec3 centre = cam.eyeRay(32.0, 24.0).dir;
    EXPECT_LE(glm::length(centre - glm::normalize(spec.lookat - spec.eye)), 1e-12) << tilt;
    const double angle = std::acos(glm::dot(cam.eyeRay(32.0, 0.0).dir, cam.eyeRay(32.0, 48.0).dir));
    EXPECT_NEAR(angle * 180.0 / 3.14159265358979323846, 40.0, 1e-9) << tilt;
  }
}

// A ray inside glass (ir 1.5, kst 1, nothing else) meeting its flat top at
// the critical angle asin(1 / 1.5) and 1e-9 rad either side. Below it the
// ray leaves, grazing (cos of the refracted angle sqrt(2 ir cos(theta_c)
// 1e-9) = 4.7e-5), and brings the background back; at it and above it the
// reflection is total and, with ksr = 0, nothing comes back: the margin of
// docs/rendering-model.md (k <= 1e-12) takes the critical angle itself.
TEST(Degenerate, TotalInternalReflectionJustBelowAtAndJustAboveTheCriticalAngle) {
  const Scene scene = parseScene("background 0.25 0.5 1\nsurface 1 1 1  0 0 1  0 1.5\n"
                                 "polygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0\n",
                                 "slab.sc");
  const auto accel = makeAccel(scene, AccelKind::Groups);
  Tracer tracer(scene, *accel, 2);
  const double critical = std::asin(1.0 / 1.5);
  for (const double delta : {-1e-6, -1e-9, 0.0, 1e-9, 1e-6}) {
    const double theta = critical + delta;
    RayCounts counts;
    const Color c = tracer.trace(
        {Vec3(0.0, 0.0, -1.0), Vec3(std::sin(theta), 0.0, std::cos(theta))}, 1, counts);
    const bool total = delta >= 0.0;
    EXPECT_EQ(counts.tirEvents, total ? 1u : 0u) << delta;
    EXPECT_EQ(counts.transmitted, total ? 0u : 1u) << delta;
    EXPECT_EQ(c, total ? Color(0.0) : scene.background) << delta;
  }
}

// A scene without lights casts no shadow ray anywhere, and its picture is
// what ambient light (none here) and the background make of it: finite,
// and not black, since the background shows.
TEST(Degenerate, SceneWithoutLights) {
  Scene scene = test::placedScene(test::kGlassAndMirror, {}, "room.sc");
  scene.lights.clear();
  const auto accel = makeAccel(scene, AccelKind::Groups);
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.threads = 2;
  const RenderResult r = render(scene, *accel, settings);
  EXPECT_EQ(r.counts.shadow, 0u);
  EXPECT_GT(r.counts.transmitted, 0u);
  EXPECT_GT(r.avgmax, 0.0);
  for (const Rgb& p : r.film.radiance)
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

} // namespace
} // namespace prism
