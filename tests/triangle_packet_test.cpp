// The BVH's test of up to four triangles at once (core/accel/triangle_packet.h)
// against the one-triangle test of core/shapes/triangle.cpp: each lane must
// answer exactly as the scalar test, hit or miss and t bit for bit, on rays
// through vertices and edges, in the triangle's plane, along the axes, with
// ties between the largest direction components, over narrow ranges, at
// scales from 1e-9 to 1e9 and far from the origin; in SSE lanes and, on a
// processor with AVX, in AVX lanes.
#include "core/accel/triangle_packet.h"
#include "core/shapes/triangle.h"

#include "test_expect.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstring>
#include <random>
#include <vector>

namespace prism {
namespace {

using test::randomUnit;

struct Answer {
  unsigned hits;
  double t[4];
};

Answer sseHits(const Ray& ray, const TriangleCorners& c, unsigned used, Interval range) {
  Answer a;
  a.hits = TrianglePacketTest<lanes::Lanes>(ray).hits(c, used, range, a.t);
  return a;
}

#if PRISM_BVH_AVX
// Compiled for AVX, as Bvh::walkAvx is; called only where the processor has it.
[[gnu::target("avx"), gnu::flatten]] Answer avxHits(const Ray& ray, const TriangleCorners& c,
                                                    unsigned used, Interval range) {
  Answer a;
  a.hits = TrianglePacketTest<lanes::AvxLanes>(ray).hits(c, used, range, a.t);
  return a;
}
bool hasAvx() { return __builtin_cpu_supports("avx"); }
#else
bool hasAvx() { return false; }
#endif

struct Counts {
  int packets = 0, lanes = 0, hits = 0, avxPackets = 0;
};

// A packet of 1 to 4 of `triangles`, the ray's target `aimed` and its
// neighbours in the list or others (lanes past the count repeat the first),
// each lane's answer against the scalar test's.
void expectLanesMatchScalar(const std::vector<Vec3>& vertices,
                            const std::vector<Triangle>& triangles, std::size_t aimed,
                            const Ray& ray, Interval range, std::mt19937& rng, Counts& counts) {
  std::uniform_int_distribution<std::size_t> pick(0, triangles.size() - 1);
  std::uniform_int_distribution<int> size(1, 4);
  const int count = size(rng);
  const std::size_t neighbours[4] = {aimed, aimed + 1, aimed + triangles.size() - 1, pick(rng)};
  std::array<std::size_t, 4> which{};
  TriangleCorners corners;
  for (int lane = 0; lane < 4; ++lane) {
    which[std::size_t(lane)] =
        lane < count ? neighbours[std::size_t(lane)] % triangles.size() : which[0];
    for (int k = 0; k < 3; ++k)
      corners.v[lane][k] = &vertices[triangles[which[std::size_t(lane)]].vertex[std::size_t(k)]];
  }
  const unsigned used = (1u << count) - 1;
  std::vector<Answer> answers{sseHits(ray, corners, used, range)};
#if PRISM_BVH_AVX
  if (hasAvx()) {
    answers.push_back(avxHits(ray, corners, used, range));
    ++counts.avxPackets;
  }
#endif
  ++counts.packets;
  for (int lane = 0; lane < count; ++lane) {
    double t = 0.0;
    const bool hit = intersect(triangles[which[std::size_t(lane)]], vertices.data(), ray, range, t);
    counts.lanes += 1;
    counts.hits += hit;
    for (const Answer& a : answers) {
      EXPECT_EQ((a.hits >> lane & 1u) != 0, hit)
          << "lane " << lane << " of " << count << (&a == &answers[0] ? " (SSE)" : " (AVX)");
      if (hit) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.t[lane]), std::bit_cast<std::uint64_t>(t));
      }
    }
  }
  for (const Answer& a : answers)
    EXPECT_EQ(a.hits & ~used, 0u); // no answer from an unused lane
}

