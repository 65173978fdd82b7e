// NFF import: every command and the scene it makes (camera, lights,
// materials, primitives, normals), a trace against hand-computed radiance, and
// every error with its file, line and column.
#include "core/accel/accel.h"
#include "core/io/nff_reader.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace prism {
namespace {

constexpr const char* kScene = R"(# every command once
v
from 0 0 10
at 0 0 0
up 0 1 0
angle 30
hither 1
resolution 64 48
b 0.2 0.3 0.4
l 0 0 5
l 3 4 0 0.5 0.25 1
f 1 0.5 0.25 0.6 0.3 12 0.1 1.5
s 0 0 0 1
c 0 -2 0 1  0 2 0 0.5
f 0.5 0.5 0.5 1 0 0 0 0
p 3
-1 -1 -1
1 -1 -1
0 1 -1
pp 4
-2 -2 -2  0 0 1
2 -2 -2  0 0 2
2 2 -2  0 0 1
-2 2 -2  1 0 1
)";

using test::expectCloseTo;

TEST(Nff, ViewBecomesTheCamera) {
  const Scene s = parseNff(kScene, "t.nff");
  expectCloseTo(s.camera.eye, {0, 0, 10});
  expectCloseTo(s.camera.lookat, {0, 0, 0});
  expectCloseTo(s.camera.up, {0, 1, 0});
  EXPECT_EQ(s.width, 64);
  EXPECT_EQ(s.height, 48);
  // NFF's angle spans the centres of the top and bottom rows (47 pixels);
  // Prism's fov spans the edges (48 pixels).
  const double expected = 2.0 * std::atan(std::tan(glm::radians(15.0)) * 48.0 / 47.0);
  EXPECT_NEAR(s.camera.fov, glm::degrees(expected), 1e-12);
  expectCloseTo(s.background, {0.2, 0.3, 0.4});
  EXPECT_EQ(s.ambient, Color(0.0));
}

// An up vector too short to cross with the view direction (1e-300) is a
// direction all the same: the camera's eye rays stay finite and the centre
// ray meets the sphere in front of the eye at distance 4.
TEST(Nff, ATinyUpIsADirectionAllTheSame) {
  const Scene s = parseNff("v\nfrom 0 0 5\nat 0 0 0\nup 0 1e-300 0\nangle 45\nhither 1\n"
                           "resolution 9 9\nl 0 5 5\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n",
                           "tiny-up.nff");
  expectCloseTo(s.camera.up, {0, 1, 0});
  const Camera camera(s.camera, s.width, s.height);
  const Ray centre = camera.eyeRay(4.5, 4.5);
  expectCloseTo(centre.dir, {0, 0, -1});
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Hit hit;
  ASSERT_TRUE(accel->closestHit(centre, Interval{}, nullptr, hit));
  EXPECT_NEAR(hit.t, 4.0, 1e-12);
}

TEST(Nff, LightsDeliverTheirIntensityAtTheViewedPoint) {
  const Scene s = parseNff(kScene, "t.nff");
  ASSERT_EQ(s.lights.size(), 2u);
  // Both lights are 5 units from `at`: intensity x 25, so that 1/r^2 gives
  // back the NFF intensity there.
  expectCloseTo(s.lights[0].position, {0, 0, 5});
  expectCloseTo(s.lights[0].intensity, Color(25.0));
  expectCloseTo(s.lights[1].position, {3, 4, 0});
  expectCloseTo(s.lights[1].intensity, Color(12.5, 6.25, 25.0));
}

TEST(Nff, FillBecomesTheMaterial) {
  const Scene s = parseNff(kScene, "t.nff");
  ASSERT_EQ(s.materials.size(), 2u);
  const Material& m = s.material({kindOf<Sphere>, 0});
  EXPECT_EQ(m.color, Color(1, 0.5, 0.25));
  EXPECT_EQ(m.kdr, 0.6);
  EXPECT_EQ(m.ksr, 0.3);
  EXPECT_EQ(m.e, 12.0);
  EXPECT_EQ(m.kst, 0.1);
  EXPECT_EQ(m.ir, 1.5);
  // ior 0 on an opaque material (as SPD writes it) means 1.
  const Material& grey = s.material({kindOf<Polygon>, 0});
  EXPECT_EQ(grey.ir, 1.0);
  EXPECT_EQ(grey.kst, 0.0);
}

