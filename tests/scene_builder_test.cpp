// The scene builder and its material table: what every reader, generator and
// test relies on when it adds to a Scene.
#include "core/scene/material_table.h"
#include "core/scene/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace prism {
namespace {

Material colored(double r) {
  Material m;
  m.color = Color(r, 0.5, 0.25);
  return m;
}

// --- MaterialTable

TEST(MaterialTable, IdenticalMaterialsShareTheIndexOfTheFirst) {
  std::vector<Material> materials;
  MaterialTable table(materials);
  EXPECT_EQ(table.intern(colored(0.1)), 0u);
  EXPECT_EQ(table.intern(colored(0.2)), 1u);
  EXPECT_EQ(table.intern(colored(0.1)), 0u);
  EXPECT_EQ(table.intern(colored(0.3)), 2u);
  EXPECT_EQ(table.intern(colored(0.2)), 1u);
  ASSERT_EQ(materials.size(), 3u); // in the order of first use
  EXPECT_EQ(materials[0], colored(0.1));
  EXPECT_EQ(materials[1], colored(0.2));
  EXPECT_EQ(materials[2], colored(0.3));
}

TEST(MaterialTable, EveryValueTellsMaterialsApart) {
  std::vector<Material> materials;
  MaterialTable table(materials);
  Material base;
  table.intern(base);
  Material m = base;
  double* const fields[] = {&m.color.r, &m.color.g, &m.color.b, &m.kdr,
                            &m.ksr,     &m.kst,     &m.e,       &m.ir};
  // The same change in each field in turn: eight new materials, each with
  // an index of its own.
  for (std::uint32_t i = 0; i < 8; ++i) {
    m = base;
    *fields[i] += 0.5;
    EXPECT_EQ(table.intern(m), i + 1);
  }
  EXPECT_EQ(materials.size(), 9u);
}

TEST(MaterialTable, NegativeZeroIsZero) {
  std::vector<Material> materials;
  MaterialTable table(materials);
  Material negative;
  negative.ksr = -0.0;
  Material positive;
  positive.ksr = 0.0;
  EXPECT_EQ(table.intern(negative), 0u);
  EXPECT_EQ(table.intern(positive), 0u);
  ASSERT_EQ(materials.size(), 1u);
  EXPECT_TRUE(std::signbit(materials[0].ksr)); // the first one is kept as given
}

TEST(MaterialTable, ContinuesAVectorThatAlreadyHasMaterials) {
  std::vector<Material> materials{colored(0.1), colored(0.2), colored(0.1)};
  MaterialTable table(materials);
  EXPECT_EQ(table.intern(colored(0.1)), 0u); // the first of the two identical ones
  EXPECT_EQ(table.intern(colored(0.2)), 1u);
  EXPECT_EQ(table.intern(colored(0.3)), 3u);
  EXPECT_EQ(materials.size(), 4u);
}

TEST(MaterialTable, ManyMaterialsKeepTheirIndices) {
  std::vector<Material> materials;
  MaterialTable table(materials);
  for (int i = 0; i < 5000; ++i)
    ASSERT_EQ(table.intern(colored(i * 1e-3)), std::uint32_t(i));
  for (int i = 4999; i >= 0; --i)
    ASSERT_EQ(table.intern(colored(i * 1e-3)), std::uint32_t(i));
  EXPECT_EQ(materials.size(), 5000u);
}

// --- SceneBuilder

TEST(SceneBuilder, TheCurrentMaterialIsStoredOnlyOnceAPrimitiveUsesIt) {
  Scene scene;
  SceneBuilder build(scene);
  build.setMaterial(colored(0.1));
  build.setMaterial(colored(0.2)); // replaced before use: never stored
  EXPECT_TRUE(scene.materials.empty());
  build.add(Sphere{Vec3(0.0), 1.0, build.currentMaterial(), {}});
  build.add(Sphere{Vec3(3.0), 1.0, build.currentMaterial(), {}});
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0], colored(0.2));
  build.setMaterial(colored(0.2)); // the same again: the same index
  EXPECT_EQ(build.currentMaterial(), 0u);
  EXPECT_EQ(build.material(colored(0.5)), 1u);
}

