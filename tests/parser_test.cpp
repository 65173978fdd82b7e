// The scene language (docs/scene-language.md): every command, the state it keeps (material,
// transform, groups, includes) and every error with its exact position. Expected
// values are worked out by hand in the comments.
#include "core/io/scene_loader.h"
#include "core/io/scene_parser.h"
#include "core/shapes/shape_kinds.h"

#include "test_files.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

namespace prism {
namespace {

namespace fs = std::filesystem;

constexpr double kTol = 1e-12;

Scene parse(std::string_view text) { return parseScene(text, "t.sc"); }

using test::sceneErrorsOf;

std::vector<Diagnostic> diagnosticsOf(std::string_view text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.diagnostics();
  }
  return {};
}

void expectVec(const Vec3& actual, const Vec3& expected, double tol = kTol) {
  test::expectVecNear(actual, expected, tol);
}

// A directory of scene files unique to the running test, removed afterwards.
class ParserFiles : public ::testing::Test {
protected:
  fs::path write(const std::string& relative, const std::string& text) {
    test::writeFile(dir_ / relative, text);
    return dir_ / relative;
  }
  std::string name(const std::string& relative) const { return (dir_ / relative).string(); }

  std::string loadErrors(const std::string& relative) {
    try {
      loadScene(dir_ / relative);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  }

  test::ScratchDir scratch_;
  const fs::path dir_ = scratch_.path();
};

// ---------------------------------------------------------------------------
// Commands and values

TEST(Parser, EmptySceneHasTheDefaults) {
  const Scene s = parse("");
  expectVec(s.camera.eye, {0, 0, 5});
  expectVec(s.camera.lookat, {0, 0, 0});
  expectVec(s.camera.up, {0, 1, 0});
  EXPECT_EQ(s.camera.fov, 45.0);
  EXPECT_EQ(s.width, 512);
  EXPECT_EQ(s.height, 512);
  expectVec(s.background, {0, 0, 0});
  expectVec(s.ambient, {0, 0, 0});
  EXPECT_EQ(s.primitiveCount(), 0u);
  EXPECT_TRUE(s.lights.empty());
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_TRUE(s.groups[0].children.empty());
  ASSERT_EQ(s.files.size(), 1u);
  EXPECT_EQ(s.files[0], "t.sc");
}

TEST(Parser, CameraAndGlobalCommands) {
  const Scene s = parse("eye 1 2 3\n"
                        "lookat 4 5 6\n"
                        "up 0 0 1\n"
                        "fov 60\n"
                        "resolution 640 480\n"
                        "background 0.1 0.2 0.3\n"
                        "ambient 0.5 0.25 0\n");
  expectVec(s.camera.eye, {1, 2, 3});
  expectVec(s.camera.lookat, {4, 5, 6});
  expectVec(s.camera.up, {0, 0, 1});
  EXPECT_EQ(s.camera.fov, 60.0);
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  expectVec(s.background, {0.1, 0.2, 0.3});
  expectVec(s.ambient, {0.5, 0.25, 0});
}

TEST(Parser, TransformsNeverMoveTheCamera) {
  const Scene s = parse("translate 1 0 0\nscale 2 2 2\neye 0 0 3\nlookat 0 1 0\n");
  expectVec(s.camera.eye, {0, 0, 3});
  expectVec(s.camera.lookat, {0, 1, 0});
}

TEST(Parser, NumbersUseCFloatingPointSyntax) {
  // Each of these is exactly 30.
  for (const char* text : {"30", "3e1", "30.", "+30", "3.0e+1", "3E1", "300e-1", ".3e2", "0x1ep0",
                           "0X1E", "0x1.ep4", "030"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(parse(std::string("fov ") + text).camera.fov, 30.0);
  }
  EXPECT_EQ(parse("light -1.5 0x1p-2 -0x.8p1 1 1 1").lights.at(0).position, Vec3(-1.5, 0.25, -1.0));
}

TEST(Parser, TokensThatAreNotNumbers) {
  for (const char* text : {"1.0.0", "1e", "1e+", "--1", "+-1", "-+1", "0x", "0x1p", "1,5", "1f",
                           "e5", ".", "+", "-", "0x-1", "1..", "3O", "30deg"}) {
    SCOPED_TRACE(text);
    // 'fov' at column 1, the argument at column 5.
    EXPECT_EQ(sceneErrorsOf(std::string("fov ") + text),
              std::string("t.sc:1:5: error: fov: expected DEGREES (a number) but found '") + text +
                  "'");
  }
}

TEST(Parser, NonFiniteNumbersAreErrors) {
  for (const char* text : {"inf", "-inf", "nan", "NAN", "-nan", "infinity", "1e999", "-1e400",
                           "1.8e308", "0x1p2000"}) {
    SCOPED_TRACE(text);
    EXPECT_EQ(sceneErrorsOf(std::string("fov ") + text),
              std::string("t.sc:1:5: error: fov: DEGREES is not a finite number ('") + text + "')");
  }
}

TEST(Parser, ANonFiniteArgumentIsReportedOnce) {
  // Not also as a negative radius, a negative colour or a non-positive IR.
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 -inf"),
            "t.sc:1:14: error: sphere: RADIUS is not a finite number ('-inf')");
  EXPECT_EQ(sceneErrorsOf("surface 1 1 -inf 1 0 0 1 nan"),
            "t.sc:1:13: error: surface: B is not a finite number ('-inf')\n"
            "t.sc:1:26: error: surface: IR is not a finite number ('nan')");
  EXPECT_EQ(sceneErrorsOf("scale 1 nan 1"),
            "t.sc:1:9: error: scale: Y is not a finite number ('nan')");
}

TEST(Parser, NumbersTooSmallForADoubleBecomeZero) {
  // 1e-400 underflows to 0, so the radius is not positive; 4.9e-324 is the
  // smallest subnormal and still positive.
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1e-400"),
            "t.sc:1:14: error: sphere: radius must be positive, found '1e-400'");
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 0x1p-2000"),
            "t.sc:1:14: error: sphere: radius must be positive, found '0x1p-2000'");
  EXPECT_GT(parse("sphere 0 0 0 4.9e-324").shapes<Sphere>().at(0).radius, 0.0);
}

TEST(Parser, CommentsAnywhereAndCommandsAcrossLines) {
  const Scene s = parse("# a scene\n"
                        "sphere 1 # centre x\n"
                        "  2 3#glued to a number\n"
                        "\t4#radius\n"
                        "fov 30#c\n"
                        "light#c\n"
                        "1 2 3 0.5 0.5 0.5 # the file ends inside a comment");
  ASSERT_EQ(s.shapes<Sphere>().size(), 1u);
  expectVec(s.shapes<Sphere>()[0].center, {1, 2, 3});
  EXPECT_EQ(s.shapes<Sphere>()[0].radius, 4.0);
  EXPECT_EQ(s.shapes<Sphere>()[0].origin.line, 2u);
  EXPECT_EQ(s.camera.fov, 30.0);
  ASSERT_EQ(s.lights.size(), 1u);
  expectVec(s.lights[0].position, {1, 2, 3});
}