TEST(Nff, Primitives) {
  const Scene s = parseNff(kScene, "t.nff");
  ASSERT_EQ(s.shapes<Sphere>().size(), 1u);
  expectCloseTo(s.shapes<Sphere>()[0].center, {0, 0, 0});
  EXPECT_EQ(s.shapes<Sphere>()[0].radius, 1.0);
  EXPECT_EQ(s.shapes<Sphere>()[0].origin.line, 13u);

  ASSERT_EQ(s.shapes<Cone>().size(), 1u);
  const Cone& c = s.shapes<Cone>()[0];
  EXPECT_TRUE(isCircular(c));
  expectCloseTo(c.objectToWorldOffset, {0, -2, 0});
  expectCloseTo(c.objectToWorldOffset + c.objectToWorld[2], {0, 2, 0});
  EXPECT_NEAR(c.baseRadius * glm::length(c.objectToWorld[0]), 1.0, 1e-15);
  EXPECT_NEAR(c.apexRadius * glm::length(c.objectToWorld[0]), 0.5, 1e-15);
  EXPECT_EQ(c.origin.line, 14u);

  ASSERT_EQ(s.shapes<Polygon>().size(), 1u);
  const Polygon& p = s.shapes<Polygon>()[0];
  ASSERT_EQ(p.vertexCount, 3u);
  expectCloseTo(s.polygonVertices[p.firstVertex + 2], {0, 1, -1});
  expectCloseTo(p.normal, {0, 0, 1}); // counterclockwise seen from +z
  EXPECT_EQ(p.origin.line, 16u);

  // The convex patch of 4 becomes a fan of 2 smooth triangles; its normals
  // are normalised ((0, 0, 2) -> (0, 0, 1)).
  ASSERT_EQ(s.shapes<Triangle>().size(), 2u);
  for (const Triangle& t : s.shapes<Triangle>()) {
    EXPECT_TRUE(t.smooth());
    EXPECT_EQ(t.origin.line, 20u);
    expectCloseTo(geometricNormal(t, s.meshVertices.data()), {0, 0, 1});
  }
  expectCloseTo(s.meshVertices[s.shapes<Triangle>()[1].vertex[2]], {-2, 2, -2});
  expectCloseTo(s.meshNormals[s.shapes<Triangle>()[0].normal[1]], {0, 0, 1});
  expectCloseTo(s.meshNormals[s.shapes<Triangle>()[1].normal[2]], glm::normalize(Vec3(1, 0, 1)));
  EXPECT_EQ(s.primitiveCount(), 5u);
}

// The eye ray through the middle of the picture hits the sphere at (0, 0, 1)
// with normal +z, straight under light 1 (r = 4, intensity 25 after the
// compensation): diffuse C kd 25/16 and highlight ks 25/16 (N.H = 1); light
// 2 is behind the surface. Depth 1: no reflected or transmitted rays.
TEST(Nff, TracesToHandComputedRadiance) {
  const Scene s = parseNff(kScene, "t.nff");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  const Color c = tracer.trace(Ray{{0, 0, 10}, {0, 0, -1}}, 1, counts);
  const double e = 25.0 / 16.0;
  EXPECT_NEAR(c.r, 1.0 * 0.6 * e + 0.3 * e, 1e-12);
  EXPECT_NEAR(c.g, 0.5 * 0.6 * e + 0.3 * e, 1e-12);
  EXPECT_NEAR(c.b, 0.25 * 0.6 * e + 0.3 * e, 1e-12);
  EXPECT_EQ(counts.shadow, 1u);
}

TEST(Nff, CommentsOptionalLightColourAndInsideOutCones) {
  const Scene s = parseNff("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8 # view\n"
                           "l 0 0 10  # a white light\n"
                           "c 0 0 0 -1  0 1 0 -0.5  # seen from inside: both radii negative\n",
                           "t.nff");
  expectCloseTo(s.lights[0].intensity, Color(100.0));
  ASSERT_EQ(s.shapes<Cone>().size(), 1u);
  EXPECT_NEAR(s.shapes<Cone>()[0].baseRadius, 1.0, 1e-15);
  EXPECT_NEAR(s.shapes<Cone>()[0].apexRadius, 0.5, 1e-15);
}

