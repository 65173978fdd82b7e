// The BVH's tests of up to four triangles or polygons at once
// (core/accel/packets.h) against the one-primitive tests of
// core/shapes/triangle.cpp and core/shapes/polygon.cpp: each lane must answer
// exactly as the scalar test, hit or miss and t bit for bit, on rays through
// vertices and edges, in the primitives' plane, along the axes, with ties
// between the largest direction components, over narrow ranges, at scales
// from 1e-9 to 1e9 and far from the origin; in SSE lanes and, on a
// processor with AVX, in AVX lanes.
#include "core/accel/packets.h"
#include "core/shapes/polygon.h"
#include "core/shapes/triangle.h"

#include "test_expect.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <type_traits>
#include <vector>

namespace prism {
namespace {

using test::randomUnit;

struct Answer {
  unsigned hits;
  double t[4];
};

template <class Corners>
Answer sseHits(const Ray& ray, const Corners& c, unsigned used, Interval range) {
  Answer a;
  a.hits = PacketTest<lanes::Lanes>(ray).hits(c, used, range, a.t);
  return a;
}

#if PRISM_BVH_AVX
// Compiled for AVX, as Bvh::walkAvx is; called only where the processor has it.
template <class Corners>
[[gnu::target("avx"), gnu::flatten]] Answer avxHits(const Ray& ray, const Corners& c, unsigned used,
                                                    Interval range) {
  Answer a;
  a.hits = PacketTest<lanes::AvxLanes>(ray).hits(c, used, range, a.t);
  return a;
}
bool hasAvx() { return __builtin_cpu_supports("avx"); }
#else
bool hasAvx() { return false; }
#endif

// Shapes of one kind over one array of vertices, as a scene stores them.
template <class Kind, class Corners> struct ShapeSet {
  std::vector<Vec3> vertices;
  std::vector<Kind> shapes;

  ShapeArrays arrays() const {
    ShapeArrays a;
    a.meshVertices = vertices;    // of triangles
    a.polygonVertices = vertices; // of polygons
    return a;
  }
  // The data a hierarchy stores for a packet of the shapes which[0, count),
  // followed by values no lane may be influenced by (a lane past `count`
  // reads them).
  struct Packet {
    std::vector<double> data;
    std::uint32_t stride = 0;
    std::uint32_t vertices = 0; // of polygons

    Corners corners() const {
      if constexpr (std::is_same_v<Corners, TriangleCorners>) {
        return {data.data(), stride};
      } else {
        return {data.data(), stride, vertices};
      }
    }
  };
  Packet packet(const std::array<std::size_t, 4>& which, int count) const {
    const Kind* lanes[4];
    for (int lane = 0; lane < count; ++lane)
      lanes[lane] = &shapes[which[std::size_t(lane)]];
    Packet p;
    p.stride = std::uint32_t(count);
    const std::span<const Kind* const> used(lanes, std::size_t(count));
    if constexpr (std::is_same_v<Kind, Triangle>) {
      appendPacket(used, arrays(), p.data);
    } else {
      p.vertices = appendPacket(used, arrays(), p.data);
    }
    static_assert(kPacketPadding == 3);
    const double inf = std::numeric_limits<double>::infinity();
    p.data.insert(p.data.end(), {std::numeric_limits<double>::quiet_NaN(), inf, -1e300});
    return p;
  }
  bool scalar(std::size_t i, const Ray& ray, Interval range, double& t) const {
    return intersect(shapes[i], arrays(), ray, range, t);
  }
};

// Triangles over shared vertices.
struct TriangleSet : ShapeSet<Triangle, TriangleCorners> {
  void add(const std::vector<std::uint32_t>& corners) {
    Triangle t;
    t.vertex = {corners[0], corners[1], corners[2]};
    shapes.push_back(t);
  }
  std::vector<Vec3> corners(std::size_t i) const {
    return {vertices[shapes[i].vertex[0]], vertices[shapes[i].vertex[1]],
            vertices[shapes[i].vertex[2]]};
  }
};

// Polygons of three to eight vertices tested in the ray's frame, each with
// vertices of its own.
struct PolygonSet : ShapeSet<Polygon, PolygonCorners> {
  void add(const std::vector<Vec3>& corners) {
    Polygon p = makePolygon(corners);
    ASSERT_TRUE(p.rayFrameTest);
    p.firstVertex = std::uint32_t(vertices.size());
    vertices.insert(vertices.end(), corners.begin(), corners.end());
    shapes.push_back(p);
  }
  std::vector<Vec3> corners(std::size_t i) const {
    const Polygon& p = shapes[i];
    return {vertices.begin() + p.firstVertex, vertices.begin() + p.firstVertex + p.vertexCount};
  }
};

struct Counts {
  int packets = 0, lanes = 0, hits = 0, avxPackets = 0;
};

// A packet of 1 to 4 of the set's shapes, the ray's target `aimed` and its
// neighbours in the list or others (stored as a hierarchy stores a packet of that
// many: lanes past the count read other values),
// each lane's answer against the scalar test's.
template <class Set>
void expectLanesMatchScalar(const Set& set, std::size_t aimed, const Ray& ray, Interval range,
                            std::mt19937& rng, Counts& counts) {
  const std::size_t size = set.shapes.size();
  std::uniform_int_distribution<std::size_t> pick(0, size - 1);
  std::uniform_int_distribution<int> lanesOf(1, 4);
  const int count = lanesOf(rng);
  const std::size_t near[4] = {aimed, aimed + 1, aimed + size - 1, pick(rng)};
  std::array<std::size_t, 4> which{};
  for (int lane = 0; lane < 4; ++lane)
    which[std::size_t(lane)] = lane < count ? near[lane] % size : which[0];
  const auto packet = set.packet(which, count);
  const auto corners = packet.corners();
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
    const bool hit = set.scalar(which[std::size_t(lane)], ray, range, t);
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

// Rays at the set's shapes, from everywhere around `centre` (about `scale`
// away): at a vertex, an edge's middle, a point inside or just beside one;
// some in axis planes, along axes, with two largest components equal, or
// from a vertex itself (t of 0, and rays in the surface).
template <class Set>
void expectLanesMatchScalarAround(const Set& set, const Vec3& centre, double scale,
                                  std::mt19937& rng, Counts& counts) {
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  std::uniform_int_distribution<int> axis(0, 2);
  std::uniform_int_distribution<std::size_t> pickShape(0, set.shapes.size() - 1);
  for (int i = 0; i < 3000; ++i) {
    const Vec3 from = centre + scale * Vec3(2 + 4 * u(rng), 3 * u(rng), 2 + 4 * u(rng));
    const std::size_t aimed = pickShape(rng);
    const std::vector<Vec3> v = set.corners(aimed);
    std::uniform_int_distribution<std::size_t> pickCorner(0, v.size() - 1);
    const std::size_t k = pickCorner(rng);
    const Vec3 a = v[k], b = v[(k + 1) % v.size()], c = v[(k + 2) % v.size()];
    Vec3 to = a;
    if (i % 4 == 1) to = 0.5 * (a + b);
    if (i % 4 == 2) to = a + 0.5 * unit(rng) * (b - a) + 0.5 * unit(rng) * (c - a);
    if (i % 4 == 3) to = a + unit(rng) * (b - a) - 0.01 * unit(rng) * (c - a);
    Vec3 dir = to == from ? randomUnit(rng) : glm::normalize(to - from);
    if (i % 9 == 4) dir[axis(rng)] = 0.0;
    if (i % 9 == 5) {
      const int big = axis(rng);
      dir[(big + 1) % 3] = (u(rng) < 0 ? -1 : 1) * std::abs(dir[big]);
    }
    if (i % 9 == 6) {
      dir = Vec3(0.0);
      dir[axis(rng)] = u(rng) < 0 ? -1.0 : 1.0;
    }
    if (i % 9 == 7) dir.y = 0.0; // near the grids' plane
    if (glm::dot(dir, dir) == 0.0) continue;
    dir = glm::normalize(dir);
    Interval range;
    if (i % 5 == 1) range.max = glm::length(to - from) * (0.999 + 0.002 * unit(rng));
    if (i % 5 == 2) range.min = glm::length(to - from) * (0.999 + 0.002 * unit(rng));
    expectLanesMatchScalar(set, aimed, Ray{from, dir}, range, rng, counts);
    if (i % 6 == 0) expectLanesMatchScalar(set, aimed, Ray{a, dir}, range, rng, counts);
  }
}

// A set built by `build` (set, scale, centre, rng) at scales from 1e-9 to
// 1e9, at and far from the origin, tested with rays all around it.
template <class Set, class Build>
void expectLanesMatchScalarEverywhere(unsigned seed, Build build) {
  std::mt19937 rng(seed);
  Counts counts;
  for (const double scale : {1.0, 1e-9, 1e9})
    for (const double offset : {0.0, 1e5, -3e12}) {
      const Vec3 centre(offset, 0.5 * offset, -offset);
      Set set;
      build(set, scale, centre, rng);
      expectLanesMatchScalarAround(set, centre, scale, rng, counts);
    }
  EXPECT_GT(counts.lanes, 60000);
  EXPECT_GT(counts.hits, 5000);
  EXPECT_EQ(counts.avxPackets, hasAvx() ? counts.packets : 0);
}

TEST(TrianglePacket, EachLaneAnswersAsTheScalarTest) {
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  expectLanesMatchScalarEverywhere<TriangleSet>(
      1207, [&](TriangleSet& set, double scale, const Vec3& centre, std::mt19937& rng) {
        // A bumpy mesh over shared vertices (a grid: shared edges) and some
        // loose triangles.
        for (int i = 0; i <= 4; ++i)
          for (int j = 0; j <= 4; ++j)
            set.vertices.push_back(centre + scale * Vec3(i, 0.3 * u(rng), j));
        for (std::uint32_t i = 0; i < 4; ++i)
          for (std::uint32_t j = 0; j < 4; ++j) {
            const std::uint32_t a = i * 5 + j;
            set.add({a, a + 6, a + 5});
            set.add({a, a + 1, a + 6});
          }
        for (int k = 0; k < 8; ++k) {
          const Vec3 a = centre + scale * 4.0 * Vec3(unit(rng), u(rng), unit(rng));
          const auto first = std::uint32_t(set.vertices.size());
          set.vertices.insert(set.vertices.end(),
                              {a, a + scale * randomUnit(rng), a + scale * randomUnit(rng)});
          set.add({first, first + 1, first + 2});
        }
      });
}

TEST(PolygonPacket, EachLaneAnswersAsTheScalarTest) {
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  expectLanesMatchScalarEverywhere<PolygonSet>(
      1208, [&](PolygonSet& set, double scale, const Vec3& centre, std::mt19937& rng) {
        // A tilted planar grid of quads (shared edges), and triangles over the
        // same grid; then convex and concave polygons of 3 to 8 vertices in
        // random planes.
        const Vec3 across = glm::normalize(Vec3(1.0, 0.3, 0.0)), along(0.0, 0.1, 1.0);
        auto grid = [&](int i, int j) {
          return centre + scale * (double(i) * across + double(j) * along);
        };
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            if ((i + j) % 3 != 0) {
              set.add({grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)});
            } else {
              set.add({grid(i, j), grid(i + 1, j), grid(i + 1, j + 1)});
              set.add({grid(i, j), grid(i + 1, j + 1), grid(i, j + 1)});
            }
          }
        for (int k = 0; k < 30; ++k) {
          const Vec3 a = centre + scale * 4.0 * Vec3(unit(rng), u(rng), unit(rng));
          const Vec3 e1 = scale * randomUnit(rng), e2 = scale * randomUnit(rng);
          if (glm::length(glm::cross(e1, e2)) < 0.1 * scale * scale) continue;
          if (k % 5 == 0) set.add({a, a + e1, a + e2});
          if (k % 5 == 1) set.add({a, a + e1, a + e1 + e2, a + e2});         // convex
          if (k % 5 == 2) set.add({a, a + e1, a + 0.3 * (e1 + e2), a + e2}); // a dart: concave
          if (k % 5 == 3) { // a regular n-gon of 5 to 8 vertices
            std::vector<Vec3> ring;
            const int n = 5 + k % 4;
            for (int i = 0; i < n; ++i) {
              const double angle = 2.0 * std::numbers::pi * i / n;
              ring.push_back(a + std::cos(angle) * e1 + std::sin(angle) * e2);
            }
            set.add(ring);
          }
          if (k % 10 == 4) // a concave L of 6 vertices
            set.add({a, a + e1, a + e1 + 0.4 * e2, a + 0.4 * (e1 + e2), a + 0.4 * e1 + e2, a + e2});
          if (k % 10 == 9) // a star of 8
            set.add({a, a + 0.5 * e1 + 0.2 * e2, a + e1, a + 0.8 * e1 + 0.5 * e2, a + e1 + e2,
                     a + 0.5 * e1 + 0.8 * e2, a + e2, a + 0.2 * e1 + 0.5 * e2});
        }
      });
}

// NaN and infinite rays hit nothing, in every lane; the same triangle from a
// finite ray is hit in all four.
TEST(TrianglePacket, NonFiniteRaysHitNothing) {
  TriangleSet set;
  set.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  set.add({0, 1, 2});
  PolygonSet polygons;
  polygons.add(set.vertices);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Ray rays[] = {{Vec3(0.2, 0.2, nan), Vec3(0, 0, -1)},
                      {Vec3(0.2, 0.2, 1), Vec3(nan, 0, -1)},
                      {Vec3(0.2, 0.2, inf), Vec3(0, 0, -1)}};
  const std::array<std::size_t, 4> same{0, 0, 0, 0};
  for (const Ray& ray : rays) {
    EXPECT_EQ(sseHits(ray, set.packet(same, 4).corners(), 0xf, Interval{}).hits, 0u);
    EXPECT_EQ(sseHits(ray, polygons.packet(same, 4).corners(), 0xf, Interval{}).hits, 0u);
#if PRISM_BVH_AVX
    if (hasAvx()) {
      EXPECT_EQ(avxHits(ray, set.packet(same, 4).corners(), 0xf, Interval{}).hits, 0u);
      EXPECT_EQ(avxHits(ray, polygons.packet(same, 4).corners(), 0xf, Interval{}).hits, 0u);
    }
#endif
  }
  const Ray finite{Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)};
  EXPECT_EQ(sseHits(finite, set.packet(same, 4).corners(), 0xf, Interval{}).hits, 0xfu);
  EXPECT_EQ(sseHits(finite, polygons.packet(same, 4).corners(), 0xf, Interval{}).hits, 0xfu);
}

} // namespace
} // namespace prism
