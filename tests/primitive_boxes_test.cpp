// The boxes the BVH is built over (core/accel/primitive_boxes.h): a long thin
// cone lying across the axes bounded slice by slice. The slice counts are
// checked against the box areas worked out in closed form here; the slices
// must cover every point of the cone; the budget must hold. That the BVH over
// them still gives brute force's answers is in accel_test.cpp.
#include "core/accel/bvh.h"
#include "core/accel/primitive_boxes.h"
#include "core/scene/scene_builder.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>

namespace prism {
namespace {

PrimitiveRef addCone(Scene& scene, const Cone& cone) { return SceneBuilder(scene).add(cone); }

bool sameBits(const Aabb& a, const Aabb& b) {
  for (int i = 0; i < 3; ++i)
    if (std::bit_cast<std::uint64_t>(a.lo[i]) != std::bit_cast<std::uint64_t>(b.lo[i]) ||
        std::bit_cast<std::uint64_t>(a.hi[i]) != std::bit_cast<std::uint64_t>(b.hi[i]))
      return false;
  return true;
}

TEST(ConeSlices, TheWholeHeightIsTheConesOwnBox) {
  const Cone cones[] = {
      makeCone(Vec3(0.1, 0.2, 0.3), 0.1, Vec3(0.7, -0.3, 1.9), 0.3),
      makeCone(Vec3(-5, 2, 1e3), 0.0, Vec3(4, 4, 4), 2.5),
      makeCone(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 1), 1.0, Mat3(2, 0.5, 0, 0, 1, 0.3, 0.1, 0, 3),
               Vec3(7, 8, 9)),
  };
  for (const Cone& c : cones)
    EXPECT_TRUE(sameBits(sliceBounds(c, 0.0, 1.0), c.bounds));
}

// The count chosen for a cylinder of radius r along a unit axis a, from the
// boxes' areas in closed form: a slice of length s reaches s |a_i| +
// 2 r sqrt(1 - a_i^2) along world axis i.
int expectedSlices(const Vec3& a, double length, double r) {
  const auto area = [&](int n) {
    Vec3 e;
    for (int i = 0; i < 3; ++i)
      e[i] = length / n * std::abs(a[i]) + 2.0 * r * std::sqrt(1.0 - a[i] * a[i]);
    return n * (e.x * e.y + e.y * e.z + e.z * e.x);
  };
  int n = 1;
  while (n < kMaxConeSlices && area(2 * n) <= 0.7 * area(n))
    n *= 2;
  return n;
}

TEST(ConeSlices, CountFollowsTheAreaTheSlicesSave) {
  // Along an axis, slicing saves nothing: one box.
  EXPECT_EQ(coneSliceCount(makeCone(Vec3(0, 0, 0), 0.05, Vec3(0, 0, 10), 0.05)), 1);
  EXPECT_EQ(expectedSlices(Vec3(0, 0, 1), 10.0, 0.05), 1);
  // Along the diagonal, thin: the most slices (each halving of the slices'
  // length halves the summed area while the radius is negligible).
  const Vec3 diagonal = glm::normalize(Vec3(1, 1, 1));
  EXPECT_EQ(coneSliceCount(makeCone(Vec3(0, 0, 0), 1e-4, Vec3(10, 10, 10), 1e-4)), kMaxConeSlices);
  // In between, the count the closed form gives.
  for (const double r : {0.01, 0.045, 0.2, 1.0, 5.0}) {
    const double length = std::sqrt(3.0);
    const int expected = expectedSlices(diagonal, length, r);
    EXPECT_EQ(coneSliceCount(makeCone(Vec3(0, 0, 0), r, Vec3(1, 1, 1), r)), expected) << r;
  }
  EXPECT_EQ(expectedSlices(diagonal, std::sqrt(3.0), 0.045), 4);
  EXPECT_EQ(expectedSlices(diagonal, std::sqrt(3.0), 5.0), 1);
}

TEST(ConeSlices, SlicesCoverEveryPointOfTheCone) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  for (int k = 0; k < 50; ++k) {
    Scene scene;
    const Vec3 base(10 * u(rng), 10 * u(rng), 10 * u(rng));
    const Vec3 apex = base + 5.0 * Vec3(u(rng), u(rng), u(rng));
    const double rb = 0.2 * unit(rng), ra = 0.2 * unit(rng);
    if (coneProblem(base, rb, apex, ra)) continue;
    addCone(scene, makeCone(base, rb, apex, ra));
    const std::vector<BoxedPrimitive> boxes = hierarchyBoxes(scene, 100);
    ASSERT_GE(boxes.size(), 1u);
    // Points on the surface: the end circles' frame from the axis.
    const Vec3 w = glm::normalize(apex - base);
    const Vec3 x =
        glm::normalize(glm::cross(w, std::abs(w.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 y = glm::cross(w, x);
    for (int i = 0; i < 400; ++i) {
      const double z = i == 0 ? 0.0 : i == 1 ? 1.0 : unit(rng);
      const double angle = 2 * std::numbers::pi * unit(rng);
      const double r = (1 - z) * rb + z * ra;
      const Vec3 p = base + z * (apex - base) + r * (std::cos(angle) * x + std::sin(angle) * y);
      bool inside = false;
      for (const BoxedPrimitive& b : boxes) {
        Aabb padded = b.box;
        padded.pad(); // as the BVH does: round-off of p itself
        inside = inside || (glm::all(glm::lessThanEqual(padded.lo, p)) &&
                            glm::all(glm::lessThanEqual(p, padded.hi)));
      }
      EXPECT_TRUE(inside) << "cone " << k << " z " << z;
    }
  }
}

TEST(ConeSlices, BudgetBoundsTheExtraBoxes) {
  Scene scene;
  for (int i = 0; i < 20; ++i)
    addCone(scene, makeCone(Vec3(i, 0, 0), 1e-3, Vec3(i + 10, 10, 10), 1e-3));
  // No budget: one box per primitive, its own.
  const std::vector<BoxedPrimitive> plain = hierarchyBoxes(scene, 0);
  ASSERT_EQ(plain.size(), 20u);
  for (std::uint32_t i = 0; i < 20; ++i) {
    EXPECT_EQ(plain[i].primitive, (PrimitiveRef{kindOf<Cone>, i}));
    EXPECT_TRUE(sameBits(plain[i].box, scene.shapes<Cone>()[i].bounds));
  }
  // Some: never more than it allows, every cone still there; slices of equal
  // height, so each cone has a power of two of them.
  const std::vector<BoxedPrimitive> some = hierarchyBoxes(scene, 37);
  EXPECT_LE(some.size(), 20u + 37u);
  std::vector<int> perCone(20, 0);
  for (const BoxedPrimitive& b : some)
    ++perCone[b.primitive.index];
  for (const int n : perCone)
    EXPECT_TRUE(n >= 1 && std::has_single_bit(unsigned(n))) << n;
  // Plenty: every cone gets what it asks for.
  EXPECT_EQ(hierarchyBoxes(scene, 1000).size(), 20u * kMaxConeSlices);
}

TEST(ConeSlices, BvhStaysWithin64BytesPerPrimitive) {
  // The worst case for the slices: every primitive a thin diagonal bar.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Scene scene;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 c(50 * u(rng), 50 * u(rng), 50 * u(rng));
    const Vec3 d(u(rng), u(rng), u(rng));
    addCone(scene, makeCone(c - d, 0.01, c + d, 0.01));
  }
  const Bvh bvh(scene);
  EXPECT_LE(double(bvh.memoryBytes()) / double(scene.primitiveCount()), 64.0);
  // Here the slices would pass the bound: the plain hierarchy instead.
  EXPECT_EQ(bvh.referenceCount(), scene.primitiveCount());
}

TEST(ConeSlices, BarsAmongBallsAreSliced) {
  // A jacks scene in miniature: the bars sliced, the memory within bounds.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  Scene scene;
  for (int i = 0; i < 1000; ++i) { // a bar with a ball on each end
    const Vec3 c(20 * u(rng), 20 * u(rng), 20 * u(rng));
    const Vec3 d(u(rng), u(rng), u(rng));
    addCone(scene, makeCone(c - d, 0.045, c + d, 0.045));
    SceneBuilder(scene).add(Sphere{c - d, 0.1, 0, {}});
    SceneBuilder(scene).add(Sphere{c + d, 0.1, 0, {}});
  }
  const Bvh bvh(scene);
  EXPECT_GT(bvh.referenceCount(), scene.primitiveCount());
  EXPECT_LE(double(bvh.memoryBytes()) / double(scene.primitiveCount()), 64.0);
  // Unbounded, the worst case above takes at most twice that: the slices at
  // most double the references.
}

TEST(ConeSlices, UnboundedTheyAtMostDoubleTheMemory) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Scene scene;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 c(50 * u(rng), 50 * u(rng), 50 * u(rng));
    const Vec3 d(u(rng), u(rng), u(rng));
    addCone(scene, makeCone(c - d, 0.01, c + d, 0.01));
  }
  const Bvh plain(scene), unbounded(scene, Bvh::Options{0});
  EXPECT_LE(unbounded.referenceCount(), scene.primitiveCount() * 3 / 2);
  EXPECT_GT(unbounded.referenceCount(), scene.primitiveCount());
  EXPECT_LE(unbounded.memoryBytes(), 2 * plain.memoryBytes());
}

} // namespace
} // namespace prism
