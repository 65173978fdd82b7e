#include "camera_controls.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace prism {

namespace {

// The closest the view direction may come to `up`: Camera needs them apart.
constexpr double kMinPolarDegrees = 1.0;

struct Frame {
  Vec3 forward; // unit, eye -> lookat
  Vec3 right;   // unit
  Vec3 up;      // unit, perpendicular to forward
};

// The same basis Camera builds.
Frame frameOf(const CameraSpec& c) {
  Frame f;
  f.forward = glm::normalize(c.lookat - c.eye);
  f.right = glm::normalize(glm::cross(f.forward, c.up));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

// Rodrigues' formula: `v` turned by `radians` about the unit vector `axis`.
Vec3 rotate(const Vec3& v, double radians, const Vec3& axis) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0 - c));
}

} // namespace

CameraSpec orbit(const CameraSpec& camera, double yawDegrees, double pitchDegrees) {
  CameraSpec out = camera;
  const Vec3 axis = glm::normalize(camera.up);
  Vec3 offset = camera.eye - camera.lookat;
  const double distance = glm::length(offset);
  offset = rotate(offset, glm::radians(yawDegrees), axis);

  // Pitch as a change of the polar angle between the offset and `up`, clamped
  // away from the poles; the rotation axis is horizontal, so yaw stays put.
  const double polar = std::acos(std::clamp(glm::dot(offset / distance, axis), -1.0, 1.0));
  const double target =
      std::clamp(polar - glm::radians(pitchDegrees), glm::radians(kMinPolarDegrees),
                 glm::radians(180.0 - kMinPolarDegrees));
  Vec3 horizontal = offset - glm::dot(offset, axis) * axis;
  if (glm::length(horizontal) < 1e-12 * distance) {
    horizontal = frameOf(camera).right; // looking straight along up: any side will do
  }
  const Vec3 side = glm::normalize(glm::cross(axis, horizontal));
  offset = rotate(axis * distance, target, side);
  out.eye = camera.lookat + offset;
  return out;
}

CameraSpec pan(const CameraSpec& camera, double dx, double dy, int imageHeight) {
  const Frame f = frameOf(camera);
  const double distance = glm::length(camera.lookat - camera.eye);
  // World units per pixel in the plane through lookat.
  const double unit =
      2.0 * distance * std::tan(glm::radians(camera.fov) * 0.5) / double(std::max(1, imageHeight));
  // Dragging right moves the scene right: the camera moves left.
  const Vec3 move = (-dx * f.right + dy * f.up) * unit;
  CameraSpec out = camera;
  out.eye += move;
  out.lookat += move;
  return out;
}

CameraSpec zoom(const CameraSpec& camera, double factor) {
  const Vec3 offset = camera.eye - camera.lookat;
  const double distance = glm::length(offset);
  // Never onto lookat, and never so close that round-off loses the direction.
  const double minDistance = 1e-9 * std::max(1.0, maxAbsComponent(camera.lookat));
  const double next = std::max(distance * std::max(factor, 0.0), minDistance);
  CameraSpec out = camera;
  out.eye = camera.lookat + offset * (next / distance);
  return out;
}

std::optional<glm::dvec2> projectToScreen(const CameraSpec& camera, int width, int height,
                                          const Vec3& point) {
  const Frame f = frameOf(camera);
  const Vec3 d = point - camera.eye;
  const double z = glm::dot(d, f.forward);
  if (!(z > 0.0)) return std::nullopt;
  const double halfHeight = std::tan(glm::radians(camera.fov) * 0.5);
  const double halfWidth = halfHeight * double(width) / double(height);
  const double u = glm::dot(d, f.right) / (z * halfWidth);
  const double v = glm::dot(d, f.up) / (z * halfHeight);
  return glm::dvec2((u + 1.0) * 0.5 * double(width), (1.0 - v) * 0.5 * double(height));
}

} // namespace prism