TEST(TrianglePacket, EachLaneAnswersAsTheScalarTest) {
  std::mt19937 rng(1207);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  std::uniform_int_distribution<int> axis(0, 2);
  Counts counts;
  const double scales[] = {1.0, 1e-9, 1e9};
  const double offsets[] = {0.0, 1e5, -3e12};
  for (const double scale : scales)
    for (const double offset : offsets) {
      // A small mesh over shared vertices (a grid, so edges are shared) and
      // some loose triangles.
      std::vector<Vec3> vertices;
      std::vector<Triangle> triangles;
      const Vec3 centre(offset, 0.5 * offset, -offset);
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j)
          vertices.push_back(centre + scale * Vec3(i, 0.3 * u(rng), j));
      for (std::uint32_t i = 0; i < 4; ++i)
        for (std::uint32_t j = 0; j < 4; ++j) {
          const std::uint32_t a = i * 5 + j;
          Triangle t1, t2;
          t1.vertex = {a, a + 6, a + 5};
          t2.vertex = {a, a + 1, a + 6};
          triangles.push_back(t1);
          triangles.push_back(t2);
        }
      for (std::uint32_t k = 0; k < 8; ++k) {
        const Vec3 a = centre + scale * 4.0 * Vec3(unit(rng), u(rng), unit(rng));
        const auto first = std::uint32_t(vertices.size());
        vertices.insert(vertices.end(),
                        {a, a + scale * randomUnit(rng), a + scale * randomUnit(rng)});
        Triangle t;
        t.vertex = {first, first + 1, first + 2};
        triangles.push_back(t);
      }
      std::uniform_int_distribution<std::size_t> pickTriangle(0, triangles.size() - 1);
      std::uniform_int_distribution<std::size_t> pickCorner(0, 2);
      for (int i = 0; i < 3000; ++i) {
        const Vec3 from = centre + scale * Vec3(2 + 4 * u(rng), 3 * u(rng), 2 + 4 * u(rng));
        const std::size_t aimed = pickTriangle(rng);
        const std::size_t k = pickCorner(rng);
        const Vec3 a = vertices[triangles[aimed].vertex[k]];
        const Vec3 b = vertices[triangles[aimed].vertex[(k + 1) % 3]];
        const Vec3 c = vertices[triangles[aimed].vertex[(k + 2) % 3]];
        Vec3 to = a; // a vertex, an edge's middle, a point inside, or beside
        if (i % 4 == 1) to = 0.5 * (a + b);
        if (i % 4 == 2) to = a + 0.5 * unit(rng) * (b - a) + 0.5 * unit(rng) * (c - a);
        if (i % 4 == 3) to = a + unit(rng) * (b - a) - 0.01 * unit(rng) * (c - a);
        Vec3 dir = to == from ? randomUnit(rng) : glm::normalize(to - from);
        if (i % 9 == 4) dir[axis(rng)] = 0.0; // in an axis plane
        if (i % 9 == 5) {                     // two largest components equal in size
          const int big = axis(rng);
          dir[(big + 1) % 3] = (u(rng) < 0 ? -1 : 1) * std::abs(dir[big]);
        }
        if (i % 9 == 6) { // along an axis
          dir = Vec3(0.0);
          dir[axis(rng)] = u(rng) < 0 ? -1.0 : 1.0;
        }
        if (i % 9 == 7) dir.y = 0.0; // in the grid's plane, roughly
        if (glm::dot(dir, dir) == 0.0) continue;
        dir = glm::normalize(dir);
        Interval range;
        if (i % 5 == 1) range.max = glm::length(to - from) * (0.999 + 0.002 * unit(rng));
        if (i % 5 == 2) range.min = glm::length(to - from) * (0.999 + 0.002 * unit(rng));
        expectLanesMatchScalar(vertices, triangles, aimed, Ray{from, dir}, range, rng, counts);
        // From a vertex: t of 0 and rays in the surface.
        if (i % 6 == 0)
          expectLanesMatchScalar(vertices, triangles, aimed, Ray{a, dir}, range, rng, counts);
      }
    }
  EXPECT_GT(counts.lanes, 50000);
  EXPECT_GT(counts.hits, 5000);
  EXPECT_EQ(counts.avxPackets, hasAvx() ? counts.packets : 0);
}

// NaN and infinite rays hit nothing, in every lane.
TEST(TrianglePacket, NonFiniteRaysHitNothing) {
  const std::vector<Vec3> vertices{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  TriangleCorners corners;
  for (auto& lane : corners.v)
    for (int k = 0; k < 3; ++k)
      lane[k] = &vertices[std::size_t(k)];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Ray rays[] = {{Vec3(0.2, 0.2, nan), Vec3(0, 0, -1)},
                      {Vec3(0.2, 0.2, 1), Vec3(nan, 0, -1)},
                      {Vec3(0.2, 0.2, inf), Vec3(0, 0, -1)}};
  for (const Ray& ray : rays) {
    EXPECT_EQ(sseHits(ray, corners, 0xf, Interval{}).hits, 0u);
#if PRISM_BVH_AVX
    if (hasAvx()) {
      EXPECT_EQ(avxHits(ray, corners, 0xf, Interval{}).hits, 0u);
    }
#endif
  }
  // The same triangle from a finite ray: hit in all four lanes.
  EXPECT_EQ(sseHits(Ray{Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)}, corners, 0xf, Interval{}).hits, 0xfu);
}

} // namespace
} // namespace prism