TEST(Nff, ConcavePatchIsSplitIntoEars) {
  // An L-shaped patch of 6 vertices: 4 triangles covering exactly its area.
  const Scene s = parseNff("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8\n"
                           "pp 6  0 0 0 0 0 1  2 0 0 0 0 1  2 1 0 0 0 1  1 1 0 0 0 1"
                           "  1 2 0 0 0 1  0 2 0 0 0 1\n",
                           "t.nff");
  ASSERT_EQ(s.shapes<Triangle>().size(), 4u);
  double area = 0.0;
  for (const Triangle& t : s.shapes<Triangle>()) {
    const Vec3* v = s.meshVertices.data();
    const Vec3 n = glm::cross(v[t.vertex[1]] - v[t.vertex[0]], v[t.vertex[2]] - v[t.vertex[0]]);
    EXPECT_GT(n.z, 0.0);
    area += 0.5 * glm::length(n);
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
}

TEST(Nff, DegeneratePolygonsAreDroppedWithAWarning) {
  std::vector<Diagnostic> warnings;
  const Scene s = parseNff("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8\n"
                           "p 3 0 0 0 1 0 0 2 0 0\n"
                           "pp 3 0 0 0 0 0 1  1 1 1 0 0 1  2 2 2 0 0 1\n",
                           "t.nff", &warnings);
  EXPECT_EQ(s.primitiveCount(), 0u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].line, 2);
  EXPECT_EQ(warnings[0].message, "p: degenerate polygon (zero area); dropped");
  EXPECT_EQ(warnings[1].message, "pp: 1 triangle has zero area; dropped");
}

TEST(Nff, PatchesThatAreNotSimplePolygonsAreReported) {
  std::vector<Diagnostic> warnings;
  const Scene s = parseNff("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8\n"
                           "pp 4 0 0 0 0 0 1  1 1 0 0 0 1  1 0 0 0 0 1  0 1 0 0 0 1\n",
                           "t.nff", &warnings);
  EXPECT_EQ(s.shapes<Triangle>().size(), 2u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 2);
  EXPECT_EQ(warnings[0].message, "pp: 1 patch is not a simple polygon (edges cross or touch, or a "
                                 "vertex repeats): its triangles are a best effort");
}

TEST(Nff, NoViewUsesTheDefaultCameraWithAWarning) {
  std::vector<Diagnostic> warnings;
  const Scene s = parseNff("s 0 0 0 1\n", "t.nff", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message, "no view ('v'): using the default camera of .sc scenes");
  EXPECT_EQ(s.camera.eye, Vec3(0, 0, 5));
}

