#include "core/scene/camera.h"

#include <glm/gtc/constants.hpp>

namespace prism {

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
