#include "core/scene/scene.h"

#include "core/shapes/geometry.h"

#include <filesystem>
#include <sstream>

namespace prism {

Aabb Scene::bounds(PrimitiveRef ref) const {
  switch (ref.kind) {
  case PrimitiveKind::Sphere: return boundsOf(spheres[ref.index]);
  case PrimitiveKind::Ellipsoid: return ellipsoids[ref.index].bounds;
  case PrimitiveKind::Polygon: return boundsOf(polygons[ref.index], polygonVertices.data());
  case PrimitiveKind::Cone: return boundsOf(cones[ref.index]);
  case PrimitiveKind::Triangle: return boundsOf(triangles[ref.index], meshVertices.data());
  }
  return {};
}

std::uint32_t Scene::materialIndex(PrimitiveRef ref) const {
  switch (ref.kind) {
  case PrimitiveKind::Sphere: return spheres[ref.index].material;
  case PrimitiveKind::Ellipsoid: return ellipsoids[ref.index].material;
  case PrimitiveKind::Polygon: return polygons[ref.index].material;
  case PrimitiveKind::Cone: return cones[ref.index].material;
  case PrimitiveKind::Triangle: return triangles[ref.index].material;
  }
  return 0;
}

Origin Scene::origin(PrimitiveRef ref) const {
  switch (ref.kind) {
  case PrimitiveKind::Sphere: return spheres[ref.index].origin;
  case PrimitiveKind::Ellipsoid: return ellipsoids[ref.index].origin;
  case PrimitiveKind::Polygon: return polygons[ref.index].origin;
  case PrimitiveKind::Cone: return cones[ref.index].origin;
  case PrimitiveKind::Triangle: return triangles[ref.index].origin;
  }
  return {};
}

std::string Scene::describe(PrimitiveRef ref) const {
  static constexpr const char* kNames[] = {"sphere", "ellipsoid", "polygon", "cone", "triangle"};
  std::ostringstream text;
  text << kNames[int(ref.kind)] << " #" << ref.index;
  const Origin o = origin(ref);
  if (o.file < files.size())
    text << " (" << std::filesystem::path(files[o.file]).filename().string() << ":" << o.line
         << ")";
  return text.str();
}

PrimitiveRef addPolygon(Scene& scene, std::span<const Vec3> vertices, std::uint32_t material,
                        Origin origin, std::uint32_t group) {
  Polygon p = makePolygon(vertices);
  p.firstVertex = std::uint32_t(scene.polygonVertices.size());
  p.material = material;
  p.origin = origin;
  if (p.vertexCount >= kIndexedPolygonVertices) {
    p.edgeIndex = std::uint32_t(scene.polygonEdgeIndices.size());
    scene.polygonEdgeIndices.emplace_back(vertices, polygonAxes(p).u, polygonAxes(p).v);
  }
  scene.polygonVertices.insert(scene.polygonVertices.end(), vertices.begin(), vertices.end());
  scene.polygons.push_back(p);
  const PrimitiveRef ref{PrimitiveKind::Polygon, std::uint32_t(scene.polygons.size() - 1)};
  scene.groups[group].primitives.push_back(ref);
  return ref;
}

std::vector<PrimitiveRef> Scene::allPrimitives() const {
  std::vector<PrimitiveRef> refs;
  refs.reserve(primitiveCount());
  for (std::uint32_t i = 0; i < spheres.size(); ++i)
    refs.push_back({PrimitiveKind::Sphere, i});
  for (std::uint32_t i = 0; i < ellipsoids.size(); ++i)
    refs.push_back({PrimitiveKind::Ellipsoid, i});
  for (std::uint32_t i = 0; i < polygons.size(); ++i)
    refs.push_back({PrimitiveKind::Polygon, i});
  for (std::uint32_t i = 0; i < cones.size(); ++i)
    refs.push_back({PrimitiveKind::Cone, i});
  for (std::uint32_t i = 0; i < triangles.size(); ++i)
    refs.push_back({PrimitiveKind::Triangle, i});
  return refs;
}

} // namespace prism
