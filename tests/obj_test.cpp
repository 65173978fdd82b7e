// OBJ/MTL import: faces (triangles, quads, concave polygons, negative
// indices, with and without normals), the MTL mapping onto Prism's material,
// groups, face lines, the default camera and lights, every error with its
// file, line and column, and hostile input (issue 10).
#include "core/accel/accel.h"
#include "core/io/obj_reader.h"
#include "core/render/tracer.h"

#include "test_files.h"
#include "tests/obj_fixture.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace prism {
namespace {

namespace fs = std::filesystem;

using Obj = test::ObjFiles;

// Every index a triangle holds is one the renderer follows without checking.
void expectIndicesInBounds(const Scene& s) {
  for (const Triangle& t : s.shapes<Triangle>()) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_LT(t.vertex[c], s.meshVertices.size());
      if (t.smooth()) {
        EXPECT_LT(t.normal[c], s.meshNormals.size());
      }
    }
    EXPECT_LT(t.material, s.materials.size());
  }
}

constexpr const char* kMtl = R"(# materials
newmtl red
Kd 0.8 0.1 0.1
Ks 0.3 0.6 0.9
Ns 50
illum 2
newmtl glass
Kd 0.1 0.2 0.3
Ks 1 1 1
Ns 200
Ni 1.5
d 0.25
illum 7
newmtl matte
Kd 0.5 0.5 0.5
Ks 1 1 1
illum 1
newmtl tr
Kd 1 1 1
Tr 0.75
)";

constexpr const char* kObj = R"(# a small mesh
mtllib t.mtl
o first
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 1
vt 0 0
usemtl red
f 1//1 2//1 3//1
f -4 -2 -1
g second
usemtl glass
v 0 0 1
v 2 0 1
v 2 1 1
v 0 1 1
vn 0 0 2
f 5/1/2 6/1/2 7/1/2 8/1/2
usemtl matte
v 0 0 2
v 2 0 2
v 2 1 2
v 1 0.5 2
v 0 1 2
f 9 10 11 12 13
usemtl tr
f 1 2 4
)";

using test::expectCloseTo;

TEST_F(Obj, FacesBecomeTriangles) {
  write("t.mtl", kMtl);
  const Scene s = loadObj(write("t.obj", kObj));
  // 1 + 1 triangles, a quad in 2, a concave pentagon in 3, one more.
  ASSERT_EQ(s.shapes<Triangle>().size(), 8u);
  expectIndicesInBounds(s);
  EXPECT_EQ(s.primitiveCount(), 8u);
  const Vec3* v = s.meshVertices.data();
  // f 1//1 2//1 3//1: smooth, its normal given.
  EXPECT_TRUE(s.shapes<Triangle>()[0].smooth());
  expectCloseTo(s.meshNormals[s.shapes<Triangle>()[0].normal[0]], {0, 0, 1});
  EXPECT_EQ(s.shapes<Triangle>()[0].origin.line, 11u);
  // f -4 -2 -1 counts back from the 4 vertices so far: 1 3 4; flat.
  EXPECT_FALSE(s.shapes<Triangle>()[1].smooth());
  expectCloseTo(v[s.shapes<Triangle>()[1].vertex[0]], {0, 0, 0});
  expectCloseTo(v[s.shapes<Triangle>()[1].vertex[1]], {1, 1, 0});
  expectCloseTo(v[s.shapes<Triangle>()[1].vertex[2]], {0, 1, 0});
  EXPECT_EQ(s.shapes<Triangle>()[1].origin.line, 12u);
  // The quad: two smooth triangles, normals normalised.
  for (int i : {2, 3}) {
    EXPECT_TRUE(s.shapes<Triangle>()[i].smooth());
    EXPECT_EQ(s.shapes<Triangle>()[i].origin.line, 20u);
    expectCloseTo(s.meshNormals[s.shapes<Triangle>()[i].normal[2]], {0, 0, 1});
  }
  // The concave pentagon: 3 triangles covering its area 2 - 0.5, all facing +z.
  double area = 0.0;
  for (int i : {4, 5, 6}) {
    const Triangle& t = s.shapes<Triangle>()[i];
    const Vec3 n = glm::cross(v[t.vertex[1]] - v[t.vertex[0]], v[t.vertex[2]] - v[t.vertex[0]]);
    EXPECT_GT(n.z, 0.0);
    area += 0.5 * glm::length(n);
    EXPECT_EQ(t.origin.line, 27u);
  }
  EXPECT_NEAR(area, 1.5, 1e-12);
  // One group per OBJ object or group, under the top level.
  EXPECT_GE(s.groups.size(), 3u);
  EXPECT_EQ(s.files[0], (dir_ / "t.obj").string());
}