std::string errorsOf(const std::string& text) {
  try {
    parseNff(text, "t.nff");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

constexpr const char* kView = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 8 8\n";

TEST(Nff, Errors) {
  const std::string v = kView;
  EXPECT_EQ(errorsOf(v + "x 1 2"), "t.nff:2:1: error: unknown command 'x'");
  EXPECT_EQ(errorsOf(v + "s 0 0 0"),
            "t.nff:2:1: error: s: expected RADIUS but reached the end of the file");
  EXPECT_EQ(errorsOf(v + "s 0 0 0 x"),
            "t.nff:2:9: error: s: expected RADIUS (a number) but found 'x'");
  EXPECT_EQ(errorsOf(v + "s 0 0 0 -1"), "t.nff:2:9: error: s: RADIUS must be positive, found '-1'");
  EXPECT_EQ(errorsOf(v + "s nan 0 0 1"), "t.nff:2:3: error: s: X is not a finite number ('nan')");
  EXPECT_EQ(errorsOf(v + "s 0 0 0 1 2"),
            "t.nff:2:11: error: expected a command but found the number '2' (too many numbers "
            "for the command before it?)");
  EXPECT_EQ(errorsOf("v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 40\n"),
            "t.nff:1:1: error: v: missing 'resolution'");
  EXPECT_EQ(errorsOf(v + "resolution 8 8"), "t.nff:2:1: error: v: duplicate 'resolution'");
  EXPECT_EQ(errorsOf(v + "s 0 0 0 1\nfrom 0 0 1"),
            "t.nff:3:1: error: 'from' belongs to a view: it may only follow 'v'");
  EXPECT_EQ(errorsOf("v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 resolution 0 8"),
            "t.nff:1:52: error: resolution: XRES must be an integer from 1 to 32768, found '0'");
  EXPECT_EQ(errorsOf("v from 0 0 5 at 0 0 0 up 0 1 0 angle 180 resolution 8 8"),
            "t.nff:1:38: error: angle: DEGREES must be greater than 0 and less than 180, found "
            "'180'");
  EXPECT_EQ(errorsOf("v from 0 0 5 at 0 0 5 up 0 1 0 angle 45 resolution 8 8"),
            "t.nff:1:1: error: v: 'from' and 'at' must be distinct points");
  EXPECT_EQ(errorsOf("v from 0 0 5 at 0 0 0 up 0 0 1 angle 45 resolution 8 8"),
            "t.nff:1:1: error: v: 'up' is parallel to the view direction (from 'from' to 'at')");
  EXPECT_EQ(errorsOf(v + v), "t.nff:2:1: error: duplicate 'v' (first given at t.nff:1:1)");
  EXPECT_EQ(errorsOf(v + "b 0 -1 0"), "t.nff:2:5: error: b: G must not be negative, found '-1'");
  EXPECT_EQ(errorsOf(v + "l 0 0 0 1 1 -1"),
            "t.nff:2:13: error: l: B must not be negative, found '-1'");
  EXPECT_EQ(errorsOf(v + "f 1 1 1 1 0 0 0.5 0"),
            "t.nff:2:19: error: f: IOR must be positive for a transmitting material (T > 0), "
            "found '0'");
  EXPECT_EQ(errorsOf(v + "f 1 1 1 -1 0 0 0 1"),
            "t.nff:2:9: error: f: KD must not be negative, found '-1'");
  EXPECT_EQ(errorsOf(v + "c 0 0 0 -1 0 1 0 1"),
            "t.nff:2:9: error: c: negative radius '-1' (only both radii may be negative, meaning "
            "seen from inside)");
  EXPECT_EQ(errorsOf(v + "c 0 0 0 1 0 0 0 1"),
            "t.nff:2:1: error: c: base and apex are the same point");
  EXPECT_EQ(errorsOf(v + "c 0 0 0 0 0 1 0 0"), "t.nff:2:1: error: c: both radii are zero");
  EXPECT_EQ(errorsOf(v + "p 2 0 0 0 1 0 0"),
            "t.nff:2:3: error: p: N must be an integer from 3 to 4294967295, found '2'");
  EXPECT_EQ(errorsOf(v + "p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1"),
            "t.nff:6:1: error: p: expected 12 numbers for 4 vertices, found 9 before 's'");
  EXPECT_EQ(errorsOf(v + "p 4 0 0 0 1 0 0 1 1 0 0 1 5"),
            "t.nff:2:1: error: p: polygon is not planar");
  EXPECT_EQ(errorsOf(v + "pp 3 0 0 0 0 0 1  1 0 0 0 0 0  0 1 0 0 0 1"),
            "t.nff:2:29: error: pp: the normal of vertex 2 must not be the zero vector");
  EXPECT_EQ(errorsOf(v + "pp 3 0 0 0 0 0 1  1 0 0 0 0 inf  0 1 0 0 0 1"),
            "t.nff:2:29: error: pp: NZ2 is not a finite number ('inf')");
  // Reading goes on after an error: both problems are reported.
  EXPECT_EQ(errorsOf(v + "s 0 0 0 x\nq\n"),
            "t.nff:2:9: error: s: expected RADIUS (a number) but found 'x'\n"
            "t.nff:3:1: error: unknown command 'q'");
}

TEST(Nff, UnreadableFile) {
  try {
    loadNff("/nonexistent/scene.nff");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/scene.nff:1:1: error: cannot read file: No such file or directory");
  }
}

TEST(Nff, LoadsFromAFile) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "prism_nff_test_scene.nff";
  {
    std::ofstream out(path);
    out << kScene;
  }
  const Scene s = loadNff(path);
  std::filesystem::remove(path);
  EXPECT_EQ(s.files[0], path.string());
  EXPECT_EQ(s.primitiveCount(), 5u);
}

} // namespace
} // namespace prism
