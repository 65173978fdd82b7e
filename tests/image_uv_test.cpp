// Per-vertex surface coordinates of triangles and OBJ/MTL texture maps
// (issue 16): the .sc forms `triangle_uv` and `ptriangle_uv`, each uv staying
// with its vertex when a mirror, an inward mesh block or vertex normals turn
// a triangle over; OBJ `vt` on the right corners (quads split, negative
// indices, faces without); MTL `map_Kd` with its options, rendered over a
// 2x2 image whose texels are decoded from sRGB by hand; `prism convert`'s
// round trip; the errors. No expected value is the code's own output.
#include "core/accel/accel.h"
#include "core/io/image_io.h"
#include "core/io/obj_reader.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/renderer.h"
#include "core/scene/scene_builder.h"

#include "test_files.h"
#include "tests/obj_fixture.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

namespace prism {
namespace {

namespace fs = std::filesystem;

constexpr double kExact = 1e-12;

PrimitiveRef triangleRef(std::uint32_t index) { return {kindOf<Triangle>, index}; }

void expectUv(const Vec2& got, const Vec2& want, double tolerance = kExact) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
}

// The world position of corner k of triangle i.
Vec3 corner(const Scene& scene, std::uint32_t i, std::size_t k) {
  return scene.meshVertices[scene.shapes<Triangle>()[i].vertex[k]];
}

// --- .sc: triangle_uv and ptriangle_uv

TEST(TriangleUv, CoordinatesAtTheVerticesAndTheCentroid) {
  const Scene scene = parseScene(R"(
triangle_uv 0 0 0  0.1 0.2   2 0 0  0.7 0.3   0 3 0  0.4 0.9
ptriangle_uv 0 0 1  0 0 1  -1 2   2 0 1  0 0 2  3 -4   0 3 1  1 0 1  0.5 0.25
triangle 0 0 2  2 0 2  0 3 2
)",
                                 "t.sc");
  ASSERT_EQ(scene.shapes<Triangle>().size(), 3u);
  EXPECT_TRUE(scene.shapes<Triangle>()[1].smooth());
  const std::array<Vec2, 3> flat = {Vec2(0.1, 0.2), Vec2(0.7, 0.3), Vec2(0.4, 0.9)};
  const std::array<Vec2, 3> smooth = {Vec2(-1, 2), Vec2(3, -4), Vec2(0.5, 0.25)};
  const Vec3 at[3] = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0)};
  for (std::size_t k = 0; k < 3; ++k) {
    expectUv(scene.imageCoordinates(triangleRef(0), at[k]), flat[k]);
    expectUv(scene.imageCoordinates(triangleRef(1), at[k] + Vec3(0, 0, 1)), smooth[k]);
  }
  // The centroid (2/3, 1): the mean of the three.
  expectUv(scene.imageCoordinates(triangleRef(0), Vec3(2.0 / 3.0, 1.0, 0.0)),
           Vec2(1.2 / 3.0, 1.4 / 3.0));
  expectUv(scene.imageCoordinates(triangleRef(1), Vec3(2.0 / 3.0, 1.0, 1.0)),
           Vec2(2.5 / 3.0, -1.75 / 3.0));
  // A plain triangle keeps its barycentric coordinates: (1, 0) at its
  // second vertex, (0, 1) at its third.
  expectUv(scene.imageCoordinates(triangleRef(2), Vec3(2, 0, 2)), Vec2(1, 0));
  expectUv(scene.imageCoordinates(triangleRef(2), Vec3(0, 3, 2)), Vec2(0, 1));
  EXPECT_EQ(scene.triangleUvs.size(), 2u); // none stored for the last
}