TEST_F(Obj, MtlMapsOntoPrismMaterials) {
  write("t.mtl", kMtl);
  const Scene s = loadObj(write("t.obj", kObj));
  const Material& red = s.material({kindOf<Triangle>, 0});
  EXPECT_EQ(red.color, Color(0.8, 0.1, 0.1));
  EXPECT_EQ(red.kdr, 1.0);
  EXPECT_NEAR(red.ksr, 0.6, 1e-15); // mean of Ks
  EXPECT_EQ(red.kst, 0.0);
  EXPECT_EQ(red.e, 50.0);
  EXPECT_EQ(red.ir, 1.0);
  const Material& glass = s.material({kindOf<Triangle>, 2});
  EXPECT_EQ(glass.kdr, 0.25); // d
  EXPECT_EQ(glass.kst, 0.75); // 1 - d
  EXPECT_EQ(glass.ksr, 1.0);
  EXPECT_EQ(glass.e, 200.0);
  EXPECT_EQ(glass.ir, 1.5);
  const Material& matte = s.material({kindOf<Triangle>, 4});
  EXPECT_EQ(matte.ksr, 0.0); // illum 1: no highlight, no mirror
  // Tr 0.75 is d 0.25; no illum given: model 2 (but Ks is 0 here).
  const Material& tr = s.material({kindOf<Triangle>, 7});
  // (tinyobjloader's own number parser is not always correctly rounded.)
  EXPECT_NEAR(tr.kdr, 0.25, 1e-15);
  EXPECT_NEAR(tr.kst, 0.75, 1e-15);
}

TEST(ObjMaterial, Mapping) {
  MtlValues v;
  v.kd = Color(0.5, 0.25, 1);
  v.ks = Color(0.3, 0.3, 0.9);
  v.ns = 10;
  v.ni = 0; // not positive: air
  v.dissolve = 0.5;
  v.illum = 2;
  const Material m = materialFromMtl(v);
  EXPECT_EQ(m.color, v.kd);
  EXPECT_EQ(m.kdr, 0.5);
  EXPECT_NEAR(m.ksr, 0.5, 1e-15);
  EXPECT_EQ(m.kst, 0.5);
  EXPECT_EQ(m.e, 10.0);
  EXPECT_EQ(m.ir, 1.0);
  v.illum = 0;
  EXPECT_EQ(materialFromMtl(v).ksr, 0.0);
}

TEST_F(Obj, DefaultCameraAndLights) {
  const Scene s = loadObj(write("t.obj", "v -1 -2 -3\nv 3 2 -3\nv 3 2 1\nf 1 2 3\n"));
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  // Looks at the box's centre along -z, from far enough to see it whole.
  expectCloseTo(s.camera.lookat, {1, 0, -1});
  const double radius = 0.5 * std::sqrt(16.0 + 16.0 + 16.0);
  expectCloseTo(s.camera.eye, {1, 0, -1 + 1.1 * radius / std::sin(glm::radians(22.5))}, 1e-9);
  ASSERT_EQ(s.lights.size(), 2u);
  // Ten radii away, compensated to deliver 1 (key) and 0.35 (fill) there.
  const double d = 10.0 * radius;
  expectCloseTo(s.lights[0].intensity, Color(d * d), 1e-6);
  expectCloseTo(s.lights[1].intensity, Color(0.35 * d * d), 1e-6);
  EXPECT_NEAR(glm::length(s.lights[0].position - s.camera.lookat), d, 1e-9);
  EXPECT_EQ(s.ambient, Color(0.1));
  EXPECT_EQ(s.background, Color(0.4));
  // Without materials: light grey, diffuse only.
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].color, Color(0.8));
  EXPECT_EQ(s.materials[0].ksr, 0.0);
}

