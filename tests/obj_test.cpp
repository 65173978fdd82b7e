// OBJ/MTL import: faces (triangles, quads, concave polygons, negative
// indices, with and without normals), the MTL mapping onto Prism's material,
// groups, face lines, the default camera and lights, and every error with
// its file, line and column.
#include "core/accel.h"
#include "core/obj_reader.h"
#include "core/tracer.h"

#include "test_files.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace prism {
namespace {

namespace fs = std::filesystem;

class Obj : public ::testing::Test {
protected:
  fs::path write(const std::string& name, const std::string& text) {
    test::writeFile(dir_ / name, text);
    return dir_ / name;
  }

  // The messages of loading `obj` (and `mtl` as t.mtl), the temporary
  // directory shown as DIR.
  std::string errorsOf(const std::string& obj, const std::string& mtl = "") {
    if (!mtl.empty()) write("t.mtl", mtl);
    try {
      loadObj(write("t.obj", obj));
    } catch (const SceneError& e) {
      std::string text = e.what();
      const std::string dir = dir_.string() + "/";
      for (std::size_t at; (at = text.find(dir)) != std::string::npos;)
        text.replace(at, dir.size(), "DIR/");
      return text;
    }
    return "no error";
  }

  test::ScratchDir scratch_;
  const fs::path dir_ = scratch_.path();
};

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
  ASSERT_EQ(s.triangles.size(), 8u);
  EXPECT_EQ(s.primitiveCount(), 8u);
  const Vec3* v = s.meshVertices.data();
  // f 1//1 2//1 3//1: smooth, its normal given.
  EXPECT_TRUE(s.triangles[0].smooth());
  expectCloseTo(s.meshNormals[s.triangles[0].normal[0]], {0, 0, 1});
  EXPECT_EQ(s.triangles[0].origin.line, 11u);
  // f -4 -2 -1 counts back from the 4 vertices so far: 1 3 4; flat.
  EXPECT_FALSE(s.triangles[1].smooth());
  expectCloseTo(v[s.triangles[1].vertex[0]], {0, 0, 0});
  expectCloseTo(v[s.triangles[1].vertex[1]], {1, 1, 0});
  expectCloseTo(v[s.triangles[1].vertex[2]], {0, 1, 0});
  EXPECT_EQ(s.triangles[1].origin.line, 12u);
  // The quad: two smooth triangles, normals normalised.
  for (int i : {2, 3}) {
    EXPECT_TRUE(s.triangles[i].smooth());
    EXPECT_EQ(s.triangles[i].origin.line, 20u);
    expectCloseTo(s.meshNormals[s.triangles[i].normal[2]], {0, 0, 1});
  }
  // The concave pentagon: 3 triangles covering its area 2 - 0.5, all facing +z.
  double area = 0.0;
  for (int i : {4, 5, 6}) {
    const Triangle& t = s.triangles[i];
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
  const Material& red = s.material({PrimitiveKind::Triangle, 0});
  EXPECT_EQ(red.color, Color(0.8, 0.1, 0.1));
  EXPECT_EQ(red.kdr, 1.0);
  EXPECT_NEAR(red.ksr, 0.6, 1e-15); // mean of Ks
  EXPECT_EQ(red.kst, 0.0);
  EXPECT_EQ(red.e, 50.0);
  EXPECT_EQ(red.ir, 1.0);
  const Material& glass = s.material({PrimitiveKind::Triangle, 2});
  EXPECT_EQ(glass.kdr, 0.25); // d
  EXPECT_EQ(glass.kst, 0.75); // 1 - d
  EXPECT_EQ(glass.ksr, 1.0);
  EXPECT_EQ(glass.e, 200.0);
  EXPECT_EQ(glass.ir, 1.5);
  const Material& matte = s.material({PrimitiveKind::Triangle, 4});
  EXPECT_EQ(matte.ksr, 0.0); // illum 1: no highlight, no mirror
  // Tr 0.75 is d 0.25; no illum given: model 2 (but Ks is 0 here).
  const Material& tr = s.material({PrimitiveKind::Triangle, 7});
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
  ASSERT_EQ(s.triangles.size(), 1u);
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
  ASSERT_EQ(s.triangles.size(), 1u);
  expectCloseTo(geometricNormal(s.triangles[0], s.meshVertices.data()), {0, 0, 1});
}

TEST_F(Obj, ZeroNormalsMakeAFlatFaceAndZeroAreaFacesAreDropped) {
  std::vector<Diagnostic> warnings;
  const Scene s = loadObj(write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nvn 0 0 0\n"
                                         "f 1//1 2//1 3//1\nf 1 2 4\n"),
                          &warnings);
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_FALSE(s.triangles[0].smooth());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].message, "1 zero-area triangle was dropped");
}

TEST_F(Obj, Errors) {
  EXPECT_EQ(errorsOf("v 1 2 x\n"), "DIR/t.obj:1:7: error: v: expected Z (a number) but found 'x'");
  EXPECT_EQ(errorsOf("v 1 2\n"),
            "DIR/t.obj:1:1: error: v: expected Z (a number) at the end of the line");
  EXPECT_EQ(errorsOf("v 1 2 inf\n"), "DIR/t.obj:1:7: error: v: Z is not a finite number ('inf')");
  EXPECT_EQ(errorsOf("vn 1 2 3 4\n"),
            "DIR/t.obj:1:10: error: vn: unexpected '4' after the statement's arguments");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
            "DIR/t.obj:4:7: error: f: vertex index 9 is out of range (3 'v' statements before "
            "this face)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"),
            "DIR/t.obj:4:7: error: f: vertex index -4 is out of range (3 'v' statements before "
            "this face)");
  EXPECT_EQ(errorsOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n"),
            "DIR/t.obj:4:3: error: f: normal index 1 is out of range (0 'vn' statements before "
            "this face)\n"
            "DIR/t.obj:4:8: error: f: normal index 1 is out of range (0 'vn' statements before "
            "this face)\n"
            "DIR/t.obj:4:13: error: f: normal index 1 is out of range (0 'vn' statements before "
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

} // namespace
} // namespace prism
