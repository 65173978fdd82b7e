// The list of shape kinds and what is generated from it: a kind must provide
// the whole shape interface to be listed; names, flatness, storage, counts and
// the dispatch follow the list, so no kind can be left out of any of them.
#include "core/scene/scene.h"
#include "core/shapes/crossings.h"
#include "core/shapes/shape_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace prism {
namespace {

// A kind made up for this test: the interface, and nothing else.
struct TestBox {
  static constexpr const char* kName = "testbox";
  static constexpr bool kFlat = false;
  Aabb box;
  std::uint32_t material = 0;
  Origin origin;
};
bool intersect(const TestBox&, const ShapeArrays&, const Ray&, Interval, double&) { return false; }
Vec3 outwardNormal(const TestBox&, const ShapeArrays&, const Vec3&) { return Vec3(0, 0, 1); }
Vec2 uvAt(const TestBox&, const ShapeArrays&, const Vec3& p) { return {p.x, p.y}; }
Aabb boundsOf(const TestBox& b, const ShapeArrays&) { return b.box; }
double roundoffScale(const TestBox& b, const ShapeArrays&) {
  return std::max(maxAbsComponent(b.box.lo), maxAbsComponent(b.box.hi));
}

// The same without bounds: not a shape kind.
struct Unbounded {
  static constexpr const char* kName = "unbounded";
  static constexpr bool kFlat = false;
  std::uint32_t material = 0;
  Origin origin;
};
bool intersect(const Unbounded&, const ShapeArrays&, const Ray&, Interval, double&) {
  return false;
}
Vec3 outwardNormal(const Unbounded&, const ShapeArrays&, const Vec3&) { return Vec3(0, 0, 1); }
Vec2 uvAt(const Unbounded&, const ShapeArrays&, const Vec3&) { return Vec2(0.0); }
[[maybe_unused]] double roundoffScale(const Unbounded&, const ShapeArrays&) { return 0.0; }

// With bounds but without surface coordinates: not a shape kind either.
struct Uncharted {
  static constexpr const char* kName = "uncharted";
  static constexpr bool kFlat = false;
  std::uint32_t material = 0;
  Origin origin;
};
bool intersect(const Uncharted&, const ShapeArrays&, const Ray&, Interval, double&) {
  return false;
}
Vec3 outwardNormal(const Uncharted&, const ShapeArrays&, const Vec3&) { return Vec3(0, 0, 1); }
[[maybe_unused]] Aabb boundsOf(const Uncharted&, const ShapeArrays&) { return Aabb{}; }
[[maybe_unused]] double roundoffScale(const Uncharted&, const ShapeArrays&) { return 0.0; }

static_assert(ShapeKind<TestBox>);
static_assert(!ShapeKind<Unbounded>);
static_assert(!ShapeKind<Uncharted>);
// The kinds that bound a solid list every crossing; the open ones do not.
static_assert(ClosedShape<Sphere> && ClosedShape<Ellipsoid> && ClosedShape<Torus> &&
              ClosedShape<Box> && ClosedShape<CappedCone> && ClosedShape<Csg> && ClosedShape<Blob>);
static_assert(!ClosedShape<Polygon> && !ClosedShape<Cone> && !ClosedShape<Triangle> &&
              !ClosedShape<Disc> && !ClosedShape<Quadric>);
static_assert(ShapeKind<Sphere> && ShapeKind<Ellipsoid> && ShapeKind<Polygon> && ShapeKind<Cone> &&
              ShapeKind<Triangle> && ShapeKind<Torus> && ShapeKind<Box> && ShapeKind<Disc> &&
              ShapeKind<CappedCone> && ShapeKind<Quadric> && ShapeKind<Csg> && ShapeKind<Blob>);

// A list with the made-up kind appended: its name and flatness come along.
using Extended = ShapeList<Sphere, Ellipsoid, Polygon, Cone, Triangle, Torus, Box, Disc, CappedCone,
                           Quadric, Csg, Blob, TestBox>;
static_assert(Extended::size == kShapeKindCount + 1);
static_assert(std::is_same_v<Extended::At<kShapeKindCount>, TestBox>);

TEST(ShapeKinds, NamesAndFlatnessFollowTheList) {
  EXPECT_STREQ(Extended::names[kShapeKindCount], "testbox");
  EXPECT_FALSE(Extended::flat[kShapeKindCount]);
  // The real list: names as messages print them, flat exactly for the planar kinds.
  const std::string names[] = {"sphere", "ellipsoid", "polygon",     "cone",    "triangle", "torus",
                               "box",    "disc",      "capped_cone", "quadric", "csg",      "blob"};
  ASSERT_EQ(std::size(names), kShapeKindCount);
  for (std::size_t i = 0; i < kShapeKindCount; ++i)
    EXPECT_EQ(kindName(PrimitiveKind(i)), names[i]);
  EXPECT_TRUE(isFlat(kindOf<Polygon>));
  EXPECT_TRUE(isFlat(kindOf<Triangle>));
  EXPECT_TRUE(isFlat(kindOf<Disc>));
  EXPECT_FALSE(isFlat(kindOf<Sphere>) || isFlat(kindOf<Ellipsoid>) || isFlat(kindOf<Cone>) ||
               isFlat(kindOf<Torus>) || isFlat(kindOf<Box>) || isFlat(kindOf<CappedCone>) ||
               isFlat(kindOf<Quadric>) || isFlat(kindOf<Csg>) || isFlat(kindOf<Blob>));
}

// The dispatch reaches every kind: one primitive of each, each visited as its
// own type, and allPrimitives lists each once.
TEST(ShapeKinds, TheDispatchReachesEveryKind) {
  Scene scene;
  scene.shapes<Sphere>().push_back({});
  scene.shapes<Ellipsoid>().push_back({});
  scene.shapes<Polygon>().push_back({});
  scene.shapes<Cone>().push_back({});
  scene.shapes<Triangle>().push_back({});
  scene.shapes<Torus>().push_back({});
  scene.shapes<Box>().push_back({});
  scene.shapes<Disc>().push_back({});
  scene.shapes<CappedCone>().push_back({});
  scene.shapes<Quadric>().push_back({});
  scene.shapes<Csg>().push_back({});
  scene.shapes<Blob>().push_back({});
  ASSERT_EQ(scene.primitiveCount(), kShapeKindCount);
  std::set<std::string> visited;
  for (const PrimitiveRef& ref : scene.allPrimitives()) {
    const std::string name = scene.visit(
        ref, [](const auto& shape) { return std::string(std::decay_t<decltype(shape)>::kName); });
    EXPECT_EQ(name, kindName(ref.kind));
    visited.insert(name);
  }
  EXPECT_EQ(visited.size(), kShapeKindCount);
}

} // namespace
} // namespace prism
