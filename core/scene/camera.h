// The pinhole camera (docs/image-formation.md): `fov` is the full vertical angle, the image
// plane's edges are the image borders, pixels are square.
#pragma once

#include "core/math/ray.h"

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