// A flat square facing the camera, its centre where the camera looks: each
// default light is 10 bounding radii from that point and compensated to
// deliver its nominal intensity there, so the radiance is
// C kdr (ambient + 1 N.L_key + 0.35 N.L_fill) with C = 0.8, kdr = 1.
TEST_F(Obj, TracesToHandComputedRadiance) {
  const Scene s = loadObj(write("t.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n"));
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  const Color c =
      tracer.trace(Ray{s.camera.eye, glm::normalize(s.camera.lookat - s.camera.eye)}, 1, counts);
  const double key = 4.0 / std::sqrt(29.0), fill = 2.0 / std::sqrt(14.0);
  EXPECT_NEAR(c.r, 0.8 * (0.1 + key + 0.35 * fill), 1e-12);
  EXPECT_EQ(counts.shadow, 2u);
}

TEST_F(Obj, NormalsAgainstTheWindingWin) {
  // Wound clockwise seen from +z, but the normals say +z is outside.
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv 0 1 0\nv 1 0 0\nvn 0 0 1\n"
                                         "f 1//1 2//1 3//1\n"));
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  expectCloseTo(geometricNormal(s.shapes<Triangle>()[0], s.meshVertices.data()), {0, 0, 1});
}

TEST_F(Obj, ZeroNormalsMakeAFlatFaceAndZeroAreaFacesAreDropped) {
  std::vector<Diagnostic> warnings;
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nvn 0 0 0\n"
                                         "f 1//1 2//1 3//1\nf 1 2 4\n"),
                          &warnings);
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  EXPECT_FALSE(s.shapes<Triangle>()[0].smooth());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message, "1 zero-area triangle was dropped");
}

// A face whose edges cross cannot be tiled by triangles; it was triangulated
// silently. Now it still is (best effort, never beyond its vertices), with a
// warning that counts such faces.
TEST_F(Obj, FacesThatAreNotSimplePolygonsAreReported) {
  std::vector<Diagnostic> warnings;
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                         "f 1 2 3 4\nf 1 3 4 2\nf 1 5 2\n"),
                          &warnings);
  expectIndicesInBounds(s);
  EXPECT_EQ(s.shapes<Triangle>().size(), 5u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message, "2 faces are not simple polygons (edges cross or touch, or a "
                                 "vertex repeats): their triangles are a best effort");
}

TEST_F(Obj, Errors) {
  EXPECT_EQ(errorsOf("v 1 2 x\n"), "DIR/t.obj:1:7: error: v: expected Z (a number) but found 'x'");
  EXPECT_EQ(errorsOf("v 1 2\n"),
            "DIR/t.obj:1:1: error: v: expected Z (a number) at the end of the line");
  EXPECT_EQ(errorsOf("v 1 2 inf\n"), "DIR/t.obj:1:7: error: v: Z is not a finite number ('inf')");
  EXPECT_EQ(errorsOf("vn 1 2 3 4\n"),
            "DIR/t.obj:1:10: error: vn: unexpected '4' after the statement's arguments");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
            "DIR/t.obj:4:7: error: f: vertex index '9' is out of range (3 'v' statements before "
            "this face)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"),
            "DIR/t.obj:4:7: error: f: vertex index '-4' is out of range (3 'v' statements before "
            "this face)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n"),
            "DIR/t.obj:4:3: error: f: normal index '1' is out of range (0 'vn' statements before "
            "this face)\n"
            "DIR/t.obj:4:8: error: f: normal index '1' is out of range (0 'vn' statements before "
            "this face)\n"
            "DIR/t.obj:4:13: error: f: normal index '1' is out of range (0 'vn' statements before "
            "this face)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nf 1 2\n"),
            "DIR/t.obj:3:1: error: f: a face needs at least 3 vertices, found 2");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
            "DIR/t.obj:4:3: error: f: vertex index 0 (indices count from 1)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 2\n"),
            "DIR/t.obj:4:5: error: f: expected a vertex index (an integer) but found 'a'");
  EXPECT_EQ(errorsOf("vv 1 2 3\n"), "DIR/t.obj:1:1: error: unknown statement 'vv'");
  EXPECT_EQ(errorsOf("mtllib nope.mtl\n"),
            "DIR/t.obj:1:8: error: mtllib: cannot read 'DIR/nope.mtl': No such file or "
            "directory");
  EXPECT_EQ(errorsOf("usemtl zzz\n"),
            "DIR/t.obj:1:8: error: usemtl: no material 'zzz' (no 'mtllib' was given)");
  EXPECT_EQ(errorsOf("mtllib t.mtl\nusemtl zzz\n", "newmtl a\n"),
            "DIR/t.obj:2:8: error: usemtl: no material 'zzz' in the material libraries");
}