// A mirror reverses the vertex order (so the triangle still faces the same
// way); each uv goes with its vertex.
TEST(TriangleUv, AMirrorKeepsEachUvWithItsVertex) {
  const Scene scene = parseScene(R"(
scale -1 1 1
triangle_uv 0 0 0  0.1 0.2   2 0 0  0.7 0.3   0 3 0  0.4 0.9
)",
                                 "t.sc");
  ASSERT_EQ(scene.shapes<Triangle>().size(), 1u);
  // Stored as (0,0,0), (0,3,0), (-2,0,0): the written order turned over.
  test::expectCloseTo(corner(scene, 0, 1), Vec3(0, 3, 0));
  test::expectCloseTo(corner(scene, 0, 2), Vec3(-2, 0, 0));
  expectUv(scene.imageCoordinates(triangleRef(0), Vec3(0, 0, 0)), Vec2(0.1, 0.2));
  expectUv(scene.imageCoordinates(triangleRef(0), Vec3(-2, 0, 0)), Vec2(0.7, 0.3));
  expectUv(scene.imageCoordinates(triangleRef(0), Vec3(0, 3, 0)), Vec2(0.4, 0.9));
}

// The surface coordinates the mesh tests give each vertex: distinct for the
// four corners of the tetrahedron.
Vec2 uvOfCorner(const Vec3& p) { return {0.5 * p.x + 0.25 * p.z, 0.5 * p.y + 0.125 * p.z}; }

// A mesh block wound inward is turned over at `end`: every triangle's
// second and third vertices swap, and their uvs with them.
TEST(TriangleUv, AnInwardMeshKeepsEachUvWithItsVertex) {
  // The tetrahedron of docs/scene-language.md, each triangle written the
  // other way round (inward), uv = uvOfCorner of each vertex.
  const Scene scene = parseScene(R"(
mesh
  triangle_uv 0 0 0  0 0      1 0 0  0.5 0    0 1 0  0 0.5
  triangle_uv 0 0 0  0 0      0 0 1  0.25 0.125  1 0 0  0.5 0
  ptriangle_uv 0 0 0  -1 -1 -1  0 0   0 1 0  0 1 0  0 0.5   0 0 1  0 0 1  0.25 0.125
  triangle_uv 1 0 0  0.5 0    0 0 1  0.25 0.125  0 1 0  0 0.5
end
)",
                                 "t.sc");
  ASSERT_EQ(scene.shapes<Triangle>().size(), 4u);
  ASSERT_EQ(scene.triangleUvs.size(), 4u);
  // Turned over: the first triangle now runs (0,0,0), (0,1,0), (1,0,0).
  test::expectCloseTo(corner(scene, 0, 1), Vec3(0, 1, 0));
  for (std::uint32_t i = 0; i < 4; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3 p = corner(scene, i, k);
      expectUv(scene.triangleUvs[i][k], uvOfCorner(p));
      expectUv(scene.imageCoordinates(triangleRef(i), p), uvOfCorner(p));
    }
  }
}

// SceneBuilder::meshTriangle reverses a triangle whose vertex normals all
// point against its winding; the uvs follow their vertices.
TEST(TriangleUv, AMeshTriangleTurnedOverByItsNormalsKeepsItsUvs) {
  Scene scene;
  SceneBuilder build(scene);
  scene.meshVertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  scene.meshNormals = {Vec3(0, 0, -1)}; // the winding says +z
  const std::array<std::uint32_t, 3> normals = {0, 0, 0};
  const std::array<Vec2, 3> uvs = {Vec2(0.25, 0.5), Vec2(0.75, 0.125), Vec2(0.375, 1.0)};
  const auto ref = build.meshTriangle({0, 1, 2}, &normals, 0, Origin{}, &uvs);
  ASSERT_TRUE(ref);
  const Triangle& t = scene.shapes<Triangle>()[0];
  EXPECT_EQ(t.vertex, (std::array<std::uint32_t, 3>{0, 2, 1})); // reversed
  const std::array<Vec2, 3> kept = {uvs[0], uvs[2], uvs[1]};
  EXPECT_EQ(scene.triangleUvs.at(0), kept);
  for (std::size_t k = 0; k < 3; ++k)
    expectUv(scene.imageCoordinates(*ref, scene.meshVertices[k]), uvs[k]);
}

