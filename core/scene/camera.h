// The pinhole camera (docs/image-formation.md): `fov` is the full vertical angle, the image
// plane's edges are the image borders, pixels are square.
#pragma once

#include "core/math/ray.h"

#include <optional>
#include <string>

namespace prism {

// The camera as the scene file states it.
struct CameraSpec {
  Vec3 eye{0.0, 0.0, 5.0};
  Vec3 lookat{0.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fov = 45.0; // degrees, full vertical angle, 0 < fov < 180
};

// A camera fixed to an image size. Screen coordinates run from (0, 0) at the
// top-left corner of the image to (width, height) at the bottom-right, so the
// centre of pixel (ix, iy) is (ix + 0.5, iy + 0.5).
// Why no camera can be made from `camera`, checked in the order below: the
// same computation as Camera's constructor, so that it cannot produce NaN.
// Each reader words the problem in its own commands.
enum class CameraProblem {
  None,
  SamePoint,   // eye and lookat are one point
  NoDirection, // too close together or too far apart to normalise
  ZeroUp,
  ParallelUp, // up along the view direction, up to round-off
  ShortUp,    // up too short to give a direction
};
CameraProblem cameraProblem(const CameraSpec& camera);

// The same as a sentence that names the values ("eye and lookat are the
// same point (0 0 5), so there is no view direction"), or nothing.
std::optional<std::string> viewProblem(const CameraSpec& spec);

// viewProblem, and before it a field of view outside (0, 180) degrees or an
// eye or lookat outside the representable range (core/math/model_range.h).
std::optional<std::string> cameraSpecProblem(const CameraSpec& spec);

class Camera {
public:
  // The spec must have eye != lookat and up not parallel to the view direction
  // (the parser guarantees both).
  Camera(const CameraSpec& spec, int width, int height);

  Ray eyeRay(double sx, double sy) const;
  // The side of a pixel on the image plane at distance 1 from the eye: the
  // angle (radians, small) one pixel spans at the image's centre, the
  // spread of an eye ray's footprint (Tracer::setEyeFootprint).
  double pixelSpread() const { return 2.0 * glm::length(upScaled_) / double(height_); }

  int width() const { return width_; }
  int height() const { return height_; }

private:
  int width_;
  int height_;
  Vec3 eye_;
  Vec3 forward_;  // unit view direction
  Vec3 right_;    // scaled to half the image plane's width at distance 1
  Vec3 upScaled_; // scaled to half the image plane's height at distance 1
};

} // namespace prism
