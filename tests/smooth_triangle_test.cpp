// Mesh triangles: hits, watertight shared edges, interpolated normals and
// their fallbacks, the .sc `triangle` and `ptriangle`, and a tessellated
// sphere with vertex normals shading like the analytic sphere.
#include "core/accel/accel.h"
#include "core/io/obj_reader.h"
#include "core/io/scene_parser.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "core/shapes/triangle.h"
#include "tests/test_expect.h"
#include "tools/sphere_mesh.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace prism {
namespace {

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

// Vertices of a unit right triangle in the z = 0 plane (and a fourth vertex
// making a square with it), with normals tilted outward at the corners.
struct Fixture {
  std::vector<Vec3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  std::vector<Vec3> normals{glm::normalize(Vec3(-1, -1, 2)), glm::normalize(Vec3(1, 0, 2)),
                            glm::normalize(Vec3(0, 1, 2)), Vec3(0, 0, 1)};
  Triangle flat() const {
    Triangle t;
    t.vertex = {0, 1, 2};
    return t;
  }
  Triangle smooth() const {
    Triangle t = flat();
    t.normal = {0, 1, 2};
    return t;
  }
};

TEST(SmoothTriangle, HitsInsideMissesOutsideBothSides) {
  const Fixture f;
  const Triangle t = f.flat();
  double hit = 0;
  ASSERT_TRUE(intersect(t, f.vertices.data(), ray({0.25, 0.25, 3}, {0, 0, -1}), Interval{}, hit));
  EXPECT_NEAR(hit, 3.0, 1e-15);
  ASSERT_TRUE(intersect(t, f.vertices.data(), ray({0.25, 0.25, -2}, {0, 0, 1}), Interval{}, hit));
  EXPECT_NEAR(hit, 2.0, 1e-15);
  EXPECT_FALSE(intersect(t, f.vertices.data(), ray({0.6, 0.6, 3}, {0, 0, -1}), Interval{}, hit));
  EXPECT_FALSE(intersect(t, f.vertices.data(), ray({-0.01, 0.5, 3}, {0, 0, -1}), Interval{}, hit));
  // Parallel to the plane, even through the middle: no area is hit.
  EXPECT_FALSE(intersect(t, f.vertices.data(), ray({-1, 0.2, 0}, {1, 0, 0}), Interval{}, hit));
  EXPECT_FALSE(
      intersect(t, f.vertices.data(), ray({0.25, 0.25, 3}, {0, 0, -1}), Interval{0, 2.5}, hit));
  EXPECT_NEAR(glm::length(geometricNormal(t, f.vertices.data()) - Vec3(0, 0, 1)), 0.0, 1e-15);
}

// From an origin 10^13 away (a ray reflected off a huge sphere, found by
// fuzz_sc), rays aimed a tenth of a unit inside and outside each edge of the
// unit triangle: the answer must be right to the precision of the origin
// itself (about 0.002 at 10^13). The 3D edge functions once cancelled twice
// and judged such rays wrong by whole units.
TEST(SmoothTriangle, FarOriginJudgesEdgesToTheOriginsPrecision) {
  const Fixture f;
  const Triangle t = f.flat();
  const Vec3 origin(2.96637e12, 2.96637e12, 9.5486e12);
  struct Aim {
    Vec3 target;
    bool inside;
  };
  const Aim aims[] = {
      {{0.25, 0.25, 0}, true},  {{0.1, 0.5, 0}, true},     {{0.5, 0.1, 0}, true},
      {{0.45, 0.45, 0}, true},  {{-0.1, 0.5, 0}, false},   {{0.5, -0.1, 0}, false},
      {{0.55, 0.55, 0}, false}, {{-0.5, -0.72, 0}, false}, {{0.75, 0.75, 0}, false},
  };
  for (const Aim& aim : aims) {
    double hit = 0;
    const Ray r = ray(origin, aim.target - origin);
    EXPECT_EQ(intersect(t, f.vertices.data(), r, Interval{}, hit), aim.inside)
        << "aimed at (" << aim.target.x << ", " << aim.target.y << ")";
    if (aim.inside) {
      EXPECT_NEAR(hit, glm::length(aim.target - origin), 0.01);
    }
  }
}

// Rays crossing the diagonal shared by two triangles of a square, in steps
// far finer than round-off matters: every one hits one of the two.
TEST(SmoothTriangle, SharedEdgeIsWatertight) {
  const Fixture f;
  Triangle a = f.flat(), b;
  b.vertex = {1, 3, 2}; // shares the edge 1-2, walked 2 -> 1
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const double s = 0.5 + 0.49 * u(rng);
    const Vec3 onEdge = (1.0 - s) * f.vertices[1] + s * f.vertices[2];
    const Vec3 origin = onEdge + Vec3(3 * u(rng), 3 * u(rng), 5.0);
    const Ray r{origin, glm::normalize(onEdge + Vec3(1e-17 * u(rng)) - origin)};
    double t;
    hits += intersect(a, f.vertices.data(), r, Interval{}, t) ||
            intersect(b, f.vertices.data(), r, Interval{}, t);
  }
  EXPECT_EQ(hits, 20000);
}

