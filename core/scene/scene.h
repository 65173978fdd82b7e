// A parsed scene: immutable once built, shared read-only by every render thread.
#pragma once

#include "core/scene/camera.h"
#include "core/scene/material.h"
#include "core/shapes/cone.h"
#include "core/shapes/polygon_edges.h"
#include "core/shapes/primitives.h"
#include "core/shapes/triangle.h"

#include <string>
#include <vector>

namespace prism {

struct Light {
  Vec3 position{0.0}; // world space (the scene transform already applied)
  Color intensity{1.0};
};

// One push/pop group: the modeller's hint for the bounding-volume hierarchy.
// Scene::groups[0] is the top level of the main file.
struct Group {
  std::vector<PrimitiveRef> primitives; // written directly in this group
  std::vector<std::uint32_t> children;  // indices into Scene::groups
  Origin origin;                        // where its `push` was written
};

struct Scene {
  CameraSpec camera;
  int width = 512; // `resolution`; the command line may override it
  int height = 512;
  Color background{0.0};
  Color ambient{0.0};

  std::vector<Light> lights; // light i of the user interface is lights[i - 1]
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<Ellipsoid> ellipsoids;
  std::vector<Polygon> polygons;
  std::vector<Vec3> polygonVertices;
  std::vector<PolygonEdgeIndex> polygonEdgeIndices; // of the polygons with many vertices
  std::vector<Cone> cones;
  std::vector<Triangle> triangles;
  std::vector<Vec3> meshVertices; // shared by triangles (Triangle::vertex)
  std::vector<Vec3> meshNormals;  // unit vertex normals of smooth triangles
  std::vector<Group> groups{Group{}};
  std::vector<std::string> files; // files[0] is the main scene file

  std::size_t primitiveCount() const {
    return spheres.size() + ellipsoids.size() + polygons.size() + cones.size() + triangles.size();
  }
  Aabb bounds(PrimitiveRef ref) const;
  std::uint32_t materialIndex(PrimitiveRef ref) const;
  const Material& material(PrimitiveRef ref) const { return materials[materialIndex(ref)]; }
  Origin origin(PrimitiveRef ref) const;
  // "sphere #3 (table.sc:12)" and the like, for diagnostics and the ray tree.
  std::string describe(PrimitiveRef ref) const;
  // Every primitive, in the order of the kinds, for brute-force queries.
  std::vector<PrimitiveRef> allPrimitives() const;
};

// Adds a polygon (whose vertices passed polygonProblem) to the scene and to
// group `group`, with an edge index when it has many vertices. Every reader
// and generator makes polygons through it.
PrimitiveRef addPolygon(Scene& scene, std::span<const Vec3> vertices, std::uint32_t material,
                        Origin origin, std::uint32_t group);

} // namespace prism
