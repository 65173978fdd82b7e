// Closed triangle meshes as CSG operands (core/shapes/solid_mesh.h, the .sc
// `mesh` block): a cube of 12 triangles against the `box` it bounds, in a
// difference and an intersection with a sphere (hits, normals, pixels); rays
// exactly through the cube's edges and corners against crossings worked out
// by hand; the tree against every triangle; the block's errors; a mesh
// outside csg renders as its triangles written plainly; both writers.
#include "core/accel/accel.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/ray_tree.h"
#include "core/render/renderer.h"
#include "core/shapes/crossings.h"
#include "core/shapes/shape_kinds.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace prism {
namespace {

using test::expectCloseTo;
using test::sceneErrorsOf;

const PrimitiveRef kFirstCsg{kindOf<Csg>, 0};

// The cube [-1, 1]^3: each face's corners counterclockwise seen from outside
// (checked by hand: the cross product of the first two edges points out),
// split along the diagonal from its first corner to its third.
const double kFaces[6][4][3] = {
    {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},     // +x
    {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}, // -x
    {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},     // +y
    {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}, // -y
    {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},     // +z
    {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}}, // -z
};

std::string corner(const double* c) {
  std::ostringstream s;
  s << c[0] << " " << c[1] << " " << c[2];
  return s.str();
}

// The cube's 12 `triangle` lines (triangle i on line i + 1 of the text),
// each indented by two spaces; `reversed` winds every one inward; `skip`
// leaves one out, `flip` turns one over.
std::string cubeTriangles(bool reversed = false, int skip = -1, int flip = -1) {
  std::string text;
  for (int f = 0; f < 6; ++f) {
    for (int half = 0; half < 2; ++half) {
      const int i = 2 * f + half;
      const double* a = kFaces[f][0];
      const double* b = kFaces[f][half == 0 ? 1 : 2];
      const double* c = kFaces[f][half == 0 ? 2 : 3];
      if (reversed != (i == flip)) std::swap(b, c);
      if (i != skip) text += "  triangle " + corner(a) + "  " + corner(b) + "  " + corner(c) + "\n";
    }
  }
  return text;
}

std::string cubeMesh() { return "mesh\n" + cubeTriangles() + "end\n"; }

const char* const kCamera = "resolution 24 24\neye 3 4 5\nlookat 0 0 0\nup 0 1 0\nfov 40\n"
                            "light 5 5 5 1 1 1\nambient 0.2 0.2 0.2\n"
                            "surface 0.8 0.3 0.2  0.7 0.3 0  10 1\n";

std::vector<Crossing> crossingsOf(const Scene& s, const Ray& r) {
  std::vector<Crossing> out;
  appendCrossings(s.shapes<Csg>().at(0), s.arrays(), r, Interval{}, out);
  return out;
}

// The mesh operand's own crossings (the first operand of the first node).
std::vector<Crossing> meshCrossings(const Scene& s, const Ray& r, Interval range = Interval{}) {
  std::vector<Crossing> out;
  appendCrossings(std::get<SolidMesh>(s.csgOperands.at(0).shape), s.arrays(), r, range, out);
  return out;
}

std::vector<Rgb> pixels(const Scene& s) {
  RenderSettings settings;
  settings.width = s.width;
  settings.height = s.height;
  settings.noAa = true;
  settings.threads = 1;
  const std::unique_ptr<Accel> accel = makeAccel(s, AccelKind::Bvh);
  const RenderResult r = render(s, *accel, settings);
  return r.film.radiance;
}

// ---------------------------------------------------------------------------
// The cube mesh is the box