TEST(SmoothTriangle, InterpolatedNormals) {
  const Fixture f;
  const Triangle t = f.smooth();
  const Vec3* v = f.vertices.data();
  const Vec3* n = f.normals.data();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(glm::length(interpolatedNormal(t, v, n, v[i]) - n[i]), 0.0, 1e-15) << i;
  }
  const Vec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
  EXPECT_NEAR(
      glm::length(interpolatedNormal(t, v, n, centroid) - glm::normalize(n[0] + n[1] + n[2])), 0.0,
      1e-15);
  // Halfway along the edge 1-2 only those two normals count.
  EXPECT_NEAR(
      glm::length(interpolatedNormal(t, v, n, 0.5 * (v[1] + v[2])) - glm::normalize(n[1] + n[2])),
      0.0, 1e-15);
  // A flat triangle is shaded with its geometric normal.
  EXPECT_NEAR(glm::length(interpolatedNormal(f.flat(), v, n, centroid) - Vec3(0, 0, 1)), 0.0,
              1e-15);
}

TEST(SmoothTriangle, LiftedPointRisesOntoTheCurvedSurface) {
  const Fixture f;
  const Vec3* v = f.vertices.data();
  const Vec3* n = f.normals.data();
  const Vec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
  const Vec3 lifted = liftedPoint(f.smooth(), v, n, centroid);
  // Normals tilted outward: a bulge above the face. Each vertex raises the
  // point onto its tangent plane (by -(p - v_i).n_i along n_i); the blend
  // weights are 1/3 each at the centroid.
  double z = 0.0;
  for (int i = 0; i < 3; ++i)
    z -= glm::dot(centroid - v[i], n[i]) * n[i].z / 3.0;
  EXPECT_NEAR(lifted.z, z, 1e-15);
  EXPECT_NEAR(z, 0.2519, 1e-4);
  EXPECT_EQ(liftedPoint(f.smooth(), v, n, v[0]), v[0]); // corners stay put
  EXPECT_EQ(liftedPoint(f.flat(), v, n, centroid), centroid);
}

Scene traceScene(const std::string& text) { return parseScene(text, "t.sc"); }

