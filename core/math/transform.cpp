#include "core/math/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace prism {

Transform Transform::translate(const Vec3& offset) {
  return {glm::translate(Mat4(1.0), offset), glm::translate(Mat4(1.0), -offset)};
}

Transform Transform::scale(const Vec3& factors) {
  return {glm::scale(Mat4(1.0), factors), glm::scale(Mat4(1.0), 1.0 / factors)};
}

Transform Transform::rotate(const Vec3& axis, double degrees) {
  const double radians = glm::radians(degrees);
  const Vec3 unit = glm::normalize(axis);
  // The inverse of a rotation is its transpose: exact, no matrix inversion.
  const Mat4 r = glm::rotate(Mat4(1.0), radians, unit);
  return {r, glm::transpose(r)};
}

Transform Transform::operator*(const Transform& other) const {
  return {m_ * other.m_, other.inverse_ * inverse_};
}

bool Transform::isSimilarity(double* scale) const {
  const Mat3 a = linear();
  const double l0 = glm::length(a[0]), l1 = glm::length(a[1]), l2 = glm::length(a[2]);
  const double tol = 1e-12 * std::max({l0, l1, l2});
  const bool uniform = std::abs(l0 - l1) <= tol * 4 && std::abs(l0 - l2) <= tol * 4;
  const bool orthogonal = std::abs(glm::dot(a[0], a[1])) <= tol * l0 * 4 &&
                          std::abs(glm::dot(a[0], a[2])) <= tol * l0 * 4 &&
                          std::abs(glm::dot(a[1], a[2])) <= tol * l0 * 4;
  if (scale != nullptr) *scale = (l0 + l1 + l2) / 3.0;
  return uniform && orthogonal;
}

} // namespace prism