TEST(TriangleUv, Errors) {
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0 0 0  1 0 0 1 0  0 1 0 0\n"),
            "t.sc:1:1: error: triangle_uv: expected V3 but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0 0 0  1 0 0 1 0  0 1 0 0\nsphere 0 0 0 1\n"),
            "t.sc:2:1: error: triangle_uv: expected V3 (a number) but found 'sphere'");
  // A triangle's 9 numbers are too few for triangle_uv: U1 is the fourth,
  // and the tenth is V2.
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0  1 0 0  0 1 0\n"),
            "t.sc:1:1: error: triangle_uv: expected V2 but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("ptriangle_uv 0 0 0  0 0 1  0 0\n"),
            "t.sc:1:1: error: ptriangle_uv: expected X2 but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0 0 nan  1 0 0 1 0  0 1 0 0 1\n"),
            "t.sc:1:21: error: triangle_uv: V1 is not a finite number ('nan')");
  // Zero normal: NX2 is the 12th number, at column 37.
  EXPECT_EQ(test::sceneErrorsOf("ptriangle_uv 0 0 0 0 0 1 0 0  1 0 0 0 0 0 1 0  0 1 0 0 0 1 0 1\n"),
            "t.sc:1:37: error: ptriangle_uv: N2 (NX2 NY2 NZ2) must not be the zero vector");
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0 0 0  0 0 0 1 0  0 1 0 0 1\n"),
            "t.sc:1:1: error: triangle_uv: degenerate triangle (zero area)");
  // Inside csg: an open shape outside a mesh block; inside one, no uv.
  EXPECT_EQ(test::sceneErrorsOf("csg union\n  sphere 0 0 0 1\n  triangle_uv 0 0 0 0 0  1 0 0 1 0  "
                                "0 1 0 0 1\nend\n"),
            "t.sc:3:3: error: triangle_uv: not a closed solid, so it cannot be an operand of csg "
            "(spheres, boxes, cylinders, capped cones, tori, blobs, meshes and csg blocks can)");
  EXPECT_EQ(test::sceneErrorsOf(R"(csg union
  sphere 0 0 0 1
  mesh
    triangle 0 0 0  0 1 0  1 0 0
    triangle 0 0 0  1 0 0  0 0 1
    triangle_uv 0 0 0 0 0  0 0 1 0 0  0 1 0 0 0
    triangle 1 0 0  0 1 0  0 0 1
  end
end
)"),
            "t.sc:6:5: error: triangle_uv: per-vertex uv is not supported in a mesh block inside "
            "csg (its triangles get their barycentric coordinates; use triangle or ptriangle "
            "there)");
  // The command after one with a missing number is read.
  EXPECT_EQ(test::sceneErrorsOf("triangle_uv 0 0 0 0 0  1 0 0 1\nsphere 0 0 0 -1\n"),
            "t.sc:2:1: error: triangle_uv: expected V2 (a number) but found 'sphere'\n"
            "t.sc:2:14: error: sphere: negative radius '-1'");
}

// --- OBJ vt and MTL map_Kd

class ObjUv : public test::ObjFiles {
protected:
  // A 2x2 PNG: top row red (255, 0, 0) and green (0, 128, 0); bottom row
  // blue (0, 0, 64) and (255, 128, 64).
  fs::path writeTexture(const std::string& name) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    writeImage8(path, 2, 2, {255, 0, 0, 0, 128, 0, 0, 0, 64, 255, 128, 64});
    return path;
  }
};