TEST_F(Obj, MtlErrorsNameTheMaterialFile) {
  const std::string obj = "mtllib t.mtl\n";
  EXPECT_EQ(errorsOf(obj, "newmtl a\nKd 1 -1 0\n"),
            "DIR/t.mtl:2:6: error: Kd: G must not be negative, found '-1'");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nKd 1 1\n"),
            "DIR/t.mtl:2:1: error: Kd: expected B (a number) at the end of the line");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nKs spectral x.rfl\n"),
            "DIR/t.mtl:2:4: error: Ks: only R G B colours are supported, found 'spectral'");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nNi 0\n"),
            "DIR/t.mtl:2:4: error: Ni: the index of refraction must be positive, found '0'");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nd 2\n"),
            "DIR/t.mtl:2:3: error: d: must be from 0 to 1, found '2'");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nNs -1\n"),
            "DIR/t.mtl:2:4: error: Ns: the exponent must not be negative, found '-1'");
  EXPECT_EQ(errorsOf(obj, "newmtl a\nillum 12\n"),
            "DIR/t.mtl:2:7: error: illum: expected an illumination model from 0 to 10, found "
            "'12'");
}

TEST_F(Obj, UnreadableFile) {
  try {
    loadObj(dir_ / "missing.obj");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir_ / "missing.obj").string() +
                  ":1:1: error: cannot read file: No such file or directory");
  }
}

// ---------------------------------------------------------------------------
// Hostile input (issue 10): the scan and tinyobjloader must read the same
// statements, and nothing that loads may send the renderer out of bounds.

// The triangle's vertices, in its order.
std::array<Vec3, 3> cornersOf(const Scene& s, std::size_t triangle) {
  const Triangle& t = s.shapes<Triangle>().at(triangle);
  return {s.meshVertices.at(t.vertex[0]), s.meshVertices.at(t.vertex[1]),
          s.meshVertices.at(t.vertex[2])};
}

// The unit triangle (0 0 z) (1 0 z) (0 1 z) as the triangle `triangle` of `s`.
void expectUnitTriangle(const Scene& s, std::size_t triangle, double z = 0.0) {
  const std::array<Vec3, 3> v = cornersOf(s, triangle);
  expectCloseTo(v[0], {0, 0, z});
  expectCloseTo(v[1], {1, 0, z});
  expectCloseTo(v[2], {0, 1, z});
}

constexpr const char* kUnitTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST_F(Obj, FormFeedAndVerticalTabAreWhiteSpace) {
  // tinyobjloader alone splits words at ' ' and '\t' only: "vn\f0 0 1" was no
  // normal to it, and the face's validated normal index read past the end.
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv\v1 0 0\nv 0 1\f0\nvn\f0 0 1\n"
                                         "f\f1//1 2//1\v3//1\n"));
  expectIndicesInBounds(s);
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  ASSERT_EQ(s.meshNormals.size(), 1u);
  EXPECT_TRUE(s.shapes<Triangle>()[0].smooth());
  expectCloseTo(s.meshNormals[0], {0, 0, 1});
  expectUnitTriangle(s, 0);
}

