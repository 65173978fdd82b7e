#include "core/io/import_common.h"

#include <cmath>

namespace prism {

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