// The sRGB decoding of an 8-bit value, written out.
double decoded(int code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

TEST_F(ObjUv, TexCoordsGoToTheirCorners) {
  const Scene scene = loadObj(write("t.obj", R"(v 0 0 0
v 2 0 0
v 2 1 0
v 0 1 0
vt 0.125 0.25
vt 0.875 0.25
vt 0.875 0.75
vt 0.125 0.75 0
vn 0 0 -1
# a quad, split in two
f 1/1 2/2 3/3 4/4
# wound +z, its normals -z: turned over, each vt staying with its corner
f 1/4/1 2/3/1 3/2/1
# a corner without vt: barycentric
f 1/1 2 4
# negative indices: v1 v2 v3 with vt4 vt3 vt2
f -4/-1 -3/-2 -2/-3
)"));
  ASSERT_EQ(scene.shapes<Triangle>().size(), 5u);
  ASSERT_EQ(scene.triangleUvs.size(), 5u);
  // The quad's vt by vertex position.
  const auto quadUv = [](const Vec3& p) { return Vec2(0.125 + 0.375 * p.x, 0.25 + 0.5 * p.y); };
  for (std::uint32_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3 p = corner(scene, i, k);
      expectUv(scene.imageCoordinates(triangleRef(i), p), quadUv(p));
    }
  }
  // Turned over: (0,0,0), (2,1,0), (2,0,0).
  test::expectCloseTo(corner(scene, 2, 1), Vec3(2, 1, 0));
  const Vec2 reversedUv[3] = {Vec2(0.125, 0.75), Vec2(0.875, 0.25), Vec2(0.875, 0.75)};
  for (std::size_t k = 0; k < 3; ++k) {
    expectUv(scene.triangleUvs[2][k], reversedUv[k]);
    expectUv(scene.imageCoordinates(triangleRef(2), corner(scene, 2, k)), reversedUv[k]);
  }
  const std::array<Vec2, 3> barycentric = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_EQ(scene.triangleUvs[3], barycentric);
  expectUv(scene.imageCoordinates(triangleRef(3), Vec3(2, 0, 0)), Vec2(1, 0));
  const std::array<Vec2, 3> negative = {Vec2(0.125, 0.75), Vec2(0.875, 0.75), Vec2(0.875, 0.25)};
  EXPECT_EQ(scene.triangleUvs[4], negative);
}

TEST_F(ObjUv, MapKdLoadsWithItsOptions) {
  const fs::path texture = writeTexture("maps/tex.png");
  write("t.mtl", R"(newmtl plain
Kd 0.5 0.5 0.5
newmtl scaled
Kd 1 0.5 0.25
map_Kd -s 2 3 -o 0.5 0.25 -clamp on -bm 1 -imfchan r maps/tex.png
newmtl once
map_Kd -s 2 -o 0.5 maps/../maps/tex.png
newmtl unused
map_Kd missing.png
)");
  const Scene scene = loadObj(write("t.obj", R"(mtllib t.mtl
v 0 0 0
v 1 0 0
v 0 1 0
usemtl plain
f 1 2 3
usemtl scaled
f 1 2 3
usemtl once
f 1 2 3
)"));
  ASSERT_EQ(scene.shapes<Triangle>().size(), 3u);
  const Material& plain = scene.materials[scene.shapes<Triangle>()[0].material];
  const Material& scaled = scene.materials[scene.shapes<Triangle>()[1].material];
  const Material& once = scene.materials[scene.shapes<Triangle>()[2].material];
  EXPECT_FALSE(plain.image.active());
  ASSERT_TRUE(scaled.image.active());
  ASSERT_TRUE(once.image.active());
  EXPECT_EQ(scaled.color, Color(1, 0.5, 0.25)); // Kd multiplies the map
  EXPECT_EQ(scaled.image.scale, Vec2(2, 3));
  EXPECT_EQ(scaled.image.offset, Vec2(0.5, 0.25));
  EXPECT_EQ(scaled.image.wrap, ImageWrap::Clamp);
  EXPECT_EQ(once.image.scale, Vec2(2, 1)); // V of -s defaults to 1, of -o to 0
  EXPECT_EQ(once.image.offset, Vec2(0.5, 0));
  EXPECT_EQ(once.image.wrap, ImageWrap::Repeat);
  // One image, read once, relative to the MTL file.
  ASSERT_TRUE(scene.images);
  EXPECT_EQ(scene.images->size(), 1u);
  EXPECT_EQ(scaled.image.image, once.image.image);
  EXPECT_EQ(fs::path(scene.images->info(scaled.image.image).path), fs::absolute(texture));
  EXPECT_EQ(scene.images->info(0).width, 2);
  // The brightest texel per channel: 255, 128 and 64 coded.
  EXPECT_NEAR(scaled.image.peak.r, 1.0, 1e-6);
  EXPECT_NEAR(scaled.image.peak.g, decoded(128), 1e-6);
  EXPECT_NEAR(scaled.image.peak.b, decoded(64), 1e-6);
  // A file that is not an image: OpenImageIO's reason follows. (Here, where
  // the module is loaded already: the other errors are found before it is.)
  write("notes.png", "not a picture");
  EXPECT_EQ(errorsOf("mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
                     "newmtl m\nmap_Kd notes.png\n")
                .rfind("DIR/t.mtl:2:8: error: map_Kd: cannot read 'DIR/notes.png': ", 0),
            0u);
}

// A unit quad with vt over the whole image, seen straight on by a camera
// that frames it exactly, lit by ambient 1 alone: the radiance is
// C_mat kdr Ia = the texel's linear colour. 10 x 10 pixels put the centres
// of pixels 2 and 7 at x, y = -0.5 and 0.5: the texel centres.
TEST_F(ObjUv, AMapKdQuadRendersItsTexels) {
  writeTexture("tex.png");
  write("t.mtl", R"(newmtl textured
Kd 1 1 1
Ks 0 0 0
illum 1
map_Kd tex.png
)");
  Scene scene = loadObj(write("t.obj", R"(mtllib t.mtl
v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl textured
f 1/1 2/2 3/3 4/4
)"));
  scene.lights.clear();
  scene.ambient = Color(1.0);
  scene.background = Color(0.0);
  scene.camera = CameraSpec{Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(0, 1, 0), 90.0};
  RenderSettings settings;
  settings.width = settings.height = 10;
  settings.noAa = true;
  settings.threads = 1;
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  const RenderResult result = render(scene, *accel, settings);
  const auto pixel = [&](int x, int y) { return result.film.radiance[result.film.index(x, y)]; };
  const auto expectTexel = [&](int x, int y, double r, double g, double b) {
    const Rgb got = pixel(x, y);
    EXPECT_NEAR(got.r, r, 1e-5) << x << ", " << y;
    EXPECT_NEAR(got.g, g, 1e-5) << x << ", " << y;
    EXPECT_NEAR(got.b, b, 1e-5) << x << ", " << y;
  };
  // The image's top row at the top of the picture (v runs up).
  expectTexel(2, 2, 1.0, 0.0, 0.0);
  expectTexel(7, 2, 0.0, decoded(128), 0.0);
  expectTexel(2, 7, 0.0, 0.0, decoded(64));
  expectTexel(7, 7, 1.0, decoded(128), decoded(64));
  // 128 coded is 0.2158605 in light, not 0.502.
  EXPECT_NEAR(decoded(128), 0.2158605, 1e-6);
}

// Files written on Windows name folders with backslashes; they are found
// with slashes where the name as written does not exist, and a name that
// really holds a backslash is kept.
TEST_F(ObjUv, BackslashesSeparateFoldersOnlyWhereThatFindsTheFile) {
  const fs::path texture = writeTexture("maps/tex.png");
  write("mtl/t.mtl", "newmtl m\nKd 1 1 1\nmap_Kd ..\\maps\\tex.png\n");
  const std::string faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n";
  const Scene scene = loadObj(write("t.obj", "mtllib mtl\\t.mtl\n" + faces));
  ASSERT_EQ(scene.shapes<Triangle>().size(), 1u);
  ASSERT_TRUE(scene.images);
  EXPECT_EQ(fs::path(scene.images->info(0).path), fs::absolute(texture));

  // A file whose name holds the backslash, next to the folder it could mean.
  const fs::path literal = writeTexture("maps\\tex.png");
  ASSERT_EQ(literal.filename().string(), "maps\\tex.png");
  write("u.mtl", "newmtl m\nKd 1 1 1\nmap_Kd maps\\tex.png\n");
  const Scene kept = loadObj(write("u.obj", "mtllib u.mtl\n" + faces));
  ASSERT_TRUE(kept.images);
  EXPECT_EQ(fs::path(kept.images->info(0).path), fs::absolute(literal));

  // Neither exists: the message quotes the name as written.
  EXPECT_EQ(errorsOf("mtllib t.mtl\n" + faces, "newmtl m\nmap_Kd no\\such.png\n"),
            "DIR/t.mtl:2:8: error: map_Kd: cannot read 'DIR/no\\such.png': no such file");
}

TEST_F(ObjUv, Errors) {
  const std::string obj = "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n";
  EXPECT_EQ(errorsOf(obj, "newmtl m\nKd 1 1 1\nmap_Kd -s 2 2 missing.png\n"),
            "DIR/t.mtl:3:15: error: map_Kd: cannot read 'DIR/missing.png': no such file");
  write("folder/x", "");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd folder\n"),
            "DIR/t.mtl:2:8: error: map_Kd: cannot read 'DIR/folder': not a regular file");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd -zoom 2 tex.png\n"),
            "DIR/t.mtl:2:8: error: map_Kd: unknown option '-zoom'");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd -s 0 1 tex.png\n"),
            "DIR/t.mtl:2:11: error: map_Kd: -s U must not be 0");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd -clamp maybe tex.png\n"),
            "DIR/t.mtl:2:15: error: map_Kd: -clamp expects on or off, found 'maybe'");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd -o\n"),
            "DIR/t.mtl:2:8: error: map_Kd -o: expected U (a number) at the end of the line");
  EXPECT_EQ(errorsOf(obj, "newmtl m\nmap_Kd -clamp on\n"),
            "DIR/t.mtl:2:1: error: map_Kd: expected a FILE");
  EXPECT_EQ(errorsOf("v 0 0 0\nvt 0.5 x\n"),
            "DIR/t.obj:2:8: error: vt: expected V (a number) but found 'x'");
  EXPECT_EQ(errorsOf("vt\n"), "DIR/t.obj:1:1: error: vt: expected U (a number) at the end of "
                              "the line");
  EXPECT_EQ(errorsOf("vt 0 0 0 0\n"),
            "DIR/t.obj:1:10: error: vt: unexpected '0' after the statement's arguments");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n"),
            "DIR/t.obj:5:11: error: f: texture coordinate index '2' is out of range (1 'vt' "
            "statements before this face)");
}