TEST_F(Obj, CarriageReturnsEndLinesAsTinyobjloaderEndsThem) {
  // "\r", "\n" and "\r\n" each end a line (an empty one between "\r\r").
  const Scene s = loadObj(write("t.obj", "v 0 0 0\rv 1 0 0\r\nv 0 1 0\r\rf 1 2 3\r"));
  expectIndicesInBounds(s);
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  expectUnitTriangle(s, 0);
  EXPECT_EQ(s.shapes<Triangle>()[0].origin.line, 5u);
  EXPECT_EQ(errorsOf("v 0 0 0\rv 1 x 0\r"),
            "DIR/t.obj:2:5: error: v: expected Y (a number) but found 'x'");
}

TEST_F(Obj, AByteOrderMarkHidesNoVertex) {
  // tinyobjloader alone took "\xEF\xBB\xBFv" for an unknown statement and
  // lost the first vertex: -3 then read before its vertex array, 3 after it.
  const std::string bom = "\xEF\xBB\xBF";
  for (const char* face : {"f -3 -2 -1\n", "f 1 2 3\n"}) {
    SCOPED_TRACE(face);
    const Scene s = loadObj(write("t.obj", bom + kUnitTriangle + face));
    expectIndicesInBounds(s);
    ASSERT_EQ(s.meshVertices.size(), 3u);
    ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
    expectUnitTriangle(s, 0);
  }
  // Columns count after the mark.
  EXPECT_EQ(errorsOf(bom + "v 0 0 x\n"),
            "DIR/t.obj:1:7: error: v: expected Z (a number) but found 'x'");
}

// The vertices of a polygon of n corners at height z, counter-clockwise seen
// from +z: convex, a regular n-gon of radius 1; concave, a "pac-man", its
// centre (the reflex corner, first so that even a fan from corner 0 covers it
// right) then n - 1 points on an arc of 300 degrees.
std::string polygonVertices(int n, bool concave, double z) {
  std::ostringstream out;
  out.precision(17);
  if (concave) out << "v 0 0 " << z << "\n";
  const int onArc = concave ? n - 1 : n;
  const double span = concave ? glm::radians(300.0) / (n - 2) : glm::radians(360.0) / n;
  for (int i = 0; i < onArc; ++i)
    out << "v " << std::cos(i * span) << " " << std::sin(i * span) << " " << z << "\n";
  return out.str();
}

double polygonArea(int n, bool concave) {
  return concave ? 0.5 * (n - 2) * std::sin(glm::radians(300.0) / (n - 2))
                 : 0.5 * n * std::sin(glm::radians(360.0) / n);
}

std::string faceOf(int first, int n) {
  std::string f = "f";
  for (int i = 0; i < n; ++i)
    f += " " + std::to_string(first + i);
  return f + "\n";
}

// Triangles [first, first + n - 2) cover the polygon of vertices [vertex,
// vertex + n) at height z: only its vertices, facing +z, its whole area.
void expectPolygon(const Scene& s, std::size_t first, std::uint32_t vertex, int n, bool concave,
                   double z, std::uint32_t line) {
  double area = 0.0;
  for (std::size_t t = first; t < first + std::size_t(n) - 2; ++t) {
    for (const std::uint32_t v : s.shapes<Triangle>()[t].vertex) {
      EXPECT_GE(v, vertex);
      EXPECT_LT(v, vertex + std::uint32_t(n));
    }
    const std::array<Vec3, 3> p = cornersOf(s, t);
    const Vec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    EXPECT_GT(normal.z, 0.0);
    EXPECT_EQ(p[0].z, z);
    area += 0.5 * glm::length(normal);
    EXPECT_EQ(s.shapes<Triangle>()[t].origin.line, line);
  }
  EXPECT_NEAR(area, polygonArea(n, concave), 1e-9);
}