TEST(Parser, WindowsLineEndings) {
  const Scene s = parse("sphere 0 0 0 1\r\nsphere 1 1 1 2\r\n");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  EXPECT_EQ(s.shapes<Sphere>()[1].origin.line, 2u);
  EXPECT_EQ(sceneErrorsOf("fov 30\r\nfoo\r\n"), "t.sc:2:1: error: unknown keyword 'foo'");
}

TEST(Parser, ByteOrderMarkIsIgnored) {
  EXPECT_EQ(parse("\xEF\xBB\xBF"
                  "fov 30")
                .camera.fov,
            30.0);
  // Columns count from after the mark, as editors show them.
  EXPECT_EQ(sceneErrorsOf("\xEF\xBB\xBF"
                          "fov -1"),
            "t.sc:1:5: error: fov: DEGREES must be greater than 0 and less than 180, found '-1'");
}

TEST(Parser, LightsArePlacedThroughTheTransformButKeepTheirIntensity) {
  // translate(1,2,3) * scale(2): (1,0,0) -> (2,0,0) -> (3,2,3).
  // rotate 90 about z: (1,0,0) -> (0,1,0).
  const Scene s = parse("light 1 1 1 1 1 1\n"
                        "push translate 1 2 3 scale 2 2 2\n"
                        "light 1 0 0 0.5 2 3\n"
                        "pop\n"
                        "rotate 0 0 1 90\n"
                        "light 1 0 0 1 0 0\n");
  ASSERT_EQ(s.lights.size(), 3u);
  expectVec(s.lights[0].position, {1, 1, 1});
  expectVec(s.lights[1].position, {3, 2, 3});
  expectVec(s.lights[1].intensity, {0.5, 2, 3});
  expectVec(s.lights[2].position, {0, 1, 0});
  expectVec(s.lights[2].intensity, {1, 0, 0});
}

TEST(Parser, TransformsPostMultiply) {
  // After translate 5 0 0 then rotate 0 0 1 90 an object is rotated first:
  // (1,0,0) -> (0,1,0) -> (5,1,0).
  const Scene s = parse("translate 5 0 0\nrotate 0 0 1 90\nsphere 1 0 0 1\n");
  ASSERT_EQ(s.shapes<Sphere>().size(), 1u);
  expectVec(s.shapes<Sphere>()[0].center, {5, 1, 0});
  EXPECT_NEAR(s.shapes<Sphere>()[0].radius, 1.0, kTol);
}

TEST(Parser, RotationIsRightHandedAboutAnyAxisLength) {
  // 120 degrees about (1,1,1) permutes the axes x -> y -> z -> x; the axis length
  // does not matter.
  const Scene s = parse("rotate 2 2 2 120\nlight 1 0 0 1 1 1\n"
                        "rotate 1e-300 1e-300 1e-300 120\nlight 1 0 0 1 1 1\n");
  expectVec(s.lights.at(0).position, {0, 1, 0});
  expectVec(s.lights.at(1).position, {0, 0, 1});
}

TEST(Parser, SurfaceSetsTheMaterialOfLaterPrimitives) {
  const Scene s = parse("sphere 0 0 0 1\n"
                        "surface 0.5 0.25 1 0.7 0.2 0.1 30 1.5\n"
                        "sphere 0 0 0 1\n");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0], Material{}); // the default [1 1 1  1 0 0  1  1]
  const Material& m = s.materials[1];
  expectVec(m.color, {0.5, 0.25, 1});
  EXPECT_EQ(m.kdr, 0.7);
  EXPECT_EQ(m.ksr, 0.2);
  EXPECT_EQ(m.kst, 0.1);
  EXPECT_EQ(m.e, 30.0);
  EXPECT_EQ(m.ir, 1.5);
  EXPECT_EQ(s.shapes<Sphere>()[0].material, 0u);
  EXPECT_EQ(s.shapes<Sphere>()[1].material, 1u);
}

TEST(Parser, IdenticalMaterialsAreStoredOnce) {
  const Scene s = parse("surface 1 0 0 1 0 0 1 1\n"
                        "sphere 0 0 0 1\n"
                        "sphere 0 0 0 1\n"
                        "surface 0 1 0 1 0 0 1 1\n"
                        "polygon 3 0 0 0 1 0 0 0 1 0\n"
                        "surface 1 0 0 1 0 0 1 1\n" // red again
                        "sphere 0 0 0 1\n"
                        "surface 9 9 9 1 0 0 1 1\n"  // never used: not stored
                        "surface 0 1 0 1 -0 0 1 1\n" // -0 equals 0: green again
                        "scale 1 2 1\n"
                        "sphere 0 0 0 1\n");
  ASSERT_EQ(s.materials.size(), 2u);
  ASSERT_EQ(s.shapes<Sphere>().size(), 3u);
  EXPECT_EQ(s.shapes<Sphere>()[0].material, 0u);
  EXPECT_EQ(s.shapes<Sphere>()[1].material, 0u);
  EXPECT_EQ(s.shapes<Polygon>().at(0).material, 1u);
  EXPECT_EQ(s.shapes<Sphere>()[2].material, 0u);
  EXPECT_EQ(s.shapes<Ellipsoid>().at(0).material, 1u);
}

TEST(Parser, SphereUnderASimilarityStaysASphere) {
  // scale 2 then rotate 90 about z: centre (1,0,0) -> (0,1,0) -> (0,2,0), radius 3 -> 6.
  // A uniform mirror scale is a similarity too: centre (1,1,1) -> (-2,-2,-2), radius 2.
  const Scene s = parse("push scale 2 2 2 rotate 0 0 1 90 sphere 1 0 0 3 pop\n"
                        "push scale -2 -2 -2 sphere 1 1 1 1 pop\n");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  EXPECT_TRUE(s.shapes<Ellipsoid>().empty());
  expectVec(s.shapes<Sphere>()[0].center, {0, 2, 0});
  EXPECT_NEAR(s.shapes<Sphere>()[0].radius, 6.0, kTol);
  expectVec(s.shapes<Sphere>()[1].center, {-2, -2, -2});
  EXPECT_NEAR(s.shapes<Sphere>()[1].radius, 2.0, kTol);
  EXPECT_EQ(s.groups[0].primitives.size(), 0u);
  EXPECT_EQ(s.groups[1].primitives, (std::vector<PrimitiveRef>{{kindOf<Sphere>, 0}}));
  EXPECT_EQ(s.groups[2].primitives, (std::vector<PrimitiveRef>{{kindOf<Sphere>, 1}}));
}

