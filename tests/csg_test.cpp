// Constructive solid geometry (core/shapes/csg.h): hits, normals and
// entering/leaving against values worked out by hand (a lens of two spheres,
// a box with a spherical hollow, touching and flush boxes), a glass lens that
// refracts as the two-surface computation says, random trees against the
// operands' interval lists, shadows through a hole, bounds, the hierarchies
// against brute force, the .sc block and its errors, and both writers.
#include "core/accel/accel.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/shapes/crossings.h"
#include "core/shapes/shape_kinds.h"
#include "tests/test_expect.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace prism {
namespace {

using test::expectCloseTo;
using test::sceneErrorsOf;

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

const PrimitiveRef kFirstCsg{kindOf<Csg>, 0};

const Csg& firstCsg(const Scene& s) { return s.shapes<Csg>().at(0); }

std::vector<Crossing> crossingsOf(const Scene& s, const Ray& r, Interval range = Interval{}) {
  std::vector<Crossing> out;
  appendCrossings(firstCsg(s), s.arrays(), r, range, out);
  return out;
}

// ---------------------------------------------------------------------------
// Hand-computed cases

// Two unit spheres with centres 1 apart, at z = -0.5 and z = 0.5: their
// intersection is a lens from z = -0.5 to 0.5 on the axis.
const char* const kLens = "csg intersection\n"
                          "  sphere 0 0 -0.5 1\n"
                          "  sphere 0 0 0.5 1\n"
                          "end\n";

TEST(Csg, LensOfTwoSpheresOnAndOffTheAxis) {
  const Scene s = parseScene(kLens, "t.sc");
  ASSERT_EQ(s.shapes<Csg>().size(), 1u);
  EXPECT_EQ(s.shapes<Sphere>().size(), 0u); // the operands are no primitives
  EXPECT_EQ(s.allPrimitives().size(), 1u);
  // On the axis: enters through the far sphere's near cap, leaves through
  // the near sphere's far cap.
  const Ray axis = ray({0, 0, -5}, {0, 0, 1});
  double t = 0;
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, axis, Interval{}, t));
  EXPECT_EQ(t, 4.5);
  SurfacePoint p = s.surfaceAt(kFirstCsg, axis, t);
  expectCloseTo(p.outward, Vec3(0, 0, -1), 1e-15);
  const std::vector<Crossing> c = crossingsOf(s, axis);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].entering);
  EXPECT_FALSE(c[1].entering);
  EXPECT_EQ(c[0].t, 4.5);
  EXPECT_EQ(c[1].t, 5.5);
  p = s.surfaceAt(kFirstCsg, axis, c[1].t);
  expectCloseTo(p.outward, Vec3(0, 0, 1), 1e-15);
  // Off the axis at x = 0.5: each sphere's surface is at z = +-0.5 +- sqrt(3/4).
  const double h = std::sqrt(0.75);
  const Ray off = ray({0.5, 0, -5}, {0, 0, 1});
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, off, Interval{}, t));
  EXPECT_NEAR(t, 5.0 + 0.5 - h, 1e-14);
  p = s.surfaceAt(kFirstCsg, off, t);
  expectCloseTo(p.outward, glm::normalize(Vec3(0.5, 0, -h)), 1e-14);
  EXPECT_LT(glm::dot(p.outward, off.dir), 0.0); // entering
  const std::vector<Crossing> co = crossingsOf(s, off);
  ASSERT_EQ(co.size(), 2u);
  EXPECT_NEAR(co[1].t, 5.0 - 0.5 + h, 1e-14);
  p = s.surfaceAt(kFirstCsg, off, co[1].t);
  expectCloseTo(p.outward, glm::normalize(Vec3(0.5, 0, h)), 1e-14);
  EXPECT_GT(glm::dot(p.outward, off.dir), 0.0); // leaving
  // From inside the lens only the way out; the point-only record agrees.
  const Ray inside = ray({0, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, inside, Interval{}, t));
  EXPECT_NEAR(t, h, 1e-15);
  expectCloseTo(s.surfaceAt(kFirstCsg, inside.at(t)).outward,
                s.surfaceAt(kFirstCsg, inside, t).outward, 1e-15);
  // Beyond the rim (|x| > sqrt(3)/2) nothing.
  EXPECT_FALSE(intersectPrimitive(s, kFirstCsg, ray({0.9, 0, -5}, {0, 0, 1}), Interval{}, t));
}