TEST_F(Obj, FacesOf256AndMoreVerticesKeepEveryVertex) {
  // tinyobjloader counts a face's vertices in 8 bits: 256 read as 0 (the face
  // vanished), 300 as 44 (a sliver), and every later face was built from the
  // wrong vertices.
  for (const int n : {255, 256, 257, 300}) {
    SCOPED_TRACE(n);
    // A convex face at z 0, a triangle at z 1, a concave face at z 2, a
    // triangle at z 3, each face after its vertices.
    const std::string text = polygonVertices(n, false, 0) + faceOf(1, n) +
                             "v 0 0 1\nv 1 0 1\nv 0 1 1\n" + faceOf(n + 1, 3) +
                             polygonVertices(n, true, 2) + faceOf(n + 4, n) +
                             "v 0 0 3\nv 1 0 3\nv 0 1 3\n" + faceOf(2 * n + 4, 3);
    std::vector<Diagnostic> warnings;
    const Scene s = loadObj(write("t.obj", text), &warnings);
    expectIndicesInBounds(s);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(s.shapes<Triangle>().size(), 2 * std::size_t(n - 2) + 2);
    const auto u = std::uint32_t(n);
    expectPolygon(s, 0, 0, n, false, 0, u + 1);
    expectUnitTriangle(s, std::size_t(n - 2), 1);
    EXPECT_EQ(s.shapes<Triangle>()[std::size_t(n - 2)].origin.line, u + 5);
    expectPolygon(s, std::size_t(n - 1), u + 3, n, true, 2, 2 * u + 6);
    expectUnitTriangle(s, 2 * std::size_t(n - 2) + 1, 3);
    EXPECT_EQ(s.shapes<Triangle>().back().origin.line, 2 * u + 10);
  }
}

TEST_F(Obj, AnObjWithoutFacesGetsAFiniteCameraAndLights) {
  // The lights were placed around an empty box: NaN, written by `convert`
  // as "light -nan -nan -nan inf inf inf". Now they light a unit box at the
  // origin, as the camera frames it.
  const double radius = 0.5 * std::sqrt(3.0), d = 10.0 * radius;
  for (const char* text : {"", "# nothing\n", "v 1 2 3\nvn 0 0 1\n"}) {
    SCOPED_TRACE(text);
    std::vector<Diagnostic> warnings;
    const Scene s = loadObj(write("t.obj", text), &warnings);
    EXPECT_TRUE(s.shapes<Triangle>().empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].line, 1);
    EXPECT_EQ(warnings[0].message, "the file has no faces: nothing to render");
    expectCloseTo(s.camera.lookat, {0, 0, 0});
    expectCloseTo(s.camera.eye, {0, 0, 1.1 * radius / std::sin(glm::radians(22.5))}, 1e-12);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_NEAR(glm::length(s.lights[0].position), d, 1e-12);
    EXPECT_NEAR(glm::length(s.lights[1].position), d, 1e-12);
    expectCloseTo(s.lights[0].intensity, Color(d * d), 1e-12);
    expectCloseTo(s.lights[1].intensity, Color(0.35 * d * d), 1e-12);
  }
  // Faces that are all dropped leave the scene as empty: the same box, and
  // the warning about the dropped faces.
  std::vector<Diagnostic> warnings;
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), &warnings);
  EXPECT_TRUE(s.shapes<Triangle>().empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message, "1 zero-area triangle was dropped");
  ASSERT_EQ(s.lights.size(), 2u);
  expectCloseTo(s.lights[0].intensity, Color(d * d), 1e-12);
}

// Coordinates are kept within +-1e30, as in every reader (core/math/model_range.h):
// beyond, the default lights' 1/r^2 compensation and the geometry's squares
// could overflow. Two triangles 2e200 apart were lit by infinite lights.
TEST_F(Obj, AMeshBeyondTheSupportedRangeIsAnError) {
  EXPECT_EQ(errorsOf("v 1e200 0 0\nv 1e200 1 0\nv 1e200 0 1\nv -1e200 0 0\nv -1e200 1 0\n"
                     "v -1e200 0 1\nf 1 2 3\nf 4 5 6\n"),
            "DIR/t.obj:7:1: error: f: vertex 1 lies outside the supported range: coordinates must "
            "be within +-1e30");
  // A vertex no face uses may lie anywhere.
  EXPECT_EQ(errorsOf(std::string("v 1e300 0 0\n") + kUnitTriangle + "f 2 3 4\n"), "no error");
  // At the limit itself, the lights are finite.
  const Scene s = loadObj(write("t.obj", "v 1e30 0 0\nv 1e30 1 0\nv 1e30 0 1\nv -1e30 0 0\n"
                                         "v -1e30 1 0\nv -1e30 0 1\nf 1 2 3\nf 4 5 6\n"));
  for (const Light& light : s.lights) {
    EXPECT_TRUE(isFinite(light.position));
    EXPECT_TRUE(isFinite(light.intensity));
  }
}