TEST(Parser, SphereUnderNonUniformScaleIsAnEllipsoid) {
  // scale 2 1 1 on the unit sphere at (1,0,0): centre (2,0,0), semi-axes 2, 1, 1.
  const Scene s = parse("scale 2 1 1\nsphere 1 0 0 1\n");
  ASSERT_EQ(s.shapes<Ellipsoid>().size(), 1u);
  EXPECT_TRUE(s.shapes<Sphere>().empty());
  const Ellipsoid& e = s.shapes<Ellipsoid>()[0];
  expectVec(e.bounds.lo, {0, -1, -1});
  expectVec(e.bounds.hi, {4, 1, 1});
  EXPECT_EQ(e.origin.line, 2u);
  EXPECT_EQ(s.groups[0].primitives, (std::vector<PrimitiveRef>{{kindOf<Ellipsoid>, 0}}));
  // At the tip (4,0,0) the normal is +x. At (2 + 2 cos 45, sin 45, 0) the gradient
  // of ((x-2)/2)^2 + y^2 is ((x-2)/4, y) = (sqrt2/4, sqrt2/2) ~ (1, 2, 0).
  expectVec(normalAt(e, {4, 0, 0}), {1, 0, 0});
  const double h = std::sqrt(0.5);
  expectVec(normalAt(e, {2 + 2 * h, h, 0}), Vec3(1, 2, 0) / std::sqrt(5.0));
}

TEST(Parser, EllipsoidRadiusAndRotationApplyInTheRightOrder) {
  // Radius 2, stretched 3x along x, then rotated 90 about z: the long axis (12 long)
  // lies along y, centred on the translated origin (1,1,1).
  const Scene s = parse("translate 1 1 1\nrotate 0 0 1 90\nscale 3 1 1\nsphere 0 0 0 2\n");
  ASSERT_EQ(s.shapes<Ellipsoid>().size(), 1u);
  const Ellipsoid& e = s.shapes<Ellipsoid>()[0];
  expectVec(e.bounds.lo, {-1, -5, -1});
  expectVec(e.bounds.hi, {3, 7, 3});
  expectVec(normalAt(e, {1, 7, 1}), {0, 1, 0});
  expectVec(normalAt(e, {3, 1, 1}), {1, 0, 0});
}

TEST(Parser, PolygonKeepsCounterclockwiseOrderAndFacesItsFront) {
  const Scene s = parse("polygon 3 0 0 0 1 0 0 0 1 0\n"
                        "translate 0 0 2\n"
                        "polygon 4\n"
                        "  0 0 0\n"
                        "  0 1 0\n"
                        "  1 1 0\n"
                        "  1 0 0\n");
  ASSERT_EQ(s.shapes<Polygon>().size(), 2u);
  const Polygon& a = s.shapes<Polygon>()[0];
  EXPECT_EQ(a.firstVertex, 0u);
  EXPECT_EQ(a.vertexCount, 3u);
  expectVec(a.normal, {0, 0, 1}); // x then y: counterclockwise seen from +z
  EXPECT_NEAR(a.planeOffset, 0.0, kTol);
  EXPECT_EQ(a.origin.line, 1u);
  const Polygon& b = s.shapes<Polygon>()[1];
  EXPECT_EQ(b.firstVertex, 3u);
  EXPECT_EQ(b.vertexCount, 4u);
  expectVec(b.normal, {0, 0, -1});        // y then x: clockwise from +z
  EXPECT_NEAR(b.planeOffset, -2.0, kTol); // the plane z = 2, normal -z
  EXPECT_EQ(b.origin.line, 3u);
  ASSERT_EQ(s.polygonVertices.size(), 7u);
  expectVec(s.polygonVertices[1], {1, 0, 0});
  expectVec(s.polygonVertices[3], {0, 0, 2});
  expectVec(s.polygonVertices[5], {1, 1, 2});
  const Aabb box = s.bounds({kindOf<Polygon>, 1});
  expectVec(box.lo, {0, 0, 2});
  expectVec(box.hi, {1, 1, 2});
}

TEST(Parser, ConcavePolygon) {
  // An L shape, counterclockwise from +z.
  const Scene s = parse("polygon 6  0 0 0  2 0 0  2 1 0  1 1 0  1 2 0  0 2 0\n");
  ASSERT_EQ(s.shapes<Polygon>().size(), 1u);
  expectVec(s.shapes<Polygon>()[0].normal, {0, 0, 1});
}

TEST(Parser, MirrorTransformReversesPolygonVertices) {
  // scale -1 1 1 maps the vertices to (0,0,0), (-1,0,0), (0,1,0), which run clockwise
  // seen from +z; stored reversed they run counterclockwise again, so the front
  // stays +z as the mirrored object's outside does.
  const Scene s = parse("scale -1 1 1\npolygon 3 0 0 0 1 0 0 0 1 0\n");
  ASSERT_EQ(s.shapes<Polygon>().size(), 1u);
  expectVec(s.shapes<Polygon>()[0].normal, {0, 0, 1});
  ASSERT_EQ(s.polygonVertices.size(), 3u);
  expectVec(s.polygonVertices[0], {0, 1, 0});
  expectVec(s.polygonVertices[1], {-1, 0, 0});
  expectVec(s.polygonVertices[2], {0, 0, 0});
}

TEST(Parser, MirroredClosedBoxKeepsOutwardNormals) {
  // The +z face of a unit cube centred at the origin, under a mirror in x and a
  // translation: its normal must still point away from the cube's centre (5,0,0).
  const Scene s = parse("translate 5 0 0 scale -1 1 1\n"
                        "polygon 4  -0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5\n");
  ASSERT_EQ(s.shapes<Polygon>().size(), 1u);
  expectVec(s.shapes<Polygon>()[0].normal, {0, 0, 1});
  EXPECT_NEAR(s.shapes<Polygon>()[0].planeOffset, 0.5, kTol);
}

TEST(Parser, PushAndPopRestoreMaterialAndTransform) {
  const Scene s = parse("surface 1 0 0 1 0 0 1 1\n"
                        "push\n"
                        "  surface 0 1 0 1 0 0 1 1\n"
                        "  translate 10 0 0\n"
                        "  sphere 0 0 0 1\n"
                        "pop\n"
                        "sphere 0 0 0 1\n");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  expectVec(s.shapes<Sphere>()[0].center, {10, 0, 0});
  expectVec(s.materials.at(s.shapes<Sphere>()[0].material).color, {0, 1, 0});
  expectVec(s.shapes<Sphere>()[1].center, {0, 0, 0});
  expectVec(s.materials.at(s.shapes<Sphere>()[1].material).color, {1, 0, 0});
}

TEST(Parser, GroupsFollowPushAndPop) {
  const Scene s = parse("sphere 0 0 0 1\n"            // group 0
                        "push\n"                      // group 1, line 2
                        "  sphere 0 0 0 1\n"          // group 1
                        "  push sphere 0 0 0 1 pop\n" // group 2, line 4
                        "  push\n"                    // group 3, line 5
                        "    polygon 3 0 0 0 1 0 0 0 1 0\n"
                        "  pop\n"
                        "  sphere 0 0 0 1\n" // group 1 again
                        "pop\n"
                        "push pop\n"         // group 4, empty
                        "sphere 0 0 0 1\n"); // group 0 again
  ASSERT_EQ(s.groups.size(), 5u);
  using R = std::vector<PrimitiveRef>;
  constexpr auto S = kindOf<Sphere>;
  EXPECT_EQ(s.groups[0].children, (std::vector<std::uint32_t>{1, 4}));
  EXPECT_EQ(s.groups[0].primitives, (R{{S, 0}, {S, 4}}));
  EXPECT_EQ(s.groups[1].children, (std::vector<std::uint32_t>{2, 3}));
  EXPECT_EQ(s.groups[1].primitives, (R{{S, 1}, {S, 3}}));
  EXPECT_EQ(s.groups[2].primitives, (R{{S, 2}}));
  EXPECT_EQ(s.groups[3].primitives, (R{{kindOf<Polygon>, 0}}));
  EXPECT_TRUE(s.groups[4].primitives.empty());
  EXPECT_EQ(s.groups[1].origin.line, 2u);
  EXPECT_EQ(s.groups[2].origin.line, 4u);
  EXPECT_EQ(s.groups[3].origin.line, 5u);
  EXPECT_EQ(s.groups[4].origin.line, 10u);
}

