// Camera navigation for the previewer: orbit, pan and zoom on a CameraSpec, and
// the projection that places light markers over the image. Pure functions of
// the spec (no window, no GL), so the mouse mapping can be unit-tested.
#pragma once

#include "core/scene/camera.h"

#include <glm/vec2.hpp>

#include <optional>

namespace prism {

// Turns the eye around `lookat`: `yawDegrees` about the scene's `up` axis,
// `pitchDegrees` toward (+) or away from (-) `up`. The distance to `lookat` is
// kept, and the view never comes within 1 degree of `up` (where it would be
// undefined, docs/image-formation.md).
CameraSpec orbit(const CameraSpec& camera, double yawDegrees, double pitchDegrees);

// Slides eye and lookat together in the image plane so that a point at the
// lookat distance follows the mouse: (dx, dy) are pixels, +x right, +y down,
// of an image `imageHeight` pixels high.
CameraSpec pan(const CameraSpec& camera, double dx, double dy, int imageHeight);

// Moves the eye toward `lookat` (factor < 1) or away from it (factor > 1),
// never onto it.
CameraSpec zoom(const CameraSpec& camera, double factor);

// The screen point (pixels, origin top-left, as Camera::eyeRay takes it) where
// `point` appears, or nothing when it is behind the eye.
std::optional<glm::dvec2> projectToScreen(const CameraSpec& camera, int width, int height,
                                          const Vec3& point);

} // namespace prism