// --- prism convert

// A scene with every way to give uv, an image over it, and a plain triangle
// last; all in one group, so the writer keeps the triangles' order.
constexpr const char* kUvScene = R"(resolution 24 24
eye 0 0 4
lookat 0 0 0
up 0 1 0
fov 60
ambient 1 1 1
light 2 3 4  0.5 0.5 0.5
surface 1 1 1  1 0 0  1 1
image tex.png
triangle_uv -1 -1 0  0 0   1 -1 0  1 0   1 1 0  1 1
mesh
  triangle_uv 0 0 0  0 0      0.5 0 0  1 0   0 0.5 0  0 1
  triangle_uv 0 0 0  0 0      0 0 0.5  0.5 0.5  0.5 0 0  1 0
  ptriangle_uv 0 0 0  -1 -1 -1  0 0   0 0.5 0  0 1 0  0 1   0 0 0.5  0 0 1  0.5 0.5
  triangle_uv 0.5 0 0  1 0    0 0 0.5  0.5 0.5   0 0.5 0  0 1
end
image tex.png clamp
uv 2 2  0.25 0
scale -1 1 1
ptriangle_uv 1 -1 -0.5  0 0 1  0 0.25   -1 -1 -0.5  0 0 1  1 0.25   0 1 -0.5  0 0 2  0.5 1
triangle -1.5 -1.5 -1  1.5 -1.5 -1  0 1.5 -1
)";