// ---------------------------------------------------------------------------
// Include

TEST_F(ParserFiles, IncludeLetsMaterialAndTransformFlowInAndOut) {
  write("main.sc", "surface 1 0 0 1 0 0 1 1\n"
                   "translate 1 0 0\n"
                   "include sub/part.sc\n"
                   "sphere 0 0 0 1\n");
  write("sub/part.sc", "sphere 0 0 0 1 # red, at (1,0,0)\n"
                       "surface 0 1 0 1 0 0 1 1\n"
                       "translate 0 1 0\n");
  const Scene s = loadScene(dir_ / "main.sc");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  expectVec(s.shapes<Sphere>()[0].center, {1, 0, 0});
  expectVec(s.materials.at(s.shapes<Sphere>()[0].material).color, {1, 0, 0});
  expectVec(s.shapes<Sphere>()[1].center, {1, 1, 0});
  expectVec(s.materials.at(s.shapes<Sphere>()[1].material).color, {0, 1, 0});
  ASSERT_EQ(s.files.size(), 2u);
  EXPECT_EQ(s.files[0], name("main.sc"));
  EXPECT_EQ(s.files[1], name("sub/part.sc"));
  EXPECT_EQ(s.shapes<Sphere>()[0].origin.file, 1u);
  EXPECT_EQ(s.shapes<Sphere>()[0].origin.line, 1u);
  EXPECT_EQ(s.shapes<Sphere>()[1].origin.file, 0u);
  EXPECT_EQ(s.shapes<Sphere>()[1].origin.line, 4u);
  // include opens no group.
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].primitives.size(), 2u);
}

TEST_F(ParserFiles, IncludePathsAreRelativeToTheIncludingFile) {
  write("main.sc", "include a/b.sc\n");
  write("a/b.sc", "include c.sc\ninclude ../d.sc\n");
  write("a/c.sc", "sphere 0 0 0 1\n");
  write("d.sc", "sphere 1 0 0 1\n");
  const Scene s = loadScene(dir_ / "main.sc");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  EXPECT_EQ(s.files, (std::vector<std::string>{name("main.sc"), name("a/b.sc"), name("a/c.sc"),
                                               name("d.sc")}));
  EXPECT_EQ(s.shapes<Sphere>()[0].origin.file, 2u);
  EXPECT_EQ(s.shapes<Sphere>()[1].origin.file, 3u);
}

TEST_F(ParserFiles, TheSamePathWrittenInTwoFoldersNamesTwoFiles) {
  // Include paths are resolved once per including file and PATH: the same
  // text in another folder must still lead to that folder's file.
  write("main.sc", "include a/part.sc\ninclude b/part.sc\ninclude a/part.sc\n");
  write("a/part.sc", "include leaf.sc\n");
  write("b/part.sc", "include leaf.sc\n");
  write("a/leaf.sc", "sphere 0 0 0 1\n");
  write("b/leaf.sc", "sphere 5 0 0 2\n");
  const Scene s = loadScene(dir_ / "main.sc");
  ASSERT_EQ(s.shapes<Sphere>().size(), 3u);
  EXPECT_EQ(s.shapes<Sphere>()[0].radius, 1.0);
  EXPECT_EQ(s.shapes<Sphere>()[1].radius, 2.0);
  EXPECT_EQ(s.shapes<Sphere>()[2].radius, 1.0);
  EXPECT_EQ(s.files,
            (std::vector<std::string>{name("main.sc"), name("a/part.sc"), name("a/leaf.sc"),
                                      name("b/part.sc"), name("b/leaf.sc")}));
  EXPECT_EQ(s.shapes<Sphere>()[2].origin.file, 2u);
}

TEST_F(ParserFiles, QuotedIncludePathMayHoldSpacesAndHashes) {
  write("main.sc", "include \"my part#1.sc\" # a comment\n"
                   "include\n"
                   "   \"my part#1.sc\"\n");
  write("my part#1.sc", "push translate 0 0 1 sphere 0 0 0 1 pop\n");
  const Scene s = loadScene(dir_ / "main.sc");
  ASSERT_EQ(s.shapes<Sphere>().size(), 2u);
  // One file included twice: stored once, and each inclusion makes its own group.
  EXPECT_EQ(s.files.size(), 2u);
  EXPECT_EQ(s.shapes<Sphere>()[1].origin.file, 1u);
  ASSERT_EQ(s.groups.size(), 3u);
  EXPECT_EQ(s.groups[0].children, (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(s.groups[1].origin.file, 1u);
}

TEST_F(ParserFiles, IncludedFileErrorsNameThatFile) {
  write("main.sc", "sphere 0 0 0 1\ninclude sub/bad.sc\n");
  write("sub/bad.sc", "\n  sphere 0 0 0 -1\n");
  EXPECT_EQ(loadErrors("main.sc"),
            name("sub/bad.sc") + ":2:16: error: sphere: negative radius '-1'");
}

TEST_F(ParserFiles, DirectIncludeCycle) {
  write("a.sc", "sphere 0 0 0 1\ninclude a.sc\n");
  EXPECT_EQ(loadErrors("a.sc"),
            name("a.sc") + ":2:9: error: include cycle: " + name("a.sc") + " -> " + name("a.sc"));
}

TEST_F(ParserFiles, IndirectIncludeCycleThroughAnotherSpelling) {
  write("a.sc", "include sub/b.sc\n");
  write("sub/b.sc", "sphere 0 0 0 1\n  include \"../a.sc\"\n");
  // The PATH token (with its quote) starts at column 11 of b.sc's line 2.
  EXPECT_EQ(loadErrors("a.sc"), name("sub/b.sc") + ":2:11: error: include cycle: " + name("a.sc") +
                                    " -> " + name("sub/b.sc") + " -> " + name("a.sc"));
}

TEST_F(ParserFiles, UnreadableIncludes) {
  write("main.sc", "include missing.sc\n"
                   "include sub\n");
  fs::create_directories(dir_ / "sub");
  EXPECT_EQ(loadErrors("main.sc"), name("main.sc") + ":1:9: error: cannot read '" +
                                       name("missing.sc") + "': No such file or directory\n" +
                                       name("main.sc") + ":2:9: error: cannot read '" +
                                       name("sub") + "': Is a directory");
}

TEST_F(ParserFiles, UnreadableMainFile) {
  EXPECT_EQ(loadErrors("nope.sc"),
            name("nope.sc") + ":1:1: error: cannot read file: No such file or directory");
  try {
    loadScene(dir_ / "nope.sc");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u);
    EXPECT_EQ(e.diagnostics()[0].line, 1);
    EXPECT_EQ(e.diagnostics()[0].column, 1);
  }
}

TEST_F(ParserFiles, IncludeNestingIsLimitedTo64Files) {
  // f0 .. f63 is 64 files deep: allowed. f63 including f64 would be the 65th.
  for (int i = 0; i < 64; ++i) {
    write("f" + std::to_string(i) + ".sc", "include f" + std::to_string(i + 1) + ".sc\n");
  }
  write("f64.sc", "sphere 0 0 0 1\n");
  EXPECT_EQ(loadErrors("f0.sc"),
            name("f63.sc") + ":1:9: error: include: files nested more than 64 deep");
  EXPECT_EQ(loadScene(dir_ / "f1.sc").shapes<Sphere>().size(), 1u);
}

TEST_F(ParserFiles, PushAndPopBalanceWithinEachFile) {
  write("main.sc", "push\ninclude pops.sc\npop\n");
  write("pops.sc", "pop\n");
  EXPECT_EQ(loadErrors("main.sc"),
            name("pops.sc") +
                ":1:1: error: pop without matching push in this file (push and pop must balance "
                "within each file)");
  write("main2.sc", "include pushes.sc\npop\n");
  write("pushes.sc", "sphere 0 0 0 1\n push\n");
  EXPECT_EQ(loadErrors("main2.sc"), name("pushes.sc") + ":2:2: error: push without matching pop\n" +
                                        name("main2.sc") +
                                        ":2:1: error: pop without matching push");
}

TEST_F(ParserFiles, DuplicateCameraCommandAcrossFiles) {
  write("main.sc", "include cam.sc\n\n  fov 50\n");
  write("cam.sc", "eye 0 0 9\nfov 40\n");
  EXPECT_EQ(loadErrors("main.sc"), name("main.sc") +
                                       ":3:3: error: duplicate 'fov' (first given at " +
                                       name("cam.sc") + ":2:1)");
}

TEST_F(ParserFiles, ExponentialIncludesAreBounded) {
  // leaf.sc is 1 MiB of comment; each level includes the next twice, so l0 would
  // expand to 2^9 MiB. The parse stops at 256 MiB of text.
  write("leaf.sc", "#" + std::string((1 << 20) - 1, 'x'));
  for (int i = 0; i < 9; ++i) {
    const std::string next = i == 8 ? "leaf.sc" : "l" + std::to_string(i + 1) + ".sc";
    write("l" + std::to_string(i) + ".sc", "include " + next + "\ninclude " + next + "\n");
  }
  try {
    loadScene(dir_ / "l0.sc");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diagnostics().at(0).message,
              "include: the scene text, counting every inclusion, exceeds 256 MiB");
  }
}