TEST_F(Obj, AHugeIndexIsPrintedAsWritten) {
  const std::string obj = kUnitTriangle;
  EXPECT_EQ(errorsOf(obj + "f 1 2 99999999999999999999999\n"),
            "DIR/t.obj:4:7: error: f: vertex index '99999999999999999999999' is out of range (3 "
            "'v' statements before this face)");
  EXPECT_EQ(errorsOf(obj + "f 1 2 -0000000000000000000004\n"),
            "DIR/t.obj:4:7: error: f: vertex index '-0000000000000000000004' is out of range (3 "
            "'v' statements before this face)");
  EXPECT_EQ(errorsOf(obj + "f 1 2 3//18446744073709551617\n"),
            "DIR/t.obj:4:7: error: f: normal index '18446744073709551617' is out of range (0 "
            "'vn' statements before this face)");
}

TEST_F(Obj, CornersCommentsAndNulBytesMeanTheSameToBothReaders) {
  // "2//" with nothing after: tinyobjloader alone read the next corner's
  // vertex as this one's normal (here 3, of 1 'vn'); "3//" or "3/" at the
  // end of the line and a comment after a face were errors to it.
  for (const char* face : {"f 1//1 2// 3//1\n", "f 1// 2// 3//\n", "f 1/ 2/ 3/\n",
                           "f 1 2 3 # a comment\n", "f 1 2 3#a comment\n", "\tf  1\t2 3  \n"}) {
    SCOPED_TRACE(face);
    const Scene s = loadObj(write("t.obj", kUnitTriangle + std::string("vn 0 0 1\n") + face));
    expectIndicesInBounds(s);
    ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
    EXPECT_FALSE(s.shapes<Triangle>()[0].smooth());
    expectUnitTriangle(s, 0);
  }
  // tinyobjloader reads a line as a C string: it stopped at a NUL byte where
  // the scan went on. One in a comment is harmless.
  EXPECT_EQ(errorsOf(std::string("v 0 0 0") + '\0' + "5\n"),
            "DIR/t.obj:1:8: error: unexpected NUL byte");
  const Scene s =
      loadObj(write("t.obj", std::string("# a") + '\0' + "b\n" + kUnitTriangle + "f 1 2 3\n"));
  expectIndicesInBounds(s);
  EXPECT_EQ(s.shapes<Triangle>().size(), 1u);
  // A `\` continuation is not supported, by either: an error, not a
  // different statement.
  EXPECT_EQ(errorsOf("v 0 0 \\\n0\n"),
            "DIR/t.obj:1:7: error: v: expected Z (a number) but found '\\'\n"
            "DIR/t.obj:2:1: error: unknown statement '0'");
}

TEST_F(Obj, LongLinesAreReadWhole) {
  const std::string text = "#" + std::string(1 << 20, 'x') + "\n" + kUnitTriangle +
                           std::string(100000, ' ') + "f 1 2 3" + std::string(100000, '\t') + "\n";
  const Scene s = loadObj(write("t.obj", text));
  expectIndicesInBounds(s);
  ASSERT_EQ(s.shapes<Triangle>().size(), 1u);
  EXPECT_EQ(s.shapes<Triangle>()[0].origin.line, 5u);
}