// Snell's law for a unit direction d meeting a unit normal n that faces it.
Vec3 refracted(const Vec3& d, const Vec3& n, double eta) {
  const double c = -glm::dot(n, d);
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  return eta * d + (eta * c - std::sqrt(k)) * n;
}

// The nearer (sign -1) or farther root of the ray against a sphere.
double sphereRoot(const Ray& r, const Vec3& centre, double radius, double sign) {
  const Vec3 f = r.origin - centre;
  const double b = glm::dot(f, r.dir);
  return -b + sign * std::sqrt(b * b - (glm::dot(f, f) - radius * radius));
}

TEST(Csg, GlassLensRefractsLikeItsTwoSurfaces) {
  const Scene s = parseScene(std::string("surface 1 1 1  0 0 1  1 1.5\n") + kLens, "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 3);
  RayCounts counts;
  RayTreeNode root;
  const Ray eye = ray({0.3, 0.2, -5}, {0, 0, 1});
  tracer.trace(eye, 1, counts, &root);
  ASSERT_TRUE(root.hit);
  EXPECT_FALSE(root.leaving);
  // Analytic: enter the sphere at z = +0.5 from outside, leave the one at -0.5.
  const Vec3 cFar(0, 0, 0.5), cNear(0, 0, -0.5);
  const Vec3 p1 = eye.at(sphereRoot(eye, cFar, 1.0, -1.0));
  expectCloseTo(root.point, p1, 1e-14);
  const Vec3 d1 = refracted(eye.dir, glm::normalize(p1 - cFar), 1.0 / 1.5);
  const auto transmittedOf = [](const RayTreeNode& n) -> const RayTreeNode* {
    for (const RayTreeNode& child : n.children)
      if (child.kind == RayKind::Transmitted) return &child;
    return nullptr;
  };
  const RayTreeNode* inner = transmittedOf(root);
  ASSERT_NE(inner, nullptr);
  expectCloseTo(inner->ray.dir, d1, 1e-14);
  ASSERT_TRUE(inner->hit);
  EXPECT_TRUE(inner->leaving);
  const Ray through{p1, d1};
  const Vec3 p2 = through.at(sphereRoot(through, cNear, 1.0, 1.0));
  expectCloseTo(inner->point, p2, 1e-12);
  const Vec3 d2 = refracted(d1, -glm::normalize(p2 - cNear), 1.5);
  const RayTreeNode* out = transmittedOf(*inner);
  ASSERT_NE(out, nullptr);
  expectCloseTo(out->ray.dir, d2, 1e-12);
}

// A biconvex lens of two spheres of radius 4, 1 thick, focuses a parallel
// beam near the axis where the thick-lens formula says: 1/f = (n - 1)
// (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)), the back focus f (1 - (n - 1) d /
// (n R1)) beyond the second surface.
TEST(Csg, GlassLensFocusesWhereTheThickLensFormulaSays) {
  const Scene s = parseScene("surface 1 1 1  0 0 1  1 1.5\n"
                             "csg intersection sphere 0 0 3.5 4  sphere 0 0 -3.5 4 end\n",
                             "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 3);
  const double n = 1.5, r1 = 4.0, r2 = -4.0, d = 1.0;
  const double f = 1.0 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * d / (n * r1 * r2)));
  const double focus = 0.5 + f * (1 - (n - 1) * d / (n * r1));
  for (const double h : {1e-3, -2e-3, 5e-4}) {
    RayCounts counts;
    RayTreeNode root;
    tracer.trace(ray({h, 0, -5}, {0, 0, 1}), 1, counts, &root);
    const RayTreeNode* node = &root;
    for (int i = 0; i < 2; ++i) {
      const auto it =
          std::find_if(node->children.begin(), node->children.end(),
                       [](const RayTreeNode& c) { return c.kind == RayKind::Transmitted; });
      ASSERT_NE(it, node->children.end());
      node = &*it;
    }
    // Where the emerging ray crosses the axis (x = 0).
    const Ray& out = node->ray;
    const double z = out.origin.z - out.origin.x * out.dir.z / out.dir.x;
    EXPECT_NEAR(z, focus, 1e-6 * focus) << h; // spherical aberration: O(h^2)
  }
}

// A box with a sphere taken out of the middle of its top face.
const char* const kHollow = "csg difference\n"
                            "  box -1 -1 -1  1 1 1\n"
                            "  sphere 0 0 1 0.5\n"
                            "end\n";

