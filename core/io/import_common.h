// What the NFF and OBJ readers share besides the SceneBuilder: a default
// camera and lights for files that have none.
#pragma once

#include "core/scene/scene.h"

namespace prism {

// A camera that sees the whole box from the front (+z side, y up, looking
// along -z), with the scene's default 45 degree field of view.
CameraSpec frameBox(const Aabb& box);

// Every primitive's bounds together (empty when there are none).
Aabb sceneBounds(const Scene& scene);

// The intensity that makes a 1/r^2 light deliver `intensity` at `distance`:
// Prism's point lights fall off, NFF's and the default lights' do not.
Color falloffCompensated(const Color& intensity, double distance);

} // namespace prism
