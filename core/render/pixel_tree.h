// The ray tree of one pixel as text: the centre ray traced with a record of
// every hit, shading term and secondary ray (`prism render --pixel X Y`, and
// the previewer's pixel inspector).
#pragma once

#include "core/render/renderer.h"

#include <string>

namespace prism {

std::string pixelRayTreeText(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                             int x, int y);

} // namespace prism