TEST(Csg, DifferenceShowsTheSubtractedSurfaceInsideOut) {
  const Scene s = parseScene(kHollow, "t.sc");
  const Ray down = ray({0, 0, 5}, {0, 0, -1});
  double t = 0;
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, down, Interval{}, t));
  EXPECT_EQ(t, 4.5); // the bottom of the hollow, not the (removed) top face
  const SurfacePoint p = s.surfaceAt(kFirstCsg, down, t);
  expectCloseTo(p.outward, Vec3(0, 0, 1), 1e-15); // toward the sphere's centre
  EXPECT_LT(glm::dot(p.outward, down.dir), 0.0);  // entering the solid
  // A slanted ray into the hollow: the normal points to the centre.
  const Ray slant = ray({0.3, 0, 5}, {0, 0, -1});
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, slant, Interval{}, t));
  const Vec3 q = slant.at(t);
  EXPECT_NEAR(glm::length(q - Vec3(0, 0, 1)), 0.5, 1e-15);
  expectCloseTo(s.surfaceAt(kFirstCsg, slant, t).outward, glm::normalize(Vec3(0, 0, 1) - q), 1e-14);
  // Beside the hollow the top face: the box's own normal.
  const Ray beside = ray({0.8, 0.8, 5}, {0, 0, -1});
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, beside, Interval{}, t));
  EXPECT_EQ(t, 4.0);
  expectCloseTo(s.surfaceAt(kFirstCsg, beside, t).outward, Vec3(0, 0, 1), 0.0);
  // Crossings through the hollow along z: enter at 0.5, leave at -1.
  const std::vector<Crossing> c = crossingsOf(s, down);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 4.5);
  EXPECT_TRUE(c[0].entering);
  EXPECT_EQ(c[1].t, 6.0);
  EXPECT_FALSE(c[1].entering);
}

TEST(Csg, UnionHasNoInternalSurfaces) {
  const Scene s = parseScene("csg union sphere 0 0 0 1  sphere 1 0 0 1 end", "t.sc");
  // From inside the first sphere through the overlap: the only crossing is
  // where the second sphere is left.
  const Ray r = ray({0, 0, 0}, {1, 0, 0});
  const std::vector<Crossing> c = crossingsOf(s, r);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 2.0);
  EXPECT_FALSE(c[0].entering);
  double t = 0;
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, r, Interval{}, t));
  EXPECT_EQ(t, 2.0);
  // The whole line: enter at x = -1, leave at x = 2.
  const std::vector<Crossing> all = crossingsOf(s, ray({-5, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].t, 4.0);
  EXPECT_EQ(all[1].t, 7.0);
  // A range: the crossings inside it only.
  EXPECT_EQ(crossingsOf(s, ray({-5, 0, 0}, {1, 0, 0}), Interval{5.0, 8.0}).size(), 1u);
}