TEST(SceneBuilder, PushMakesAChildGroupAndPopRestoresGroupAndMaterial) {
  Scene scene;
  SceneBuilder build(scene);
  build.setMaterial(colored(0.1));
  const PrimitiveRef outer = build.add(Sphere{Vec3(0.0), 1.0, build.currentMaterial(), {}});
  const std::uint32_t child = build.push(Origin{0, 7});
  EXPECT_EQ(child, 1u);
  EXPECT_EQ(build.group(), child);
  EXPECT_EQ(build.openPushes(), 1u);
  build.setMaterial(colored(0.2));
  const PrimitiveRef inner = build.add(Sphere{Vec3(3.0), 1.0, build.currentMaterial(), {}});
  const std::uint32_t grandchild = build.push(Origin{0, 9});
  build.pop();
  build.pop();
  EXPECT_EQ(build.group(), 0u);
  EXPECT_EQ(build.openPushes(), 0u);
  EXPECT_EQ(build.currentMaterial(), 0u); // colored(0.1) again
  ASSERT_EQ(scene.groups.size(), 3u);
  EXPECT_EQ(scene.groups[0].primitives, std::vector<PrimitiveRef>{outer});
  EXPECT_EQ(scene.groups[0].children, std::vector<std::uint32_t>{child});
  EXPECT_EQ(scene.groups[child].primitives, std::vector<PrimitiveRef>{inner});
  EXPECT_EQ(scene.groups[child].children, std::vector<std::uint32_t>{grandchild});
  EXPECT_EQ(scene.groups[child].origin.line, 7u);
  EXPECT_EQ(scene.groups[grandchild].origin.line, 9u);
  EXPECT_EQ(scene.shapes<Sphere>()[inner.index].material, 1u);
}

TEST(SceneBuilder, AddGroupAndEnterFillGroupsOutOfOrder) {
  Scene scene;
  SceneBuilder build(scene);
  const std::uint32_t a = build.addGroup(0);
  const std::uint32_t b = build.addGroup(a, Origin{2, 3});
  EXPECT_EQ(build.group(), 0u); // not entered
  build.enter(b);
  const PrimitiveRef inB = build.add(Sphere{Vec3(0.0), 1.0, 0, {}});
  build.enter(a);
  const PrimitiveRef inA = build.add(Sphere{Vec3(2.0), 1.0, 0, {}});
  EXPECT_EQ(scene.groups[a].children, std::vector<std::uint32_t>{b});
  EXPECT_EQ(scene.groups[b].origin.file, 2u);
  EXPECT_EQ(scene.groups[b].primitives, std::vector<PrimitiveRef>{inB});
  EXPECT_EQ(scene.groups[a].primitives, std::vector<PrimitiveRef>{inA});
  EXPECT_TRUE(scene.groups[0].primitives.empty());
}