// ---------------------------------------------------------------------------
// Errors, each at its exact line and column

TEST(ParserErrors, FormatAndWhat) {
  const Diagnostic d{"dir/a.sc", 12, 7, "sphere: negative radius '-1'"};
  EXPECT_EQ(d.format(), "dir/a.sc:12:7: error: sphere: negative radius '-1'");
  const SceneError e({d, Diagnostic{"b.sc", 1, 1, "x"}});
  EXPECT_EQ(std::string(e.what()),
            "dir/a.sc:12:7: error: sphere: negative radius '-1'\nb.sc:1:1: error: x");
  EXPECT_EQ(e.diagnostics().size(), 2u);
}

// Warnings quote names from the input as errors do: a control byte in a file
// name or message cannot reach the terminal.
TEST(ParserErrors, WarningsAreFormattedPrintableLikeErrors) {
  const Diagnostic d{"dir/\x1b[2Ja.obj", 3, 1, "unsupported statement 'curv\x07'"};
  EXPECT_EQ(formatWarning(d), "dir/\\x1b[2Ja.obj:3:1: warning: unsupported statement 'curv\\x07'");
}

TEST(ParserErrors, UnknownKeyword) {
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1\n  shpere 1 2 3 4\n"),
            "t.sc:2:3: error: unknown keyword 'shpere'");
  EXPECT_EQ(sceneErrorsOf("Sphere 0 0 0 1"),
            "t.sc:1:1: error: unknown keyword 'Sphere' (keywords are lower case: 'sphere')");
  const auto d = diagnosticsOf("fov 30\n\tcamera 1 2 3\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].file, "t.sc");
  EXPECT_EQ(d[0].line, 2);
  EXPECT_EQ(d[0].column, 2); // a tab is one byte
  EXPECT_EQ(d[0].message, "unknown keyword 'camera'");
}

TEST(ParserErrors, UnprintableAndLongTokensAreShownSafely) {
  EXPECT_EQ(sceneErrorsOf(std::string("\x01x\x7f", 3)),
            "t.sc:1:1: error: unknown keyword '\\x01x\\x7f'");
  EXPECT_EQ(sceneErrorsOf(std::string(100, 'a')),
            "t.sc:1:1: error: unknown keyword '" + std::string(40, 'a') + "...'");
}

// Well-formed UTF-8 is shown as it is; every byte that is not part of it (a
// stray continuation byte, an overlong form, a surrogate, a code point above
// U+10FFFF, a sequence cut short) is escaped like a control byte.
TEST(ParserErrors, InvalidUtf8IsEscapedAndValidUtf8Kept) {
  EXPECT_EQ(sceneErrorsOf("sph\u00e8re"), "t.sc:1:1: error: unknown keyword 'sph\u00e8re'");
  EXPECT_EQ(sceneErrorsOf("\u2192\U0001F600"),
            "t.sc:1:1: error: unknown keyword '\u2192\U0001F600'");
  EXPECT_EQ(sceneErrorsOf("a\x80"
                          "b"),
            "t.sc:1:1: error: unknown keyword 'a\\x80b'");
  EXPECT_EQ(sceneErrorsOf("\xc0\xaf"), "t.sc:1:1: error: unknown keyword '\\xc0\\xaf'");
  EXPECT_EQ(sceneErrorsOf("\xed\xa0\x80"), "t.sc:1:1: error: unknown keyword '\\xed\\xa0\\x80'");
  EXPECT_EQ(sceneErrorsOf("\xf4\x90\x80\x80"),
            "t.sc:1:1: error: unknown keyword '\\xf4\\x90\\x80\\x80'");
  EXPECT_EQ(sceneErrorsOf("x\xe2\x86"), "t.sc:1:1: error: unknown keyword 'x\\xe2\\x86'");
  // The file name is made printable too (it comes from the command line).
  EXPECT_EQ(sceneErrorsOf("bad", "\xff.sc"), "\\xff.sc:1:1: error: unknown keyword 'bad'");
}

TEST(ParserErrors, TooManyNumbers) {
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1 2 3\n"),
            "t.sc:1:16: error: expected a command but found the number '2' (too many numbers for "
            "the command before it?)");
}

