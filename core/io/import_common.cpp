#include "core/io/import_common.h"

#include <cmath>

namespace prism {

std::uint32_t MaterialTable::intern(const Material& m) {
  const std::array<double, 8> key{m.color.r, m.color.g, m.color.b, m.kdr, m.ksr, m.kst, m.e, m.ir};
  const auto [it, inserted] = ids_.try_emplace(key, std::uint32_t(scene_.materials.size()));
  if (inserted) scene_.materials.push_back(m);
  return it->second;
}

bool addMeshTriangle(Scene& scene, std::array<std::uint32_t, 3> vertex,
                     const std::array<std::uint32_t, 3>* normals, std::uint32_t material,
                     Origin origin, std::uint32_t group) {
  const Vec3& a = scene.meshVertices[vertex[0]];
  const Vec3& b = scene.meshVertices[vertex[1]];
  const Vec3& c = scene.meshVertices[vertex[2]];
  if (triangleProblem(a, b, c)) return false;
  Triangle t;
  t.vertex = vertex;
  if (normals != nullptr) {
    t.normal = *normals;
    const Vec3 face = glm::cross(b - a, c - a);
    const Vec3 sum = scene.meshNormals[t.normal[0]] + scene.meshNormals[t.normal[1]] +
                     scene.meshNormals[t.normal[2]];
    if (glm::dot(face, sum) < 0.0) {
      std::swap(t.vertex[1], t.vertex[2]);
      std::swap(t.normal[1], t.normal[2]);
    }
  }
  t.material = material;
  t.origin = origin;
  scene.shapes<Triangle>().push_back(t);
  scene.groups[group].primitives.push_back(
      {kindOf<Triangle>, std::uint32_t(scene.shapes<Triangle>().size() - 1)});
  return true;
}

CameraSpec frameBox(const Aabb& box) {
  CameraSpec camera;
  if (box.empty()) return camera;
  const Vec3 centre = box.centroid();
  const double radius = 0.5 * glm::length(box.extent());
  // The bounding sphere fills the vertical field of view, with a margin.
  const double half = glm::radians(camera.fov) / 2.0;
  const double distance = radius > 0.0 ? 1.1 * radius / std::sin(half) : 1.0;
  camera.lookat = centre;
  camera.eye = centre + Vec3(0.0, 0.0, distance);
  return camera;
}

Aabb sceneBounds(const Scene& scene) {
  Aabb box;
  for (const PrimitiveRef& ref : scene.allPrimitives())
    box.extend(scene.bounds(ref));
  return box;
}

Color falloffCompensated(const Color& intensity, double distance) {
  return intensity * (distance * distance);
}

} // namespace prism