TEST(Csg, NestedDifferenceIntersected) {
  // (box - sphere) ∩ sphere: along the x axis the box is [-2, 2], the
  // hollow [-1, 1], the other sphere [0.5, 3.5]: inside on [1, 2] only.
  const Scene s = parseScene("csg intersection\n"
                             "  csg difference box -2 -2 -2 2 2 2  sphere 0 0 0 1 end\n"
                             "  sphere 2 0 0 1.5\n"
                             "end\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Csg>().size(), 1u);
  ASSERT_EQ(s.csgNodes.size(), 1u);
  const Ray r = ray({-5, 0, 0}, {1, 0, 0});
  const std::vector<Crossing> c = crossingsOf(s, r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 6.0);
  EXPECT_TRUE(c[0].entering);
  EXPECT_EQ(c[1].t, 7.0);
  expectCloseTo(s.surfaceAt(kFirstCsg, r, 6.0).outward, Vec3(-1, 0, 0), 1e-15); // hollow, turned
  expectCloseTo(s.surfaceAt(kFirstCsg, r, 7.0).outward, Vec3(1, 0, 0), 0.0);    // the box
  // A subtracted difference turns twice: box - (box - sphere) shows the
  // sphere the right way out.
  const Scene twice = parseScene("csg difference box -3 -3 -3 3 3 3\n"
                                 "  csg difference box -2 -2 -2 2 2 2  sphere 0 0 0 1 end\n"
                                 "end\n",
                                 "t.sc");
  const std::vector<Crossing> w = crossingsOf(twice, r);
  ASSERT_EQ(w.size(), 6u); // [-3,-2], [-1, 1], [2, 3]
  EXPECT_EQ(w[2].t, 4.0);
  EXPECT_TRUE(w[2].entering);
  expectCloseTo(twice.surfaceAt(kFirstCsg, r, 4.0).outward, Vec3(-1, 0, 0), 1e-15);
  expectCloseTo(twice.surfaceAt(kFirstCsg, r, 3.0).outward, Vec3(1, 0, 0), 0.0);
}

TEST(Csg, CoincidentFaces) {
  const Ray r = ray({-1, 0.5, 0.5}, {1, 0, 0});
  // Two boxes touching at x = 1: their union has no face there.
  const Scene u = parseScene("csg union box 0 0 0 1 1 1  box 1 0 0 2 1 1 end", "t.sc");
  std::vector<Crossing> c = crossingsOf(u, r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 1.0);
  EXPECT_EQ(c[1].t, 3.0);
  // Their intersection is a face only: nothing is inside.
  const Scene i = parseScene("csg intersection box 0 0 0 1 1 1  box 1 0 0 2 1 1 end", "t.sc");
  EXPECT_TRUE(crossingsOf(i, r).empty());
  double t = 0;
  EXPECT_FALSE(intersectPrimitive(i, kFirstCsg, r, Interval{}, t));
  // A box cut flush by another: the far faces coincide and vanish with the
  // cut; the cut face is the second box's, turned.
  const Scene d = parseScene("csg difference box 0 0 0 2 1 1  box 1 0 0 2 1 1 end", "t.sc");
  c = crossingsOf(d, r);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[1].t, 2.0);
  EXPECT_FALSE(c[1].entering);
  expectCloseTo(d.surfaceAt(kFirstCsg, r, 2.0).outward, Vec3(1, 0, 0), 0.0);
  // Either order of the operands of a union, the same answer.
  const Scene u2 = parseScene("csg union box 1 0 0 2 1 1  box 0 0 0 1 1 1 end", "t.sc");
  EXPECT_EQ(crossingsOf(u2, r).size(), 2u);
  // A solid minus itself is empty.
  const Scene none = parseScene("csg difference sphere 0 0 0 1 sphere 0 0 0 1 end", "t.sc");
  EXPECT_TRUE(crossingsOf(none, ray({-5, 0, 0}, {1, 0, 0})).empty());
}

TEST(Csg, MaterialsStayWithTheOperands) {
  const Scene s = parseScene("surface 1 0 0 1 0 0 1 1\n"
                             "csg difference\n"
                             "  box -1 -1 -1 1 1 1\n"
                             "  surface 0 0 1 1 0 0 1 1\n"
                             "  sphere 0 0 1 0.5\n"
                             "end\n"
                             "sphere 5 0 0 1\n",
                             "t.sc");
  const Ray hollow = ray({0, 0, 5}, {0, 0, -1});
  const Ray top = ray({0.8, 0.8, 5}, {0, 0, -1});
  EXPECT_EQ(s.materialAt(s.surfaceAt(kFirstCsg, hollow, 4.5)).color, Color(0, 0, 1));
  EXPECT_EQ(s.materialAt(s.surfaceAt(kFirstCsg, top, 4.0)).color, Color(1, 0, 0));
  // `end` restores the material of `csg`.
  EXPECT_EQ(s.material({kindOf<Sphere>, 0}).color, Color(1, 0, 0));
  EXPECT_EQ(s.describe(kFirstCsg), "csg #0 (t.sc:2)");
  EXPECT_EQ(s.kindCounts(), "1 sphere, 1 csg");
}

TEST(Csg, TransformsInsideAndOutsideTheBlock) {
  const Scene s = parseScene("push translate 10 0 0\n"
                             "csg union\n"
                             "  sphere 0 0 0 1\n"
                             "  push translate 0 5 0 box -1 -1 -1 1 1 1 pop\n"
                             "  translate 0 0 7\n"
                             "  sphere 0 0 0 1\n"
                             "end\n"
                             "sphere 0 0 0 1\n" // the translate inside the block is gone
                             "pop\n",
                             "t.sc");
  const Csg& node = firstCsg(s);
  EXPECT_EQ(node.bounds.lo, Vec3(9, -1, -1));
  EXPECT_EQ(node.bounds.hi, Vec3(11, 6, 8));
  EXPECT_EQ(s.shapes<Sphere>().at(0).center, Vec3(10, 0, 0));
  EXPECT_EQ(s.groups.size(), 2u); // the push inside the block makes no group
}