TEST_F(ObjUv, ConvertRoundTripsTheUvs) {
  writeTexture("tex.png");
  const Scene scene = parseScene(kUvScene, (dir_ / "s.sc").string());
  ASSERT_EQ(scene.shapes<Triangle>().size(), 7u);
  ASSERT_EQ(scene.triangleUvs.size(), 6u);
  std::ostringstream text;
  writeScene(text, scene);
  const std::string written = text.str();
  EXPECT_NE(written.find("\ntriangle_uv "), std::string::npos) << written;
  EXPECT_NE(written.find("\nptriangle_uv "), std::string::npos) << written;
  // The last, plain triangle mirrored too: x negated, vertices 2 and 3
  // swapped.
  EXPECT_NE(written.find("\ntriangle  1.5 -1.5 -1  0 1.5 -1  -1.5 -1.5 -1\n"), std::string::npos)
      << written;
  // Read back elsewhere: the image's path was written absolute.
  const Scene again = parseScene(written, (dir_ / "elsewhere" / "again.sc").string());
  EXPECT_EQ(again.triangleUvs, scene.triangleUvs) << written;
  EXPECT_EQ(again.meshVertices, scene.meshVertices);
  EXPECT_EQ(again.materials, scene.materials);
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.threads = 2;
  const RenderResult a = render(scene, *makeAccel(scene, AccelKind::Bvh), settings);
  const RenderResult b = render(again, *makeAccel(again, AccelKind::Bvh), settings);
  ASSERT_EQ(a.film.radiance.size(), b.film.radiance.size());
  EXPECT_TRUE(a.film.radiance == b.film.radiance);
  EXPECT_EQ(again.meshNormals, scene.meshNormals);
  // The picture has the image in it: the triangle_uv half of the quad is
  // orange at the bottom (uv 0.84, 0.26) and green at the top (0.84, 0.74).
  const Rgb bottom = a.film.radiance[a.film.index(15, 14)];
  const Rgb top = a.film.radiance[a.film.index(15, 9)];
  // (mostly the texels (255, 128, 64) and (0, 128, 0), with a fifth of
  // their left neighbours (0, 0, 64) and (255, 0, 0)).
  EXPECT_GT(bottom.r, 2.0f * top.r);
  EXPECT_GT(bottom.b, 10.0f * top.b);
}

// POV-Ray gets neither the image nor the uvs, and says so.
TEST_F(ObjUv, PovRayOutputSaysWhatIsNotConverted) {
  writeTexture("tex.png");
  std::ostringstream out;
  writePov(out, parseScene(kUvScene, (dir_ / "s.sc").string()));
  const std::string text = out.str();
  EXPECT_NE(text.find("// the triangles' per-vertex uv (triangle_uv) are not converted"),
            std::string::npos);
  EXPECT_NE(text.find("// Prism_M0 has the image texture " + (dir_ / "tex.png").string() +
                      ", which is not converted"),
            std::string::npos)
      << text;
  std::ostringstream plain;
  writePov(plain, parseScene("triangle 0 0 0  1 0 0  0 1 0\n", "p.sc"));
  EXPECT_EQ(plain.str().find("not converted"), std::string::npos);
}

} // namespace
} // namespace prism