TEST(ParserErrors, MissingOrNonNumericArgument) {
  // 'light' begins the next command, so it is parsed (and is fine).
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 light 1 2 3 1 1 1"),
            "t.sc:1:14: error: sphere: expected RADIUS (a number) but found 'light'");
  // 'zero' is not a keyword: it is skipped with the numbers after it.
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 zero 1\nsphere 0 0 0 1"),
            "t.sc:1:12: error: sphere: expected Z (a number) but found 'zero'");
  // At the end of the file the command keyword is pointed at.
  EXPECT_EQ(sceneErrorsOf("fov 30\n  sphere 0 0 0\n"),
            "t.sc:2:3: error: sphere: expected RADIUS but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("light 1 2 3 # no colour"),
            "t.sc:1:1: error: light: expected R but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("surface 1 1 1 1 0 0 1 eye 0 0 1"),
            "t.sc:1:23: error: surface: expected IR (a number) but found 'eye'");
  EXPECT_EQ(sceneErrorsOf("rotate 0 0 1 ninety"),
            "t.sc:1:14: error: rotate: expected DEGREES (a number) but found 'ninety'");
  EXPECT_EQ(sceneErrorsOf("translate 1 2"),
            "t.sc:1:1: error: translate: expected Z but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("scale x"),
            "t.sc:1:7: error: scale: expected X (a number) but found 'x'");
  EXPECT_EQ(sceneErrorsOf("eye 1 2 up 0 0 1"),
            "t.sc:1:9: error: eye: expected Z (a number) but found 'up'");
  EXPECT_EQ(sceneErrorsOf("background 0 0"),
            "t.sc:1:1: error: background: expected B but reached the end of the file");
}

TEST(ParserErrors, NegativeAndZeroRadius) {
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 -2"), "t.sc:1:14: error: sphere: negative radius '-2'");
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 0"),
            "t.sc:1:14: error: sphere: radius must be positive, found '0'");
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 -0"),
            "t.sc:1:14: error: sphere: radius must be positive, found '-0'");
}

TEST(ParserErrors, FieldOfView) {
  for (const char* text : {"0", "180", "-5", "200"}) {
    EXPECT_EQ(sceneErrorsOf(std::string("fov ") + text),
              std::string("t.sc:1:5: error: fov: DEGREES must be greater than 0 and less than 180, "
                          "found '") +
                  text + "'");
  }
  EXPECT_EQ(parse("fov 179.5").camera.fov, 179.5);
  EXPECT_EQ(parse("fov 1e-3").camera.fov, 1e-3);
}

TEST(ParserErrors, ResolutionIsTwoIntegerLiterals) {
  EXPECT_EQ(parse("resolution +640 480").width, 640);
  EXPECT_EQ(parse("resolution 32768 1").width, 32768);
  EXPECT_EQ(sceneErrorsOf("resolution 640.0 480"),
            "t.sc:1:12: error: resolution: W must be an integer from 1 to 32768, found '640.0'");
  EXPECT_EQ(sceneErrorsOf("resolution 640 0"),
            "t.sc:1:16: error: resolution: H must be an integer from 1 to 32768, found '0'");
  EXPECT_EQ(sceneErrorsOf("resolution 32769 -1"),
            "t.sc:1:12: error: resolution: W must be an integer from 1 to 32768, found '32769'\n"
            "t.sc:1:18: error: resolution: H must be an integer from 1 to 32768, found '-1'");
  EXPECT_EQ(sceneErrorsOf("resolution 0x280 99999999999999999999999"),
            "t.sc:1:12: error: resolution: W must be an integer from 1 to 32768, found '0x280'\n"
            "t.sc:1:18: error: resolution: H must be an integer from 1 to 32768, found "
            "'99999999999999999999999'");
  EXPECT_EQ(sceneErrorsOf("resolution 640 tall"),
            "t.sc:1:16: error: resolution: expected H (an integer) but found 'tall'");
}

TEST(ParserErrors, NegativeColoursAndCoefficients) {
  EXPECT_EQ(sceneErrorsOf("background 0 -1 0"),
            "t.sc:1:14: error: background: G must not be negative, found '-1'");
  EXPECT_EQ(sceneErrorsOf("ambient -0.5 0 0"),
            "t.sc:1:9: error: ambient: R must not be negative, found '-0.5'");
  EXPECT_EQ(sceneErrorsOf("light 0 0 0 1 1 -1e-9"),
            "t.sc:1:17: error: light: B must not be negative, found '-1e-9'");
  // Light positions may be negative.
  EXPECT_EQ(parse("light -1 -2 -3 1 1 1").lights.size(), 1u);
  // Columns: R 9, G 11, B 13, KDR 15, KSR 17, KST 19, E 21, IR 23.
  EXPECT_EQ(sceneErrorsOf("surface 1 1 1 1 -.5 0 1 1"),
            "t.sc:1:17: error: surface: KSR must not be negative, found '-.5'");
  EXPECT_EQ(sceneErrorsOf("surface 1 1 1 1 0 0 -1 1"),
            "t.sc:1:21: error: surface: E must not be negative, found '-1'");
  EXPECT_EQ(sceneErrorsOf("surface -1 1 1 -1 0 0 1 0"),
            "t.sc:1:9: error: surface: R must not be negative, found '-1'\n"
            "t.sc:1:16: error: surface: KDR must not be negative, found '-1'\n"
            "t.sc:1:25: error: surface: IR must be positive, found '0'");
  // e = 0 is allowed (docs/rendering-model.md).
  EXPECT_EQ(parse("surface 1 1 1 1 1 0 0 1 sphere 0 0 0 1").materials.at(0).e, 0.0);
}

TEST(ParserErrors, ScaleAndRotate) {
  EXPECT_EQ(sceneErrorsOf("scale 1 0 1"), "t.sc:1:9: error: scale: Y must not be zero, found '0'");
  EXPECT_EQ(sceneErrorsOf("rotate 0 0 0 45"),
            "t.sc:1:8: error: rotate: the axis (AX AY AZ) must not be zero");
  // A transform that overflows is refused where it would happen.
  EXPECT_EQ(sceneErrorsOf("scale 1e200 1e200 1e200\nscale 1e200 1 1\n"),
            "t.sc:2:1: error: scale: the current transform would become degenerate (too large or "
            "too small)");
  EXPECT_EQ(sceneErrorsOf("scale 1e-200 1 1\nscale 1e-200 1 1\n"),
            "t.sc:2:1: error: scale: the current transform would become degenerate (too large or "
            "too small)");
  EXPECT_EQ(sceneErrorsOf("scale 1e300 1 1\nlight 1e300 0 0 1 1 1\n"),
            "t.sc:2:1: error: light: lies outside the supported range: world coordinates (after "
            "the current transform) must be within +-1e30");
  EXPECT_EQ(sceneErrorsOf("scale 1e300 1e300 1e300\nsphere 0 0 0 1e300\n"),
            "t.sc:2:1: error: sphere: lies outside the supported range: world coordinates (after "
            "the current transform) must be within +-1e30");
  EXPECT_EQ(sceneErrorsOf("scale 1e-300 1e-300 1e-300\nsphere 0 0 0 1e-300\n"),
            "t.sc:2:1: error: sphere: too small after the current transform");
}