TEST(SceneBuilder, EveryKindLandsInItsStorageAndTheCurrentGroup) {
  Scene scene;
  SceneBuilder build(scene);
  build.push(Origin{});
  const PrimitiveRef s = build.add(Sphere{Vec3(0.0), 1.0, 0, Origin{0, 1}});
  const PrimitiveRef e = build.add(makeEllipsoid(Mat3(2.0), Vec3(1.0)));
  const PrimitiveRef c = build.add(makeCone(Vec3(0.0), 1.0, Vec3(0, 0, 1), 0.5));
  const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const PrimitiveRef p = build.polygon(square, 0, Origin{0, 4});
  const PrimitiveRef t =
      build.triangle({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, nullptr, 0, Origin{0, 5});
  EXPECT_EQ(s.kind, kindOf<Sphere>);
  EXPECT_EQ(e.kind, kindOf<Ellipsoid>);
  EXPECT_EQ(c.kind, kindOf<Cone>);
  EXPECT_EQ(p.kind, kindOf<Polygon>);
  EXPECT_EQ(t.kind, kindOf<Triangle>);
  EXPECT_EQ(scene.primitiveCount(), 5u);
  EXPECT_EQ(scene.groups[1].primitives, (std::vector<PrimitiveRef>{s, e, c, p, t}));
  EXPECT_EQ(scene.origin(s).line, 1u);
  EXPECT_EQ(scene.origin(p).line, 4u);
  EXPECT_EQ(scene.origin(t).line, 5u);
}

TEST(SceneBuilder, PolygonsStoreTheirVerticesAndManyGetAnEdgeIndex) {
  Scene scene;
  SceneBuilder build(scene);
  const std::vector<Vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  build.polygon(triangle, 0, Origin{});
  std::vector<Vec3> disc;
  for (std::uint32_t i = 0; i < kIndexedPolygonVertices; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / kIndexedPolygonVertices;
    disc.emplace_back(std::cos(a), std::sin(a), 2.0);
  }
  build.polygon(disc, 0, Origin{});
  const auto& polygons = scene.shapes<Polygon>();
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].firstVertex, 0u);
  EXPECT_EQ(polygons[0].vertexCount, 3u);
  EXPECT_EQ(polygons[0].edgeIndex, Polygon::kNoEdgeIndex);
  EXPECT_EQ(polygons[1].firstVertex, 3u);
  EXPECT_EQ(polygons[1].vertexCount, kIndexedPolygonVertices);
  EXPECT_EQ(polygons[1].edgeIndex, 0u);
  EXPECT_EQ(scene.polygonEdgeIndices.size(), 1u);
  EXPECT_EQ(scene.polygonVertices.size(), 3u + kIndexedPolygonVertices);
  EXPECT_EQ(scene.polygonVertices[3], disc[0]);
}

