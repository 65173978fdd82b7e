#include "core/render/pixel_tree.h"

#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"

#include <sstream>

namespace prism {

RayTreeNode pixelRayTree(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                         int x, int y, RayCounts& counts) {
  const Camera camera(scene.camera, settings.width, settings.height);
  Tracer tracer(scene, accel, settings.maxDepth);
  RayTreeNode root;
  tracer.setEyeFootprint(camera.pixelSpread());
  tracer.trace(camera.eyeRay(x + 0.5, y + 0.5), 1, counts, &root);
  return root;
}

std::string pixelRayTreeText(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                             int x, int y) {
  RayCounts counts;
  const RayTreeNode root = pixelRayTree(scene, accel, settings, x, y, counts);
  return formatPixelRayTree(scene, settings, x, y, root, counts);
}

std::string formatPixelRayTree(const Scene& scene, const RenderSettings& settings, int x, int y,
                               const RayTreeNode& root, const RayCounts& counts) {
  std::ostringstream out;
  out << "pixel (" << x << ", " << y << ") of " << settings.width << " x " << settings.height
      << ", max depth " << settings.maxDepth << ": centre ray\n";
  printRayTree(out, root, scene);
  out << "rays: 1 eye, " << counts.shadow << " shadow, " << counts.reflected << " reflected, "
      << counts.transmitted << " transmitted (" << counts.tirEvents
      << " total internal reflections)\n";
  return out.str();
}

} // namespace prism