TEST_F(Obj, NumbersAreOnesTinyobjloaderReadsAlike) {
  // Its parser knows plain decimals only: it read "0x1p0" as 0, "0e500" as
  // NaN and a 1 after 400 zeros as 0.
  EXPECT_EQ(errorsOf("v 0x1p0 0 0\n"),
            "DIR/t.obj:1:3: error: v: X must be a plain decimal number (at most 64 characters, "
            "an exponent from -300 to 300), found '0x1p0'");
  EXPECT_EQ(errorsOf("vn 0 0e500 1\n"),
            "DIR/t.obj:1:6: error: vn: Y must be a plain decimal number (at most 64 characters, "
            "an exponent from -300 to 300), found '0e500'");
  EXPECT_EQ(errorsOf("v 0 0 0." + std::string(400, '0') + "1e401\n"),
            "DIR/t.obj:1:7: error: v: Z must be a plain decimal number (at most 64 characters, "
            "an exponent from -300 to 300), found '0.00000000000000000000000000000000000000...'");
  EXPECT_EQ(errorsOf("mtllib t.mtl\n", "newmtl a\nKd 1 1 1e-301\n"),
            "DIR/t.mtl:2:8: error: Kd: B must be a plain decimal number (at most 64 characters, "
            "an exponent from -300 to 300), found '1e-301'");
  // It reads this spelling of the largest double as infinite: the face using
  // it is an error, and so is the material.
  EXPECT_EQ(errorsOf("v 17976931348623158e292 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            "DIR/t.obj:4:1: error: f: tinyobjloader reads vertex 1 as infinite");
  EXPECT_EQ(errorsOf("mtllib t.mtl\nusemtl a\n" + std::string(kUnitTriangle) + "f 1 2 3\n",
                     "newmtl a\nKd 17976931348623158e292 0 0\n"),
            "DIR/t.obj:6:1: error: usemtl: tinyobjloader reads a value of material 'a' as "
            "infinite");
  // What they do read, they read alike (a vertex no face uses may lie beyond
  // the supported range).
  const Scene s =
      loadObj(write("t.obj", "v -.5 +0.5e0 1.E2\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\nv 1e300 0 0\n"));
  expectCloseTo(s.meshVertices[0], {-0.5, 0.5, 100});
  EXPECT_EQ(s.meshVertices[1].x, 1e30);
  EXPECT_EQ(s.meshVertices[3].x, 1e300);
}

// The material the single face of `s` has.
const Material& faceMaterial(const Scene& s) {
  EXPECT_EQ(s.shapes<Triangle>().size(), 1u);
  return s.material({kindOf<Triangle>, 0});
}

TEST_F(Obj, MaterialsAreTheOnesTheScanChecked) {
  const std::string face = std::string(kUnitTriangle) + "f 1 2 3\n";
  const auto colourOf = [&](const std::string& obj, const std::string& mtl) {
    write("t.mtl", mtl);
    const Scene s = loadObj(write("t.obj", obj));
    expectIndicesInBounds(s);
    return faceMaterial(s).color;
  };
  const Color red(1, 0, 0);
  // The name ends where the scan's words end (tinyobjloader alone took the
  // rest of the line, comment and all), and starts after any white space.
  for (const char* mtl : {"newmtl red # a comment\nKd 1 0 0\n", "newmtl \t red\nKd 1 0 0\n",
                          "\xEF\xBB\xBFnewmtl red\nKd 1 0 0\n", "newmtl red\rKd\f1 0 0\r"}) {
    SCOPED_TRACE(mtl);
    EXPECT_EQ(colourOf("mtllib t.mtl\nusemtl red\n" + face, mtl), red);
  }
  // `usemtl` before its `mtllib` (tinyobjloader alone looked the name up
  // before reading the library, and gave the default grey).
  EXPECT_EQ(colourOf("usemtl red\nmtllib t.mtl\n" + face, "newmtl red\nKd 1 0 0\n"), red);
  // Every library of an `mtllib` (tinyobjloader alone stopped after the
  // first it could read).
  write("b.mtl", "newmtl blue\nKd 0 0 1\n");
  EXPECT_EQ(colourOf("mtllib t.mtl b.mtl\nusemtl blue\n" + face, "newmtl red\nKd 1 0 0\n"),
            Color(0, 0, 1));
  // The first definition of a name wins, `illum` included: here none is
  // given, so model 2 and the highlight of Ks 1.
  write("t.mtl", "newmtl a\nKs 1 1 1\nnewmtl a\nKs 0 0 0\nillum 1\n");
  const Scene s = loadObj(write("t.obj", "mtllib t.mtl\nusemtl a\n" + face));
  EXPECT_EQ(faceMaterial(s).ksr, 1.0);
}

} // namespace
} // namespace prism