// ---------------------------------------------------------------------------
// Bounds, hierarchies and shadows

TEST(Csg, BoundsByWhatTheNodeCanCover) {
  const auto boundsOfText = [](const char* text) {
    const Scene s = parseScene(text, "t.sc");
    return s.bounds(kFirstCsg);
  };
  Aabb b = boundsOfText("csg union box 0 0 0 1 1 1  box 2 2 2 3 3 3 end");
  EXPECT_EQ(b.lo, Vec3(0));
  EXPECT_EQ(b.hi, Vec3(3));
  b = boundsOfText("csg intersection box 0 0 0 2 2 2  box 1 1 1 3 3 3 end");
  EXPECT_EQ(b.lo, Vec3(1));
  EXPECT_EQ(b.hi, Vec3(2));
  b = boundsOfText("csg difference box 0 0 0 2 2 2  box 1 1 1 3 3 3 end");
  EXPECT_EQ(b.lo, Vec3(0));
  EXPECT_EQ(b.hi, Vec3(2));
  b = boundsOfText("csg intersection box 0 0 0 1 1 1  box 2 2 2 3 3 3 end");
  EXPECT_EQ(b.lo, b.hi); // disjoint: a point, never hit
}

TEST(Csg, AccelsAgreeWithBruteForce) {
  std::string text;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10, 10), r(0.3, 1.5);
  const auto n = [&](double x) { return std::to_string(x) + " "; };
  const char* const ops[] = {"union", "intersection", "difference"};
  for (int i = 0; i < 60; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    text += std::string("csg ") + ops[i % 3] + "\n";
    text += "  box " + n(x) + n(y) + n(z) + n(x + r(rng)) + n(y + r(rng)) + n(z + r(rng)) + "\n";
    text += "  sphere " + n(x + 0.5) + n(y + 0.5) + n(z + 0.5) + n(r(rng)) + "\n";
    if (i % 4 == 0)
      text += "  csg union sphere " + n(x) + n(y) + n(z) + "0.4 cylinder " + n(x) + n(y) + n(z) +
              n(x + 1) + n(y) + n(z) + "0.2 end\n";
    text += "end\n";
    if (i % 5 == 0)
      text += "push box " + n(x) + n(y) + n(z + 2) + n(x + 1) + n(y + 1) + n(z + 3) + "pop\n";
  }
  const Scene s = parseScene(text, "t.sc");
  ASSERT_EQ(s.shapes<Csg>().size(), 60u);
  EXPECT_GT(test::expectAccelsAgreeWithBruteForce(s, 10.0, 3000), 150);
}

TEST(Csg, ShadowsPassThroughAHole) {
  // A slab with a vertical hole through it, a light above.
  const Scene s = parseScene("csg difference\n"
                             "  box -2 1 -2  2 1.5 2\n"
                             "  cylinder 0 0 0  0 3 0  0.5\n"
                             "end\n",
                             "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  const Vec3 light(0, 10, 0);
  const auto lit = [&](const Vec3& from) {
    const Vec3 to = light - from;
    return !accel->anyHit(Ray{from, glm::normalize(to)}, Interval{0.0, glm::length(to)}, nullptr);
  };
  EXPECT_TRUE(lit({0, 0, 0}));
  EXPECT_TRUE(lit({0.1, 0, 0.1}));
  EXPECT_FALSE(lit({1, 0, 0}));
  EXPECT_FALSE(lit({0, 0, -1.5}));
}

// ---------------------------------------------------------------------------
// Random trees against the operands' interval lists

struct Spans {
  std::vector<std::pair<double, double>> list; // where the ray is inside
  bool contains(double t) const {
    return std::any_of(list.begin(), list.end(),
                       [&](const auto& s) { return s.first < t && t < s.second; });
  }
};

// Inside-ness of a tree at t, from its leaves' spans, by the definition.
bool insideAt(const Csg& node, const ShapeArrays& arrays, const Ray& r, double t) {
  bool result = node.op != CsgOp::Union;
  const auto operands = operandsOf(node, arrays);
  for (std::size_t i = 0; i < operands.size(); ++i) {
    bool in = false;
    std::visit(
        [&](const auto& shape) {
          if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>) {
            in = insideAt(arrays.csgNodes[shape.index], arrays, r, t);
          } else {
            std::vector<Crossing> c;
            appendCrossings(shape, arrays, r, Interval{-1e300, 1e300}, c);
            Spans spans;
            for (std::size_t k = 0; k + 1 < c.size(); k += 2)
              spans.list.push_back({c[k].t, c[k + 1].t});
            in = spans.contains(t);
          }
        },
        operands[i].shape);
    if (node.op == CsgOp::Union) result = result || in;
    if (node.op == CsgOp::Intersection) result = result && in;
    if (node.op == CsgOp::Difference) result = i == 0 ? in : result && !in;
  }
  return result;
}