void expectSameAsBox(const std::string& op, const std::string& second) {
  const Scene mesh =
      parseScene(std::string(kCamera) + "csg " + op + "\n" + cubeMesh() + second + "end\n", "t.sc");
  const Scene box = parseScene(
      std::string(kCamera) + "csg " + op + "\nbox -1 -1 -1 1 1 1\n" + second + "end\n", "t.sc");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 from(4 * u(rng), 4 * u(rng), 4 * u(rng));
    const Ray q{from, glm::normalize(Vec3(u(rng), u(rng), u(rng)) - from)};
    const std::vector<Crossing> a = crossingsOf(mesh, q), b = crossingsOf(box, q);
    ASSERT_EQ(a.size(), b.size()) << op << " ray " << i;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].t, b[k].t, 1e-14 * (1 + std::abs(b[k].t)));
      EXPECT_EQ(a[k].entering, b[k].entering);
      const SurfacePoint pa = mesh.surfaceAt(kFirstCsg, q, a[k].t);
      const SurfacePoint pb = box.surfaceAt(kFirstCsg, q, b[k].t);
      expectCloseTo(pa.outward, pb.outward, 1e-14);
      ++hits;
    }
  }
  EXPECT_GT(hits, 1000);
  const std::vector<Rgb> pm = pixels(mesh), pb = pixels(box);
  ASSERT_EQ(pm.size(), pb.size());
  for (std::size_t i = 0; i < pm.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(pm[i][c], pb[i][c], 1e-6f) << i;
}

TEST(CsgMesh, CubeMinusSphereIsBoxMinusSphere) {
  expectSameAsBox("difference", "sphere 0.5 0.5 1 0.8\n");
}

TEST(CsgMesh, CubeAndSphereIsBoxAndSphere) {
  expectSameAsBox("intersection", "sphere 0.5 0.5 1 1.2\n");
}

// ---------------------------------------------------------------------------
// Edges and corners, by hand

struct Expected {
  double t;
  bool entering;
};

void expectMeshCrossings(const Scene& s, const Ray& r, const std::vector<Expected>& want) {
  const std::vector<Crossing> got = meshCrossings(s, r);
  std::string listed;
  for (const Crossing& c : got)
    listed += std::to_string(c.t) + (c.entering ? " in " : " out ");
  ASSERT_EQ(got.size(), want.size()) << listed;
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].t, want[i].t, 1e-14) << i;
    EXPECT_EQ(got[i].entering, want[i].entering) << i;
  }
}

TEST(CsgMesh, RaysThroughEdgesAndCorners) {
  const Scene s = parseScene("csg union\n" + cubeMesh() + "sphere 9 9 9 1\nend\n", "t.sc");
  // The axis meets the z faces at their centres, on the diagonal both
  // triangles of each face share: one crossing each.
  expectMeshCrossings(s, Ray{{0, 0, -5}, {0, 0, 1}}, {{4, true}, {6, false}});
  // Corner to corner: six triangles meet at each of (-1 -1 -1) and (1 1 1).
  expectMeshCrossings(s, Ray{{-3, -3, -3}, {1, 1, 1}}, {{2, true}, {4, false}});
  // Through the edges x = y = -1 and x = y = 1 at z = 0, across the cube.
  expectMeshCrossings(s, Ray{{-2, -2, 0}, {1, 1, 0}}, {{1, true}, {3, false}});
  // Grazing the edge x = y = 1 from outside: the +y face is entered and the
  // +x face left at one point, a touch.
  expectMeshCrossings(s, Ray{{0, 2, 0}, {1, -1, 0}}, {});
  // Grazing the corner (1 1 1) in the plane z = 1.
  expectMeshCrossings(s, Ray{{0, 2, 1}, {1, -1, 0}}, {});
  // In at the corner (1 1 1), out through the centre of the -z face (on its
  // diagonal) at (0 0 -1).
  expectMeshCrossings(s, Ray{{2, 2, 3}, {-1, -1, -2}}, {{1, true}, {2, false}});
}

TEST(CsgMesh, InwardWindingIsTurnedOutward) {
  const Scene s = parseScene(
      "csg union\nmesh\n" + cubeTriangles(true) + "end\n" + "sphere 9 9 9 1\nend\n", "t.sc");
  expectMeshCrossings(s, Ray{{0.25, 0.5, -5}, {0, 0, 1}}, {{4, true}, {6, false}});
  const SurfacePoint p = s.surfaceAt(kFirstCsg, Ray{{0.25, 0.5, -5}, {0, 0, 1}}, 4);
  expectCloseTo(p.outward, Vec3(0, 0, -1), 0);
}