TEST(SceneBuilder, TrianglesWithTheirOwnVerticesAndNormals) {
  Scene scene;
  SceneBuilder build(scene);
  const std::array<Vec3, 3> v{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const std::array<Vec3, 3> n{Vec3(0, 0, 1), Vec3(0, 0.6, 0.8), Vec3(0.6, 0, 0.8)};
  const PrimitiveRef flat = build.triangle(v, nullptr, 0, Origin{});
  const PrimitiveRef smooth = build.triangle(v, &n, 0, Origin{});
  const Triangle& f = scene.shapes<Triangle>()[flat.index];
  const Triangle& s = scene.shapes<Triangle>()[smooth.index];
  EXPECT_FALSE(f.smooth());
  EXPECT_EQ(f.vertex, (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(s.vertex, (std::array<std::uint32_t, 3>{3, 4, 5}));
  EXPECT_EQ(s.normal, (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(scene.meshNormals[s.normal[1]], n[1]);
  EXPECT_EQ(scene.meshVertices.size(), 6u);
}

TEST(SceneBuilder, MeshTrianglesFollowTheirNormalsWinding) {
  Scene scene;
  SceneBuilder build(scene);
  // Counterclockwise seen from +z: the face's normal is +z.
  scene.meshVertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 2, 0)};
  scene.meshNormals = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
  const std::array<std::uint32_t, 3> up{0, 0, 0};

  const auto agreeing = build.meshTriangle({0, 1, 2}, &up, 0, Origin{});
  ASSERT_TRUE(agreeing);
  EXPECT_EQ(scene.shapes<Triangle>()[agreeing->index].vertex,
            (std::array<std::uint32_t, 3>{0, 1, 2}));

  // Normals on the other side: the winding is reversed, normals with it.
  const std::array<std::uint32_t, 3> mixed{1, 0, 1};
  const auto opposed = build.meshTriangle({0, 1, 2}, &mixed, 0, Origin{});
  ASSERT_TRUE(opposed);
  EXPECT_EQ(scene.shapes<Triangle>()[opposed->index].vertex,
            (std::array<std::uint32_t, 3>{0, 2, 1}));
  EXPECT_EQ(scene.shapes<Triangle>()[opposed->index].normal,
            (std::array<std::uint32_t, 3>{1, 1, 0}));

  // Flat: the winding is kept whatever side it faces.
  const auto flat = build.meshTriangle({0, 2, 1}, nullptr, 0, Origin{});
  ASSERT_TRUE(flat);
  EXPECT_EQ(scene.shapes<Triangle>()[flat->index].vertex, (std::array<std::uint32_t, 3>{0, 2, 1}));

  // Zero area (collinear): nothing added.
  const std::size_t before = scene.groups[0].primitives.size();
  scene.meshVertices.push_back(Vec3(4, 4, 0));
  EXPECT_FALSE(build.meshTriangle({0, 3, 4}, nullptr, 0, Origin{}));
  EXPECT_EQ(scene.shapes<Triangle>().size(), 3u);
  EXPECT_EQ(scene.groups[0].primitives.size(), before);
}

TEST(SceneBuilder, FilesAndLights) {
  Scene scene;
  SceneBuilder build(scene);
  EXPECT_EQ(build.addFile("main.sc"), 0u);
  EXPECT_EQ(build.addFile("parts/leaf.sc"), 1u);
  EXPECT_EQ(scene.files, (std::vector<std::string>{"main.sc", "parts/leaf.sc"}));
  build.addLight({Vec3(1, 2, 3), Color(4.0)});
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].position, Vec3(1, 2, 3));
}

TEST(SceneBuilder, ASecondBuilderContinuesTheMaterialTable) {
  Scene scene;
  {
    SceneBuilder first(scene);
    EXPECT_EQ(first.material(colored(0.1)), 0u);
    EXPECT_EQ(first.material(colored(0.2)), 1u);
  }
  SceneBuilder second(scene);
  EXPECT_EQ(second.material(colored(0.2)), 1u);
  EXPECT_EQ(second.material(colored(0.3)), 2u);
}

// The tracer asks Scene::hasMedia for every tile instead of scanning the
// materials: the builder keeps the flag as materials enter, however they do.
TEST(SceneBuilder, KeepsTrackOfAbsorbingMaterials) {
  Material glass = colored(0.9);
  glass.kst = 0.9;
  glass.ir = 1.5;
  Material amber = glass;
  amber.absorption = Color(0.0, 0.2, 0.9);

  Scene scene;
  SceneBuilder build(scene);
  build.material(glass);
  build.setMaterial(colored(0.1));
  build.currentMaterial();
  EXPECT_FALSE(scene.absorbingMaterials);
  EXPECT_FALSE(scene.hasMedia());
  build.setMaterial(amber);
  EXPECT_FALSE(scene.absorbingMaterials) << "not yet used by a primitive";
  build.currentMaterial();
  EXPECT_TRUE(scene.absorbingMaterials);
  EXPECT_TRUE(scene.hasMedia());

  Scene direct;
  SceneBuilder(direct).material(amber);
  EXPECT_TRUE(direct.hasMedia());

  // Materials put in without a builder are found when one continues.
  Scene filled;
  filled.materials = {glass, amber};
  EXPECT_FALSE(filled.hasMedia());
  { const SceneBuilder continued(filled); }
  EXPECT_TRUE(filled.hasMedia());
}

TEST(Scene, FogIsAMediumAsItIsNow) {
  Scene scene;
  EXPECT_FALSE(scene.hasMedia());
  scene.fog = Fog{Color(0.5), 0.1};
  EXPECT_TRUE(scene.hasMedia()); // as the previewer's fog edit sets it
  const Scene copy = scene;
  EXPECT_TRUE(copy.hasMedia());
  scene.fog.density = 0.0;
  EXPECT_FALSE(scene.hasMedia());
}

} // namespace
} // namespace prism