TEST(Csg, RandomTreesMatchTheIntervalLists) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1), r(0.3, 1.0);
  const char* const ops[] = {"union", "intersection", "difference"};
  const auto n = [](double x) { return std::to_string(x) + " "; };
  const auto leaf = [&] {
    if (rng() % 2) return "sphere " + n(u(rng)) + n(u(rng)) + n(u(rng)) + n(r(rng));
    const double x = u(rng), y = u(rng), z = u(rng);
    return "box " + n(x) + n(y) + n(z) + n(x + r(rng)) + n(y + r(rng)) + n(z + r(rng));
  };
  int checked = 0;
  for (int tree = 0; tree < 40; ++tree) {
    std::string text = std::string("csg ") + ops[tree % 3] + "\n";
    for (int k = 0; k < 2 + tree % 2; ++k) {
      if (rng() % 3 == 0)
        text += std::string("csg ") + ops[rng() % 3] + " " + leaf() + " " + leaf() + " end\n";
      else
        text += leaf() + "\n";
    }
    text += "end\n";
    const Scene s = parseScene(text, "t.sc");
    const Csg& node = firstCsg(s);
    for (int i = 0; i < 200; ++i) {
      // From all around toward points of the operands' region.
      const Vec3 from(4 * u(rng), 4 * u(rng), 4 * u(rng));
      const Ray q = ray(from, Vec3(u(rng), u(rng), u(rng)) - from);
      // Where the inside-ness by definition changes, from the leaves' crossings.
      std::vector<double> events;
      for (const CsgOperand& o : s.csgOperands) {
        std::visit(
            [&](const auto& shape) {
              if constexpr (!std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>) {
                std::vector<Crossing> c;
                appendCrossings(shape, s.arrays(), q, Interval{}, c);
                for (const Crossing& x : c)
                  events.push_back(x.t);
              }
            },
            o.shape);
      }
      std::sort(events.begin(), events.end());
      std::optional<double> want;
      for (std::size_t k = 0; k < events.size() && !want; ++k) {
        const double before = k == 0 ? events[k] / 2 : (events[k - 1] + events[k]) / 2;
        const double after =
            k + 1 < events.size() ? (events[k] + events[k + 1]) / 2 : events[k] + 1.0;
        if (insideAt(node, s.arrays(), q, before) != insideAt(node, s.arrays(), q, after))
          want = events[k];
      }
      double t = 0;
      const bool hit = intersectPrimitive(s, kFirstCsg, q, Interval{}, t);
      ASSERT_EQ(hit, want.has_value()) << text << " ray " << i;
      if (hit) {
        ++checked;
        EXPECT_EQ(t, *want) << text << " ray " << i;
        // The normal agrees with entering or leaving by definition.
        const bool entering = !insideAt(node, s.arrays(), q, t * (1 - 1e-9) - 1e-12);
        const SurfacePoint p = s.surfaceAt(kFirstCsg, q, t);
        EXPECT_EQ(glm::dot(p.outward, q.dir) < 0.0, entering) << text << " ray " << i;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

// ---------------------------------------------------------------------------
// The .sc block

TEST(Csg, IncludedOperands) {
  test::ScratchDir dir;
  test::writeFile(dir.path() / "part.sc", "sphere 0 0 0 1\ncsg union box 0 0 0 1 1 1 "
                                          "cylinder 0 0 0 0 0 2 0.5 end\n");
  test::writeFile(dir.path() / "main.sc", "csg difference box -2 -2 -2 2 2 2\n"
                                          "  include part.sc\n"
                                          "end\n");
  const Scene s = loadScene((dir.path() / "main.sc").string());
  ASSERT_EQ(s.shapes<Csg>().size(), 1u);
  EXPECT_EQ(firstCsg(s).operandCount, 3u);
  EXPECT_EQ(s.csgNodes.size(), 1u);
}

TEST(Csg, ScErrors) {
  const std::string operands = " sphere 0 0 0 1 sphere 1 0 0 1";
  EXPECT_EQ(sceneErrorsOf("csg union sphere 0 0 0 1 end"),
            "t.sc:1:1: error: csg union: needs at least two operands, found 1");
  EXPECT_EQ(sceneErrorsOf("csg difference\nend"),
            "t.sc:1:1: error: csg difference: needs at least two operands, found 0");
  EXPECT_EQ(sceneErrorsOf("sphere 0 0 0 1\nend"),
            "t.sc:2:1: error: end without matching csg or mesh");
  EXPECT_EQ(sceneErrorsOf("csg union" + operands), "t.sc:1:1: error: csg without matching end");
  EXPECT_EQ(sceneErrorsOf("csg xor" + operands + " end"),
            "t.sc:1:5: error: csg: expected union, intersection or difference but found 'xor'");
  EXPECT_EQ(sceneErrorsOf("csg"),
            "t.sc:1:1: error: csg: expected union, intersection or difference but reached the "
            "end of the file\n"
            "t.sc:1:1: error: csg without matching end");
  const std::string closed =
      " (spheres, boxes, cylinders, capped cones, tori, blobs, meshes and csg blocks can)";
  EXPECT_EQ(sceneErrorsOf("csg union polygon 3  0 0 0  1 0 0  0 1 0" + operands + " end"),
            "t.sc:1:11: error: polygon: not a closed solid, so it cannot be an operand of csg" +
                closed);
  EXPECT_EQ(sceneErrorsOf("csg union\ncone 0 0 0 1 0 0 1 0" + operands + " end"),
            "t.sc:2:1: error: cone: not a closed solid, so it cannot be an operand of csg" +
                closed);
  EXPECT_EQ(sceneErrorsOf("csg union disc 0 0 0 0 0 1 1" + operands + " end"),
            "t.sc:1:11: error: disc: not a closed solid, so it cannot be an operand of csg" +
                closed);
  EXPECT_EQ(
      sceneErrorsOf("csg union quadric 1 1 1 0 0 0 0 0 0 -1 -2 -2 -2 2 2 2" + operands + " end"),
      "t.sc:1:11: error: quadric: not a closed solid, so it cannot be an operand of csg" + closed);
  EXPECT_EQ(sceneErrorsOf("csg union triangle 0 0 0 1 0 0 0 1 0" + operands + " end"),
            "t.sc:1:11: error: triangle: not a closed solid, so it cannot be an operand of csg" +
                closed);
  EXPECT_EQ(
      sceneErrorsOf("csg union ptriangle 0 0 0 0 0 1 1 0 0 0 0 1 0 1 0 0 0 1" + operands + " end"),
      "t.sc:1:11: error: ptriangle: not a closed solid, so it cannot be an operand of csg" +
          closed);
  // Closed shapes after an open one still count; capped cones are closed.
  EXPECT_EQ(sceneErrorsOf("csg union capped_cone 0 0 0 1 0 0 1 0 torus 0 0 0 0 0 1 1 0.2 end"), "");
  // push/pop and csg/end nest, each closed by its own word.
  EXPECT_EQ(sceneErrorsOf("csg union push" + operands + " end pop end"),
            "t.sc:1:46: error: end without matching csg or mesh (a push is open: close it with "
            "'pop' first)");
  EXPECT_EQ(sceneErrorsOf("push csg union" + operands + " pop end pop"),
            "t.sc:1:46: error: pop without matching push (a csg block is open: close it with "
            "'end' first)");
  EXPECT_EQ(sceneErrorsOf("csg union push" + operands + " pop end"), "");
  // Nesting is bounded: reading stops at the block past the limit.
  std::string deep;
  for (int i = 0; i < 1001; ++i)
    deep += "csg union ";
  EXPECT_EQ(sceneErrorsOf(deep), "t.sc:1:10001: error: csg: blocks nested more than 1000 deep");
  // Errors inside operands are reported as always, and the block read on.
  EXPECT_EQ(sceneErrorsOf("csg union sphere 0 0 0 -1" + operands + " end"),
            "t.sc:1:24: error: sphere: negative radius '-1'");
}

std::string loadErrorsOf(const std::filesystem::path& path) {
  try {
    loadScene(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Csg, BlocksBalanceWithinEachFile) {
  test::ScratchDir dir;
  test::writeFile(dir.path() / "open.sc", "csg union sphere 0 0 0 1\n");
  test::writeFile(dir.path() / "close.sc", "end\n");
  test::writeFile(dir.path() / "a.sc", "include open.sc\n");
  test::writeFile(dir.path() / "b.sc", "csg union sphere 0 0 0 1 sphere 1 0 0 1\n"
                                       "include close.sc\nend\n");
  EXPECT_EQ(loadErrorsOf(dir.path() / "a.sc"),
            (dir.path() / "open.sc").lexically_normal().string() +
                ":1:1: error: csg without matching end");
  EXPECT_EQ(loadErrorsOf(dir.path() / "b.sc"),
            (dir.path() / "close.sc").lexically_normal().string() +
                ":1:1: error: end without matching csg or mesh in this file (blocks and their end "
                "must balance within each file)");
}

// ---------------------------------------------------------------------------
// Writers

const char* const kDie = "surface 0.9 0.9 0.9  1 0 0  1 1\n"
                         "csg difference\n"
                         "  csg intersection\n"
                         "    push rotate 1 2 3 20 box -1 -1 -1 1 1 1 pop\n"
                         "    sphere 0 0 0 1.4\n"
                         "  end\n"
                         "  surface 0.1 0.1 0.1  1 0 0  1 1\n"
                         "  sphere 0 0 1.1 0.3\n"
                         "  push scale 1 2 1 sphere 1.1 0 0 0.2 pop\n"
                         "  torus 0 -1 0  0 1 0  0.5 0.1\n"
                         "  cylinder 0 -2 0  0 2 0  0.1\n"
                         "end\n"
                         "sphere 4 0 0 1\n";

TEST(Csg, WriterRoundTrip) {
  const Scene s = parseScene(kDie, "t.sc");
  std::ostringstream first;
  writeScene(first, s);
  EXPECT_NE(first.str().find("csg difference\n  csg intersection\n"), std::string::npos)
      << first.str();
  const Scene back = parseScene(first.str(), "back.sc");
  // (A turned box's angles may come back an ulp apart, as outside CSG.)
  ASSERT_EQ(back.csgOperands.size(), s.csgOperands.size());
  ASSERT_EQ(back.csgNodes.size(), s.csgNodes.size());
  EXPECT_EQ(back.material({kindOf<Sphere>, 0}), s.material({kindOf<Sphere>, 0}));
  // The same hits and records, ray for ray.
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 from(5 * u(rng), 5 * u(rng), 5 * u(rng));
    const Ray q = ray(from, Vec3(u(rng), u(rng), u(rng)) - from);
    double a = 0, b = 0;
    const bool ha = intersectPrimitive(s, kFirstCsg, q, Interval{}, a);
    ASSERT_EQ(ha, intersectPrimitive(back, kFirstCsg, q, Interval{}, b));
    if (!ha) continue;
    ++hits;
    EXPECT_NEAR(a, b, 1e-12 * (1 + a));
    const SurfacePoint pa = s.surfaceAt(kFirstCsg, q, a), pb = back.surfaceAt(kFirstCsg, q, b);
    expectCloseTo(pa.outward, pb.outward, 1e-9);
    EXPECT_EQ(s.materialAt(pa), back.materialAt(pb));
  }
  EXPECT_GT(hits, 50);
}

TEST(Csg, PovRayText) {
  const Scene s = parseScene(kHollow, "t.sc");
  std::ostringstream out;
  writePov(out, s);
  const std::string text = out.str();
  EXPECT_NE(text.find("difference {\n  box { <-1, -1, -1>, <1, 1, 1> material { Prism_M0 } }\n"
                      "  sphere { <0, 0, 1>, 0.5 material { Prism_M0 } }\n}\n"),
            std::string::npos)
      << text;
  const Scene nested = parseScene(
      "csg union sphere 0 0 0 1 csg intersection sphere 1 0 0 1 sphere 2 0 0 1 end end", "t.sc");
  std::ostringstream nestedOut;
  writePov(nestedOut, nested);
  EXPECT_NE(nestedOut.str().find("union {\n  sphere"), std::string::npos) << nestedOut.str();
  EXPECT_NE(nestedOut.str().find("  intersection {\n"), std::string::npos) << nestedOut.str();
}

} // namespace
} // namespace prism