// The tree finds what testing every triangle finds: a faceted ball of 400
// triangles, away from its edges every triangle hit is a crossing.
TEST(CsgMesh, TreeFindsEveryTriangle) {
  constexpr int kRings = 10, kSegments = 20;
  // The poles and the seam are given once, so the corners that meet there
  // are equal (welded).
  const auto at = [](int ring, int segment) {
    if (ring == 0) return Vec3(0, 0, 1);
    if (ring == kRings) return Vec3(0, 0, -1);
    const double theta = M_PI * ring / kRings, phi = 2 * M_PI * (segment % kSegments) / kSegments;
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  std::string text = "csg union\nmesh\n";
  const auto tri = [&](Vec3 a, Vec3 b, Vec3 c) {
    std::ostringstream line;
    line.precision(17);
    line << "triangle " << a.x << " " << a.y << " " << a.z << " " << b.x << " " << b.y << " " << b.z
         << " " << c.x << " " << c.y << " " << c.z << "\n";
    text += line.str();
  };
  for (int r = 0; r < kRings; ++r)
    for (int g = 0; g < kSegments; ++g) {
      if (r > 0) tri(at(r, g), at(r + 1, g), at(r, g + 1));
      if (r + 1 < kRings) tri(at(r, g + 1), at(r + 1, g), at(r + 1, g + 1));
    }
  text += "end\nsphere 9 9 9 1\nend\n";
  const Scene s = parseScene(text, "t.sc");
  const SolidMesh& m = std::get<SolidMesh>(s.csgOperands.at(0).shape);
  ASSERT_EQ(m.triangleCount, 2u * kRings * kSegments - 2 * kSegments);
  EXPECT_GT(m.nodeCount, 1u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int crossings = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 from(3 * u(rng), 3 * u(rng), 3 * u(rng));
    const Ray q{from, glm::normalize(Vec3(u(rng), u(rng), u(rng)) * 0.8 - from)};
    const Interval line{-1e300, 1e300};
    std::vector<double> all;
    for (const Triangle& t : trianglesOf(m, s.arrays())) {
      double h = 0;
      if (intersect(t, s.meshVertices.data(), q, line, h)) all.push_back(h);
    }
    std::sort(all.begin(), all.end());
    const std::vector<Crossing> got = meshCrossings(s, q, line);
    ASSERT_EQ(got.size(), all.size()) << i;
    for (std::size_t k = 0; k < all.size(); ++k) {
      EXPECT_EQ(got[k].t, all[k]);
      EXPECT_EQ(got[k].entering, k % 2 == 0);
    }
    crossings += int(all.size());
  }
  EXPECT_GT(crossings, 1000);
}

// ---------------------------------------------------------------------------
// The block

TEST(CsgMesh, Errors) {
  const std::string sphere = "sphere 5 0 0 1\n";
  // Without triangle 11 (the -z face's second, which runs (1 1 -1) ->
  // (1 -1 -1)), the first triangle with an edge no other runs back is
  // triangle 0 (line 3): (1 -1 -1) -> (1 1 -1).
  EXPECT_EQ(
      sceneErrorsOf("csg union\nmesh\n" + cubeTriangles(false, 11) + "end\n" + sphere + "end\n"),
      "t.sc:3:3: error: mesh: not closed: the edge from (1 -1 -1) to (1 1 -1) of this "
      "triangle is in no other triangle");
  // Triangle 5 (line 8) turned over runs (1 1 -1) -> (1 1 1) as triangle 0
  // (line 3) does.
  EXPECT_EQ(
      sceneErrorsOf("csg union\nmesh\n" + cubeTriangles(false, -1, 5) + "end\n" + sphere + "end\n"),
      "t.sc:8:3: error: mesh: not consistently oriented: this triangle runs the edge from "
      "(1 1 -1) to (1 1 1) the same way as the triangle at t.sc:3:3 (triangles sharing an "
      "edge must run it in opposite directions, and no more than two may share it)");
  // Outside csg too: a mesh block is a solid wherever it is.
  EXPECT_NE(sceneErrorsOf("mesh\n" + cubeTriangles(false, 11) + "end\n"), "");
  EXPECT_EQ(sceneErrorsOf("mesh\nend\n"), "t.sc:1:1: error: mesh: has no triangles");
  EXPECT_EQ(sceneErrorsOf("mesh\n" + cubeTriangles()),
            "t.sc:1:1: error: mesh without matching end");
  EXPECT_EQ(sceneErrorsOf("mesh\n" + cubeTriangles() + "sphere 0 0 0 1\nend\n"),
            "t.sc:14:1: error: sphere: not allowed inside a mesh block (it holds triangle, "
            "ptriangle, triangle_uv, ptriangle_uv, push, pop, translate, scale, rotate and "
            "include)");
  EXPECT_EQ(sceneErrorsOf("mesh\n" + cubeTriangles() + "pop\nend\n"),
            "t.sc:14:1: error: pop without matching push (a mesh block is open: close it with "
            "'end' first)");
  EXPECT_EQ(sceneErrorsOf("push\nmesh\n" + cubeTriangles() + "pop end\n"),
            "t.sc:15:1: error: pop without matching push (a mesh block is open: close it with "
            "'end' first)\n"
            "t.sc:1:1: error: push without matching pop");
  // A bad triangle is reported and the mesh dropped, without a second error.
  EXPECT_EQ(
      sceneErrorsOf("mesh\n" + cubeTriangles(false, 11) + "  triangle 0 0 0 0 0 0 1 1 1\nend\n"),
      "t.sc:13:3: error: triangle: degenerate triangle (zero area)");
  // Transforms and groups inside the block, and pushes balanced.
  EXPECT_EQ(sceneErrorsOf("csg union mesh push translate 1 0 0 pop scale 2 2 2\n" +
                          cubeTriangles() + "end\n" + sphere + "end\n"),
            "");
}

TEST(CsgMesh, TransformedMeshIsPlacedLikeItsTriangles) {
  // Scaled by 2 along x and moved by 3: the cube spans x = 1 .. 5.
  const Scene s = parseScene("csg union\npush translate 3 0 0 scale 2 1 1\n" + cubeMesh() +
                                 "pop\nsphere 9 9 9 1\nend\n",
                             "t.sc");
  expectMeshCrossings(s, Ray{{0, 0.5, 0.25}, {1, 0, 0}}, {{1, true}, {5, false}});
}

TEST(CsgMesh, OutsideCsgRendersLikeItsTriangles) {
  const std::string plain = std::string(kCamera) + cubeTriangles();
  const std::string block = std::string(kCamera) + cubeMesh();
  const Scene a = parseScene(plain, "t.sc"), b = parseScene(block, "t.sc");
  EXPECT_EQ(b.shapes<Triangle>().size(), 12u);
  EXPECT_EQ(pixels(a), pixels(b));
}

// The --pixel ray tree names the operand met, and its triangle as the part.
TEST(CsgMesh, RayTreeNamesTheMeshOperand) {
  const Scene s = parseScene("csg union\n" + cubeMesh() + "sphere 9 9 9 1\nend\n", "t.sc");
  RayTreeNode node;
  node.ray = Ray{{0.25, 0.5, -5}, {0, 0, 1}};
  node.hit = true;
  node.where = Hit{4.0, kFirstCsg};
  node.part = s.surfaceAt(kFirstCsg, node.ray, 4.0).part;
  std::ostringstream out;
  printRayTree(out, node, s);
  EXPECT_NE(out.str().find("hits csg #0 (t.sc:1), operand mesh (t.sc:2) at t = 4,"),
            std::string::npos)
      << out.str();
  // The part is the triangle's place in the text: (0.25 0.5) on the -z face
  // lies where y > x, in triangle 10 (corners (-1 -1), (-1 1), (1 1)).
  EXPECT_NE(out.str().find(", part 10\n"), std::string::npos) << out.str();
}

TEST(CsgMesh, WritersRoundTrip) {
  const Scene s = parseScene(std::string(kCamera) + "csg difference\n" + cubeMesh() +
                                 "sphere 0.5 0.5 1 0.8\nend\n",
                             "t.sc");
  std::ostringstream sc;
  writeScene(sc, s);
  EXPECT_NE(sc.str().find("csg difference\n  mesh\n    triangle "), std::string::npos) << sc.str();
  const Scene back = parseScene(sc.str(), "back.sc");
  ASSERT_EQ(back.meshTriangles.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(back.meshVertices[back.meshTriangles[i].vertex[k]],
                s.meshVertices[s.meshTriangles[i].vertex[k]]);
  EXPECT_EQ(pixels(back), pixels(s));
  std::ostringstream pov;
  writePov(pov, s);
  EXPECT_NE(pov.str().find("difference {\n  mesh {\n  triangle { "), std::string::npos)
      << pov.str();
  EXPECT_NE(pov.str().find("  inside_vector <0, 0, 1> material { Prism_M"), std::string::npos)
      << pov.str();
}

} // namespace
} // namespace prism
