// The benchmark scenes of tools/spd_gen (docs/benchmark-scenes.md): each kind,
// generated small and read by the scene parser, holds exactly the primitives
// its formula promises, by kind; generation is deterministic; and the sizes
// 10^3, 10^4 and 10^5 pick the levels the documentation lists. The expected
// counts are worked out by hand in the comments.
#include "core/io/scene_parser.h"
#include "core/shapes/shape_kinds.h"
#include "tools/spd/spd_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace prism {
namespace {

struct Expected {
  const char* kind;
  long size;
  int level;
  std::size_t spheres, polygons, cones, triangles;
};

// clang-format off
const Expected kSmall[] = {
    // 1 + 9 + 81 spheres; the ground.
    {"balls", 100, 2, 91, 1, 0, 0},
    // 2 x 2 gears of 146 polygons (2 faces, 144 sides); the floor.
    {"gears", 585, 2, 0, 4 * 146 + 1, 0, 0},
    // 6 * 4^2 triangles; 4 glass spheres.
    {"mount", 100, 2, 4, 0, 0, 96},
    // 1 + 4 = 5 rings of 12 spheres and 12 cylinders; the floor.
    {"rings", 121, 2, 60, 1, 60, 0},
    // 32 pieces of 2 x 2 quads = 256 triangles, less one per quad at the
    // 8 pole pieces' pole (2 each): 240; 8 x 8 checkers.
    {"teapot", 304, 2, 0, 64, 0, 240},
    // 4^2 tetrahedra of 4 triangles; the floor.
    {"tetra", 65, 2, 0, 1, 0, 64},
    // 1 + 2 + 4 + 8 = 15 branches, a cone and a sphere each; the ground.
    {"tree", 31, 3, 15, 1, 15, 0},
    // 3^3 spheres, 3 * 3^2 * 2 = 54 cylinders; the floor.
    {"lattice", 82, 3, 27, 1, 54, 0},
    // 5 jacks of 3 cylinders and 6 balls; the floor.
    {"jacks", 46, 5, 30, 1, 15, 0},
    // 50 spheres; the sand.
    {"shells", 51, 50, 50, 1, 0, 0},
    // 5 x 5 squares of 2 triangles.
    {"hfield", 50, 5, 0, 0, 0, 50},
};
// clang-format on

const spd::SpdKind& kindNamed(const char* name) {
  const spd::SpdKind* kind = spd::findSpdKind(name);
  EXPECT_NE(kind, nullptr) << name;
  return kind ? *kind : spd::spdKinds().front();
}

TEST(SpdGen, EveryKindIsTested) {
  ASSERT_EQ(spd::spdKinds().size(), std::size(kSmall));
  for (const spd::SpdKind& kind : spd::spdKinds())
    EXPECT_TRUE(std::any_of(std::begin(kSmall), std::end(kSmall), [&](const Expected& e) {
      return e.kind == std::string(kind.name);
    })) << kind.name;
  EXPECT_EQ(spd::findSpdKind("sphereflake"), nullptr);
}

TEST(SpdGen, SmallScenesHoldWhatTheirFormulasSay) {
  for (const Expected& e : kSmall) {
    SCOPED_TRACE(e.kind);
    const spd::SpdKind& kind = kindNamed(e.kind);
    const spd::SpdScene generated = spd::makeSpdScene(kind, e.size);
    EXPECT_EQ(generated.level, e.level);
    const Scene scene = parseScene(generated.text, std::string(e.kind) + ".sc");
    EXPECT_EQ(scene.shapes<Sphere>().size(), e.spheres);
    EXPECT_EQ(scene.shapes<Ellipsoid>().size(), 0u);
    EXPECT_EQ(scene.shapes<Polygon>().size(), e.polygons);
    EXPECT_EQ(scene.shapes<Cone>().size(), e.cones);
    EXPECT_EQ(scene.shapes<Triangle>().size(), e.triangles);
    // The writer's own count and the kind's formula agree with the reader.
    EXPECT_EQ(std::size_t(generated.counts.total()), scene.primitiveCount());
    EXPECT_EQ(std::size_t(kind.primitives(e.level)), scene.primitiveCount());
    EXPECT_EQ(scene.width, 512);
    EXPECT_EQ(scene.height, 512);
    EXPECT_GE(scene.lights.size(), 2u);
  }
}

TEST(SpdGen, GearFacesHave144Vertices) {
  const Scene scene = parseScene(spd::makeSpdScene(kindNamed("gears"), 147).text, "gears.sc");
  const auto& polygons = scene.shapes<Polygon>();
  ASSERT_EQ(polygons.size(), 147u); // one gear and the floor
  const long faces = std::count_if(polygons.begin(), polygons.end(),
                                   [](const Polygon& p) { return p.vertexCount == 144; });
  const long quads = std::count_if(polygons.begin(), polygons.end(),
                                   [](const Polygon& p) { return p.vertexCount == 4; });
  EXPECT_EQ(faces, 2);
  EXPECT_EQ(quads, 145); // the sides and the floor
}

TEST(SpdGen, TeapotIsSmoothAndMountHasGlass) {
  const Scene teapot = parseScene(spd::makeSpdScene(kindNamed("teapot"), 120).text, "t.sc");
  for (const Triangle& t : teapot.shapes<Triangle>())
    EXPECT_TRUE(t.smooth());
  const Scene mount = parseScene(spd::makeSpdScene(kindNamed("mount"), 10).text, "m.sc");
  EXPECT_TRUE(std::any_of(mount.materials.begin(), mount.materials.end(),
                          [](const Material& m) { return m.kst > 0 && m.ir == 1.5; }));
}

TEST(SpdGen, SameBytesEveryTime) {
  for (const Expected& e : kSmall) {
    const spd::SpdKind& kind = kindNamed(e.kind);
    EXPECT_EQ(spd::makeSpdScene(kind, e.size).text, spd::makeSpdScene(kind, e.size).text) << e.kind;
  }
}

// The levels of docs/benchmark-scenes.md's table for about 10^3, 10^4 and
// 10^5 primitives (nearest on a logarithmic scale).
TEST(SpdGen, SizesPickTheDocumentedLevels) {
  struct Row {
    const char* kind;
    int levels[3];
  };
  const Row rows[] = {
      {"balls", {3, 4, 5}},           {"gears", {3, 8, 26}},    {"mount", {4, 5, 7}},
      {"rings", {5, 10, 23}},         {"teapot", {4, 13, 40}},  {"tetra", {4, 6, 7}},
      {"tree", {8, 11, 15}},          {"lattice", {7, 14, 29}}, {"jacks", {111, 1111, 11111}},
      {"shells", {999, 9999, 99999}}, {"hfield", {22, 71, 224}}};
  for (const Row& row : rows) {
    const long sizes[3] = {1000, 10000, 100000};
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(spd::levelForSize(kindNamed(row.kind), sizes[k]), row.levels[k])
          << row.kind << " at " << sizes[k];
  }
}

} // namespace
} // namespace prism
