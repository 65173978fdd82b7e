#include "core/scene/camera.h"

#include "core/math/model_range.h"

#include <glm/gtc/constants.hpp>

#include <charconv>

namespace prism {

namespace {

// The shortest text that reads back as exactly `x`.
std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string text(const Vec3& v) { return number(v.x) + " " + number(v.y) + " " + number(v.z); }

} // namespace

CameraProblem cameraProblem(const CameraSpec& camera) {
  const Vec3 direction = camera.lookat - camera.eye;
  if (direction == Vec3(0.0)) return CameraProblem::SamePoint;
  const Vec3 forward = glm::normalize(direction);
  if (!isFinite(forward)) return CameraProblem::NoDirection;
  if (camera.up == Vec3(0.0)) return CameraProblem::ZeroUp;
  // The sine of the angle between up and the view direction; 1e-9 catches what is
  // parallel up to round-off. (Scaled before normalising so that it cannot underflow.)
  const Vec3 unitUp = glm::normalize(camera.up / maxAbsComponent(camera.up));
  if (glm::length(glm::cross(forward, unitUp)) < 1e-9) return CameraProblem::ParallelUp;
  if (!isFinite(glm::normalize(glm::cross(forward, camera.up)))) return CameraProblem::ShortUp;
  return CameraProblem::None;
}

std::optional<std::string> viewProblem(const CameraSpec& c) {
  const std::string view = "eye " + text(c.eye) + ", lookat " + text(c.lookat);
  switch (cameraProblem(c)) {
  case CameraProblem::None: return std::nullopt;
  case CameraProblem::SamePoint:
    return "eye and lookat are the same point (" + text(c.eye) + "), so there is no view direction";
  case CameraProblem::NoDirection:
    return "eye and lookat are too close together or too far apart to give a view direction (" +
           view + ")";
  case CameraProblem::ZeroUp: return std::string("the scene's up is the zero vector");
  case CameraProblem::ParallelUp:
    return "the scene's up (" + text(c.up) +
           ") is parallel to the view direction from eye to lookat (" + view + ")";
  case CameraProblem::ShortUp:
    return "the scene's up (" + text(c.up) + ") is too short to give a direction with this view (" +
           view + ")";
  }
  return std::nullopt;
}

std::optional<std::string> cameraSpecProblem(const CameraSpec& c) {
  if (!(c.fov > 0.0 && c.fov < 180.0))
    return "fov must be greater than 0 and less than 180 degrees, found " + number(c.fov);
  for (const auto& [name, p] : {std::pair{"eye", &c.eye}, std::pair{"lookat", &c.lookat}})
    if (!withinModelRange(*p))
      return std::string(name) + " " + text(*p) + ": the point must be within +-" +
             kMaxCoordinateText;
  return viewProblem(c);
}

Camera::Camera(const CameraSpec& spec, int width, int height)
    : width_(width), height_(height), eye_(spec.eye) {
  forward_ = glm::normalize(spec.lookat - spec.eye);
  const Vec3 right = glm::normalize(glm::cross(forward_, spec.up));
  const Vec3 up = glm::cross(right, forward_); // `up` made perpendicular to the view
  const double halfHeight = std::tan(glm::radians(spec.fov) * 0.5);
  const double halfWidth = halfHeight * double(width) / double(height);
  right_ = right * halfWidth;
  upScaled_ = up * halfHeight;
}

Ray Camera::eyeRay(double sx, double sy) const {
  const double u = 2.0 * sx / double(width_) - 1.0;  // -1 at the left border
  const double v = 1.0 - 2.0 * sy / double(height_); // +1 at the top border
  return {eye_, glm::normalize(forward_ + u * right_ + v * upScaled_)};
}

} // namespace prism
