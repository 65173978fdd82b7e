// Affine transforms as the scene language composes them: each command
// post-multiplies the current matrix, as in OpenGL, so the command written last
// acts on the object first (docs/scene-language.md).
#pragma once

#include "core/math/math.h"

namespace prism {

class Transform {
public:
  Transform() = default; // identity

  static Transform translate(const Vec3& offset);
  static Transform scale(const Vec3& factors); // every factor non-zero
  // Right-handed rotation by `degrees` about `axis` (non-zero) through the origin.
  static Transform rotate(const Vec3& axis, double degrees);

  // this * other: `other` is applied to a point first.
  Transform operator*(const Transform& other) const;

  Vec3 point(const Vec3& p) const { return Vec3(m_ * glm::dvec4(p, 1.0)); }
  Vec3 vector(const Vec3& v) const { return Mat3(m_) * v; }
  // Normals transform by the inverse transpose; the result is not normalised.
  Vec3 normal(const Vec3& n) const { return glm::transpose(Mat3(inverse_)) * n; }

  const Mat4& matrix() const { return m_; }
  const Mat4& inverse() const { return inverse_; }
  Mat3 linear() const { return Mat3(m_); }
  double determinant() const { return glm::determinant(linear()); }

  // True when the linear part is a rotation (or reflection) times a uniform scale,
  // i.e. spheres stay spheres. `scale` receives that uniform factor.
  bool isSimilarity(double* scale = nullptr) const;

private:
  Transform(const Mat4& m, const Mat4& inverse) : m_(m), inverse_(inverse) {}

  Mat4 m_{1.0};
  Mat4 inverse_{1.0};
};

} // namespace prism
