// Blobs as CSG operands (core/shapes/csg.h): a box minus a blob and a blob
// intersected with a box, against crossings and normals computed by hand. The
// blob has one component of radius 2 and strength 1 at the origin with
// threshold 9/16, so its surface is the sphere of radius
// 2 sqrt(1 - sqrt(9/16)) = 2 sqrt(1/4) = 1 (blob.h); a line at distance a
// from the centre meets it at +-sqrt(1 - a^2). Also the .sc block and both
// writers.
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/shapes/crossings.h"
#include "core/shapes/shape_kinds.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace prism {
namespace {

using test::expectCloseTo;

const PrimitiveRef kFirstCsg{kindOf<Csg>, 0};
// The blob's root finder polishes its roots to about this (blob_test).
constexpr double kTol = 1e-12;

const char* const kBoxMinusBlob = "csg difference\n"
                                  "  box -2 -2 -2 2 2 2\n"
                                  "  blob 0.5625 1  0 0 0  2 1\n"
                                  "end\n";

const char* const kBlobAndBox = "csg intersection\n"
                                "  blob 0.5625 1  0 0 0  2 1\n"
                                "  box 0 -2 0.5 2 2 3\n"
                                "end\n";

std::vector<Crossing> crossingsOf(const Scene& s, const Ray& r) {
  std::vector<Crossing> out;
  appendCrossings(s.shapes<Csg>().at(0), s.arrays(), r, Interval{}, out);
  return out;
}

struct Expected {
  double t;
  bool entering;
  Vec3 outward;
};

void expectCrossings(const Scene& s, const Ray& r, const std::vector<Expected>& want) {
  const std::vector<Crossing> got = crossingsOf(s, r);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].t, want[i].t, kTol) << i;
    EXPECT_EQ(got[i].entering, want[i].entering) << i;
    const SurfacePoint p = s.surfaceAt(kFirstCsg, r, got[i].t);
    expectCloseTo(p.outward, want[i].outward, 1e-9);
  }
  // The nearest hit is the first crossing.
  double t = 0;
  ASSERT_TRUE(intersectPrimitive(s, kFirstCsg, r, Interval{}, t));
  EXPECT_NEAR(t, want.front().t, kTol);
}

TEST(CsgBlob, BoxMinusBlob) {
  const Scene s = parseScene(kBoxMinusBlob, "t.sc");
  ASSERT_EQ(s.shapes<Csg>().size(), 1u);
  EXPECT_EQ(s.shapes<Blob>().size(), 0u); // an operand, not a primitive
  EXPECT_EQ(s.blobComponents.size(), 1u);
  // Along the axis: the box's face at z = -2, the hollow from z = -1 to 1
  // (its surface turned inside out), the far face.
  expectCrossings(
      s, Ray{{0, 0, -5}, {0, 0, 1}},
      {{3, true, {0, 0, -1}}, {4, false, {0, 0, 1}}, {6, true, {0, 0, -1}}, {7, false, {0, 0, 1}}});
  // At x = 0.6 the hollow spans z = -0.8 .. 0.8.
  expectCrossings(s, Ray{{0.6, 0, -5}, {0, 0, 1}},
                  {{3, true, {0, 0, -1}},
                   {4.2, false, {-0.6, 0, 0.8}},
                   {5.8, true, {-0.6, 0, -0.8}},
                   {7, false, {0, 0, 1}}});
  // Outside the hollow the box is whole.
  expectCrossings(s, Ray{{1.5, 0, -5}, {0, 0, 1}}, {{3, true, {0, 0, -1}}, {7, false, {0, 0, 1}}});
}

TEST(CsgBlob, BlobIntersectedWithABox) {
  const Scene s = parseScene(kBlobAndBox, "t.sc");
  // At x = 0.6 the ball spans z = -0.8 .. 0.8 and the box starts at z = 0.5.
  expectCrossings(s, Ray{{0.6, 0, -5}, {0, 0, 1}},
                  {{5.5, true, {0, 0, -1}}, {5.8, false, {0.6, 0, 0.8}}});
  // Along x at z = 0.6: the ball spans x = -0.8 .. 0.8, the box x >= 0.
  expectCrossings(s, Ray{{-5, 0, 0.6}, {1, 0, 0}},
                  {{5, true, {-1, 0, 0}}, {5.8, false, {0.8, 0, 0.6}}});
  // Below the box's bottom the ball alone: nothing.
  double t = 0;
  EXPECT_FALSE(intersectPrimitive(s, kFirstCsg, Ray{{0.2, 0, 0.3}, {1, 0, 0}}, Interval{}, t));
  // The bounds are the box's and the ball's overlap.
  const Aabb b = s.shapes<Csg>()[0].bounds;
  EXPECT_GE(b.lo.z, 0.5 - 1e-12);
  EXPECT_LE(b.hi.z, 2.0 + 1e-12);
}

TEST(CsgBlob, WritersRoundTrip) {
  // A stretched blob is written through its frame, inside push/pop.
  const std::string text = std::string(kBoxMinusBlob) +
                           "csg union sphere 5 0 0 1 push scale 1 2 1\n"
                           "  blob 0.5625 2  5 0 0  2 1  5 0.5 0  1 1 pop end\n";
  const Scene s = parseScene(text, "t.sc");
  std::ostringstream sc;
  writeScene(sc, s);
  EXPECT_NE(sc.str().find("  blob 0.5625 1\n"), std::string::npos) << sc.str();
  const Scene back = parseScene(sc.str(), "back.sc");
  ASSERT_EQ(back.shapes<Csg>().size(), 2u);
  ASSERT_EQ(back.csgOperands.size(), s.csgOperands.size());
  for (const Vec3 from : {Vec3(0.6, 0, -5), Vec3(5.3, -5, 0.1)}) {
    const Ray r{from, from.x < 1 ? Vec3(0, 0, 1) : Vec3(0, 1, 0)};
    const PrimitiveRef ref{kindOf<Csg>, from.x < 1 ? 0u : 1u};
    double a = 0, b = 0;
    ASSERT_TRUE(intersectPrimitive(s, ref, r, Interval{}, a));
    ASSERT_TRUE(intersectPrimitive(back, ref, r, Interval{}, b));
    EXPECT_NEAR(a, b, kTol);
  }
  std::ostringstream pov;
  writePov(pov, s);
  EXPECT_NE(pov.str().find("difference {\n  box { <-2, -2, -2>, <2, 2, 2> material { Prism_M0 } "
                           "}\n  blob { threshold 0.5625\n  sphere { <0, 0, 0>, 2, strength 1 }\n"),
            std::string::npos)
      << pov.str();
}

} // namespace
} // namespace prism