// The tracer shades with the interpolated normal; where it faces away from
// the ray's side of the face, it falls back to the geometric normal.
TEST(SmoothTriangle, TracerUsesInterpolatedNormalWithFallback) {
  // All three normals tilted toward +x by 45 degrees.
  const Scene s = traceScene("light 0 0 10  1 1 1\n"
                             "ptriangle -1 -1 0  1 0 1   1 -1 0  1 0 1   0 1 0  1 0 1\n");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  RayTreeNode front, back;
  const Color c = tracer.trace(ray({0, 0, 5}, {0, 0, -1}), 1, counts, &front);
  EXPECT_FALSE(front.leaving);
  EXPECT_NEAR(glm::length(front.normal - Vec3(0, 0, 1)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(front.shadingNormal - glm::normalize(Vec3(1, 0, 1))), 0.0, 1e-15);
  EXPECT_NEAR(c.r, std::sqrt(0.5) / 100.0, 1e-15); // N.L = cos 45, r = 10
  // From behind, the flipped interpolated normal (-1, 0, -1)/sqrt 2 still
  // faces the ray's side: it is used, flipped.
  tracer.trace(ray({0, 0, -5}, {0, 0, 1}), 1, counts, &back);
  EXPECT_TRUE(back.leaving);
  EXPECT_NEAR(glm::length(back.shadingNormal + glm::normalize(Vec3(1, 0, 1))), 0.0, 1e-15);

  // Normals bent past the face (pointing below it): the geometric normal.
  const Scene bent =
      traceScene("light 0 0 10  1 1 1\n"
                 "ptriangle -1 -1 0  1 0 -0.2   1 -1 0  1 0 -0.2   0 1 0  1 0 -0.2\n");
  const auto accel2 = makeAccel(bent, AccelKind::Bvh);
  Tracer tracer2(bent, *accel2, 1);
  RayTreeNode node;
  const Color c2 = tracer2.trace(ray({0, 0, 5}, {0, 0, -1}), 1, counts, &node);
  EXPECT_NEAR(glm::length(node.shadingNormal - node.normal), 0.0, 1e-15);
  EXPECT_NEAR(c2.r, 1.0 / 100.0, 1e-15);
}

TEST(SmoothTriangle, ScLanguage) {
  const Scene s = traceScene("triangle 0 0 0  1 0 0  0 1 0\n"
                             "push scale 2 1 1\n"
                             "ptriangle 0 0 0  1 1 0   1 0 0  1 1 0   0 1 0  1 1 0\n"
                             "scale -1 1 1\n"
                             "triangle 0 0 0  1 0 0  0 1 0\n"
                             "pop\n");
  ASSERT_EQ(s.shapes<Triangle>().size(), 3u);
  EXPECT_FALSE(s.shapes<Triangle>()[0].smooth());
  EXPECT_TRUE(s.shapes<Triangle>()[1].smooth());
  // Normals move by the inverse transpose: (1, 1, 0) under scale 2 1 1 is
  // (1/2, 1, 0), normalised.
  EXPECT_NEAR(glm::length(s.meshNormals[s.shapes<Triangle>()[1].normal[0]] -
                          glm::normalize(Vec3(0.5, 1, 0))),
              0.0, 1e-15);
  EXPECT_EQ(s.meshVertices[s.shapes<Triangle>()[1].vertex[1]], Vec3(2, 0, 0));
  // Mirrored: the winding is reversed so the outward normal stays +z.
  EXPECT_NEAR(
      glm::length(geometricNormal(s.shapes<Triangle>()[2], s.meshVertices.data()) - Vec3(0, 0, 1)),
      0.0, 1e-15);

  EXPECT_EQ(test::sceneErrorsOf("triangle 0 0 0  1 1 1  2 2 2"),
            "t.sc:1:1: error: triangle: degenerate triangle (zero area)");
  EXPECT_EQ(test::sceneErrorsOf("ptriangle 0 0 0 0 0 1  1 0 0 0 0 0  0 1 0 0 0 1"),
            "t.sc:1:30: error: ptriangle: N2 (NX2 NY2 NZ2) must not be the zero vector");
  EXPECT_EQ(test::sceneErrorsOf("triangle 0 0 0  1 0 0  0 1"),
            "t.sc:1:1: error: triangle: expected Z3 but reached the end of the file");
}

// A UV sphere of 96 x 192 (36,480 triangles) with exact vertex normals, read
// from OBJ, against the analytic sphere under the same light and camera:
// every pixel away from the silhouette (where the flat outline differs by
// construction) within 1% of the analytic radiance.
TEST(SmoothTriangle, TessellatedSphereShadesLikeAnalyticSphere) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "prism_smooth_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path obj = dir / "sphere.obj";
  {
    std::ofstream out(obj);
    writeSphereObj(out, 96, 192);
  }
  Scene mesh = loadObj(obj);
  std::filesystem::remove_all(dir);
  const Scene analytic = traceScene("eye 0.3 0.4 4  lookat 0 0 0\n"
                                    "light -3 4 5  40 40 40\nlight 4 -1 3  10 10 10\n"
                                    "surface 0.8 0.7 0.6  0.9 0.4 0  30 1\n"
                                    "sphere 0 0 0 1\n");
  mesh.camera = analytic.camera;
  mesh.lights = analytic.lights;
  mesh.ambient = analytic.ambient;
  mesh.background = analytic.background;
  mesh.materials = analytic.materials;
  mesh.absorbingMaterials = analytic.absorbingMaterials;
  mesh.texturedMaterials = analytic.texturedMaterials;
  for (Triangle& t : mesh.shapes<Triangle>())
    t.material = 0;

  const auto accelA = makeAccel(analytic, AccelKind::Bvh);
  const auto accelM = makeAccel(mesh, AccelKind::Bvh);
  Tracer a(analytic, *accelA, 1), m(mesh, *accelM, 1);
  const Camera camera(analytic.camera, 96, 96);
  double worst = 0.0;
  int compared = 0;
  for (int y = 0; y < 96; ++y) {
    for (int x = 0; x < 96; ++x) {
      const Ray r = camera.eyeRay(x + 0.5, y + 0.5);
      RayCounts counts;
      RayTreeNode na, nm;
      const Color ca = a.trace(r, 1, counts, &na);
      const Color cm = m.trace(r, 1, counts, &nm);
      if (!na.hit || !nm.hit || glm::dot(na.normal, -r.dir) < 0.3) continue;
      ++compared;
      const double scale = std::max(maxComponent(ca), 1e-3);
      worst = std::max(worst, maxAbsComponent(ca - cm) / scale);
    }
  }
  EXPECT_GT(compared, 2000);
  EXPECT_LT(worst, 0.01) << "largest relative difference " << worst;
  std::cout << "tessellated vs analytic sphere: " << compared
            << " pixels, largest relative difference " << worst << "\n";
}

} // namespace
} // namespace prism