// An ellipsoid or an elliptic cone stretched more than 1e10 times along one
// direction than another is thinner than the ray offsets (and near 1e16 its
// map is singular to double precision, so `prism convert` wrote NaN, found by
// fuzz_roundtrip): refused where it is made. Circular cones are not limited.
TEST(ParserErrors, TransformsStretchingTooUnevenly) {
  const std::string uneven =
      ": the current transform stretches it too unevenly: one direction more than 1e10 times "
      "another";
  EXPECT_EQ(sceneErrorsOf("scale 1 1 1e-11\nsphere 0 0 0 1"), "t.sc:2:1: error: sphere" + uneven);
  EXPECT_EQ(sceneErrorsOf("rotate 1 2 3 40 scale 0.9 1e-300 0.9 rotate 0 0 1 10 sphere 0 0 0 1"),
            "t.sc:1:54: error: sphere" + uneven);
  EXPECT_EQ(sceneErrorsOf("scale 1e6 1 1e-5\ncone 0 0 0 1  1 1 1 0.5"),
            "t.sc:2:1: error: cone" + uneven);
  // Just inside: axes 2, 1 and 1e-9 (|m| |m^-1| = 2.2e9).
  EXPECT_EQ(parse("rotate 1 2 3 40 scale 2 1 1e-9 sphere 0 0 0 1").shapes<Ellipsoid>().size(), 1u);
  // A circular cone of any proportions under a uniform scale.
  EXPECT_EQ(parse("scale 1e-5 1e-5 1e-5 cone 0 0 0 1e20  0 0 1 1e20").shapes<Cone>().size(), 1u);
}

// Squares of distances must not overflow (a sphere of radius 1e155 was never
// hit, an eye at 1e300 had "no view direction"): world coordinates are kept
// within +-1e30, the limit checked after every transform, and exactly at it.
TEST(ParserErrors, WorldCoordinatesBeyondTheSupportedRange) {
  const std::string outside = ": lies outside the supported range: world coordinates (after the "
                              "current transform) must be within +-1e30";
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1e155"), "t.sc:1:1: error: sphere" + outside);
  EXPECT_EQ(sceneErrorsOf("sphere 1e30 0 0 1e15"), "t.sc:1:1: error: sphere" + outside);
  EXPECT_EQ(parse("sphere 0 0 0 1e30").shapes<Sphere>().at(0).radius, 1e30); // the limit itself
  EXPECT_EQ(sceneErrorsOf("scale 1e20 1e20 1e20\nscale 1e20 1 1 sphere 0 0 0 1"),
            "t.sc:2:16: error: sphere" + outside);
  EXPECT_EQ(sceneErrorsOf("scale 1e29 1 1 sphere 0 0 0 20"), "t.sc:1:16: error: sphere" + outside);
  EXPECT_EQ(sceneErrorsOf("polygon 3 0 0 0 2e30 0 0 0 1 0"), "t.sc:1:1: error: polygon" + outside);
  EXPECT_EQ(sceneErrorsOf("translate 0 0 -1e30 triangle 0 0 -1e25 1 0 0 0 1 0"),
            "t.sc:1:21: error: triangle" + outside);
  EXPECT_EQ(sceneErrorsOf("cone 0 0 0 1e31 0 0 1 0"), "t.sc:1:1: error: cone" + outside);
  EXPECT_EQ(sceneErrorsOf("light 0 0 -2e30 1 1 1"), "t.sc:1:1: error: light" + outside);
  EXPECT_EQ(sceneErrorsOf("eye 1e300 0 0"),
            "t.sc:1:5: error: eye: the point must be within +-1e30");
  EXPECT_EQ(sceneErrorsOf("lookat 0 0 -1e31"),
            "t.sc:1:8: error: lookat: the point must be within +-1e30");
  // `up` is a direction: any length will do.
  EXPECT_EQ(parse("up 0 1e300 0 sphere 0 0 0 1").camera.up, Vec3(0, 1e300, 0));
}

TEST(ParserErrors, PolygonVertexCount) {
  EXPECT_EQ(sceneErrorsOf("polygon 2 0 0 0 1 0 0\nsphere 0 0 0 1"),
            "t.sc:1:9: error: polygon: N must be an integer from 3 to 4294967295, found '2'");
  EXPECT_EQ(sceneErrorsOf("polygon 3.0 0 0 0 1 0 0 0 1 0"),
            "t.sc:1:9: error: polygon: N must be an integer from 3 to 4294967295, found '3.0'");
  EXPECT_EQ(sceneErrorsOf("polygon 4294967296 1 2 3"),
            "t.sc:1:9: error: polygon: N must be an integer from 3 to 4294967295, found "
            "'4294967296'");
  EXPECT_EQ(sceneErrorsOf("polygon three 0 0 0"),
            "t.sc:1:9: error: polygon: expected N (an integer) but found 'three'");
  EXPECT_EQ(sceneErrorsOf("polygon"),
            "t.sc:1:1: error: polygon: expected N but reached the end of the file");
}

TEST(ParserErrors, PolygonWrongNumberOfCoordinates) {
  EXPECT_EQ(sceneErrorsOf("polygon 4 0 0 0 1 0 0 1 1 0"),
            "t.sc:1:1: error: polygon: expected 12 numbers for 4 vertices, found 9 before the end "
            "of the file");
  EXPECT_EQ(
      sceneErrorsOf("polygon 4 0 0 0 1 0 0 1 1 0\nsphere 0 0 0 1\n"),
      "t.sc:2:1: error: polygon: expected 12 numbers for 4 vertices, found 9 before 'sphere'");
  EXPECT_EQ(sceneErrorsOf("polygon 3 0 0 0 1 0 0 0 1 z 5 6\nsphere 0 0 0 1\n"),
            "t.sc:1:27: error: polygon: expected 9 numbers for 3 vertices, found 8 before 'z'");
}

TEST(ParserErrors, PolygonNonFiniteCoordinate) {
  EXPECT_EQ(sceneErrorsOf("polygon 3 0 0 0 1 nan 0 0 1 0"),
            "t.sc:1:19: error: polygon: Y2 is not a finite number ('nan')");
}

TEST(ParserErrors, DegenerateAndNonPlanarPolygons) {
  // The wording of the reason is geometry's (polygonProblem); the parser places it at
  // the keyword.
  const auto collinear = diagnosticsOf("sphere 0 0 0 1\n polygon 3 0 0 0 1 0 0 2 0 0");
  ASSERT_EQ(collinear.size(), 1u);
  EXPECT_EQ(collinear[0].line, 2);
  EXPECT_EQ(collinear[0].column, 2);
  EXPECT_EQ(collinear[0].message.rfind("polygon: ", 0), 0u);
  EXPECT_NE(collinear[0].message.find("degenerate"), std::string::npos);
  const auto bent = diagnosticsOf("polygon 4 0 0 0 1 0 0 1 1 1 0 1 0");
  ASSERT_EQ(bent.size(), 1u);
  EXPECT_EQ(bent[0].column, 1);
  EXPECT_NE(bent[0].message.find("not planar"), std::string::npos);
  // 1e300 * 1e300 overflows: the transformed vertex is rejected too.
  const auto huge = diagnosticsOf("scale 1e300 1 1\npolygon 3 0 0 0 1e300 0 0 0 1 0");
  ASSERT_EQ(huge.size(), 1u);
  EXPECT_EQ(huge[0].line, 2);
  EXPECT_EQ(huge[0].column, 1);
  EXPECT_EQ(huge[0].message.rfind("polygon: ", 0), 0u);
}

