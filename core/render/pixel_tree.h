// The ray tree of one pixel as text: the centre ray traced with a record of
// every hit, shading term and secondary ray (`prism render --pixel X Y`, and
// the previewer's pixel inspector).
#pragma once

#include "core/render/ray_tree.h"
#include "core/render/renderer.h"

#include <string>

namespace prism {

// The centre ray of pixel (x, y) traced with its record; `counts` gets its rays.
RayTreeNode pixelRayTree(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                         int x, int y, RayCounts& counts);

// That record as text: what `prism render --pixel X Y` prints.
std::string formatPixelRayTree(const Scene& scene, const RenderSettings& settings, int x, int y,
                               const RayTreeNode& root, const RayCounts& counts);

std::string pixelRayTreeText(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                             int x, int y);

} // namespace prism