TEST(ParserErrors, HugeVertexCountWithLittleTextFailsQuickly) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(sceneErrorsOf("polygon 4294967295 0 0 0"),
            "t.sc:1:1: error: polygon: expected 12884901885 numbers for 4294967295 vertices, "
            "found 3 before the end of the file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(ParserErrors, UnbalancedPushAndPop) {
  EXPECT_EQ(sceneErrorsOf("pop"), "t.sc:1:1: error: pop without matching push");
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1\n  push\npush\npop\n"),
            "t.sc:2:3: error: push without matching pop");
  EXPECT_EQ(
      sceneErrorsOf("push\npush\n"),
      "t.sc:1:1: error: push without matching pop\nt.sc:2:1: error: push without matching pop");
}

TEST(ParserErrors, EachCameraCommandAtMostOnce) {
  for (const char* command : {"eye 0 0 9", "lookat 0 0 1", "up 1 0 0", "fov 30", "resolution 10 10",
                              "background 0 0 0", "ambient 0 0 0"}) {
    SCOPED_TRACE(command);
    const std::string keyword = std::string(command).substr(0, std::string(command).find(' '));
    EXPECT_EQ(sceneErrorsOf(std::string(command) + "\nsphere 0 0 0 1\n " + command + "\n"),
              "t.sc:3:2: error: duplicate '" + keyword + "' (first given at t.sc:1:1)");
  }
}

TEST(ParserErrors, EyeEqualsLookat) {
  EXPECT_EQ(sceneErrorsOf("eye 1 2 3\nfov 30\nlookat 1 2 3"),
            "t.sc:3:1: error: eye and lookat are the same point, so there is no view direction");
  // Without lookat: at eye (the default lookat is the origin).
  EXPECT_EQ(sceneErrorsOf("fov 30\n eye 0 0 0"),
            "t.sc:2:2: error: eye and lookat are the same point, so there is no view direction");
  // Without eye: at lookat (the default eye is (0,0,5)).
  EXPECT_EQ(sceneErrorsOf("\n\n  lookat 0 0 5"),
            "t.sc:3:3: error: eye and lookat are the same point, so there is no view direction");
  // Distinct, but 1e-300 squared underflows, so no direction can be computed.
  EXPECT_EQ(sceneErrorsOf("eye 0 0 1e-300"),
            "t.sc:1:1: error: eye and lookat are too close together or too far apart to give a "
            "view direction");
}

TEST(ParserErrors, UpParallelToTheViewDirection) {
  EXPECT_EQ(sceneErrorsOf("eye 0 5 0\nup 0 2 0"),
            "t.sc:2:1: error: up is parallel to the view direction (from eye to lookat)");
  EXPECT_EQ(sceneErrorsOf("eye 0 5 0\nlookat 0 1 0\nup 0 -1 0"),
            "t.sc:3:1: error: up is parallel to the view direction (from eye to lookat)");
  // Without up, at where the view was written: lookat, else eye.
  EXPECT_EQ(sceneErrorsOf("eye 0 5 0\nlookat 0 1 0"),
            "t.sc:2:1: error: up is parallel to the view direction (from eye to lookat)");
  EXPECT_EQ(sceneErrorsOf("fov 30 eye 0 5 0"),
            "t.sc:1:8: error: up is parallel to the view direction (from eye to lookat)");
  EXPECT_EQ(sceneErrorsOf("up 0 0 0"), "t.sc:1:1: error: up must not be the zero vector");
  // Not parallel, but the cross product with the view direction underflows.
  EXPECT_EQ(sceneErrorsOf("up 1e-300 0 0"), "t.sc:1:1: error: up is too short to give a direction");
  // Nearly parallel is fine.
  EXPECT_EQ(parse("eye 0 5 0\nup 0 1 1e-6").camera.up, Vec3(0, 1, 1e-6));
}

TEST(ParserErrors, IncludeSyntax) {
  EXPECT_EQ(sceneErrorsOf("include # nothing"),
            "t.sc:1:1: error: include: expected PATH but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("include \"a.sc\nsphere 0 0 0 1"),
            "t.sc:1:9: error: include: PATH has no closing '\"' on its line");
  EXPECT_EQ(sceneErrorsOf("include \"\""), "t.sc:1:9: error: include: PATH is empty");
}

TEST(ParserErrors, RecoveryReportsEveryProblem) {
  const char* text = "sphere 0 0 0 -1\n"         // radius at column 14
                     "bogus 1 2 3\n"             // unknown; its numbers are skipped
                     "light 0 0 0 1 1\n"         // B missing: 'surface' found instead
                     "surface 1 1 1 1 0 0 1 0\n" // still parsed: IR at column 23
                     "sphere 1 2 x 4\n"          // x at column 12; x and 4 skipped
                     "sphere 0 0 0 1\n";         // fine
  EXPECT_EQ(sceneErrorsOf(text),
            "t.sc:1:14: error: sphere: negative radius '-1'\n"
            "t.sc:2:1: error: unknown keyword 'bogus'\n"
            "t.sc:4:1: error: light: expected B (a number) but found 'surface'\n"
            "t.sc:4:23: error: surface: IR must be positive, found '0'\n"
            "t.sc:5:12: error: sphere: expected Z (a number) but found 'x'");
}

TEST(ParserErrors, AtMostFiftyErrorsThenTooManyErrors) {
  std::string text;
  for (int i = 0; i < 80; ++i)
    text += "bogus\n";
  const auto d = diagnosticsOf(text);
  ASSERT_EQ(d.size(), 51u);
  EXPECT_EQ(d[49].format(), "t.sc:50:1: error: unknown keyword 'bogus'");
  EXPECT_EQ(d[50].format(), "t.sc:51:1: error: too many errors; giving up");
}

TEST(ParserErrors, ArbitraryBytesNeverCrash) {
  // Fragments of the language in random order plus random bytes: any outcome but a
  // crash, hang or stray exception is fine.
  const std::vector<std::string> pieces = {
      "sphere", "polygon", "push", "pop", "include", "surface", "light", "scale", "rotate",
      "eye",    "1",       "-1",   "0",   "1e999",   "nan",     "#",     "\n",    " ",
      "\"",     "3",       "1e-9", "1e9", "x",       "0x1p3",   "fov",   "up",    "99999999999"};
  std::mt19937 random(12345);
  for (int round = 0; round < 300; ++round) {
    std::string text;
    const int length = int(random() % 200);
    for (int i = 0; i < length; ++i) {
      if (random() % 8 == 0) {
        text += char(random() % 256);
      } else {
        text += pieces[random() % pieces.size()];
        text += ' ';
      }
    }
    try {
      // In a directory that does not exist, so that random includes read nothing.
      parseScene(text, "/nonexistent-prism-parser-test/t.sc");
    } catch (const SceneError& e) {
      EXPECT_FALSE(e.diagnostics().empty());
      EXPECT_LE(e.diagnostics().size(), 51u);
    }
  }
}

} // namespace
} // namespace prism
