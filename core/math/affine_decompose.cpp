#include "core/math/affine_decompose.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace prism {

namespace {

// |x| without squaring the components themselves: no underflow for vectors of
// 1e-300, no overflow for vectors of 1e300.
double norm(const Vec3& x) { return std::hypot(x.x, x.y, x.z); }

// Makes the columns exactly orthonormal and right-handed.
Mat3 orthonormalise(const Mat3& m) {
  const Vec3 x = glm::normalize(m[0]);
  const Vec3 y = glm::normalize(m[1] - glm::dot(m[1], x) * x);
  return Mat3(x, y, glm::cross(x, y));
}

} // namespace

// One-sided Jacobi (Hestenes): plane rotations v applied to the columns of
// w = a v until every two columns are orthogonal; then the column lengths are
// the singular values and the normalised columns are u. Unlike the
// eigenvectors of a^T a, which square the condition number and lose a small
// singular value below 1e-8 of the largest (and underflow it to zero below
// 1e-154, giving NaN), this keeps every singular value to high relative
// precision: a sphere scaled by 1e-300 along one axis is written back as such.
RotationScaleRotation decompose(const Mat3& a) {
  Mat3 w = a;
  Mat3 v(1.0);
  for (int sweep = 0; sweep < 64; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        const double np = norm(w[p]), nq = norm(w[q]);
        if (np == 0.0 || nq == 0.0) continue;
        const double cosine = glm::dot(w[p] / np, w[q] / nq);
        if (!(std::abs(cosine) > 1e-15)) continue; // orthogonal to round-off
        rotated = true;
        // The rotation that diagonalises [[np^2, g], [g, nq^2]], g = np nq cosine,
        // written with ratios of the lengths so nothing is squared.
        const double zeta = (nq / np - np / nq) / (2.0 * cosine);
        const double t = std::copysign(1.0, zeta) / (std::abs(zeta) + std::hypot(1.0, zeta));
        const double c = 1.0 / std::hypot(1.0, t), s = c * t;
        const Vec3 wp = w[p], vp = v[p];
        w[p] = c * wp - s * w[q];
        w[q] = s * wp + c * w[q];
        v[p] = c * vp - s * v[q];
        v[q] = s * vp + c * v[q];
      }
    }
    if (!rotated) break;
  }
  RotationScaleRotation out;
  Mat3 u;
  for (int i = 0; i < 3; ++i) {
    out.scale[i] = norm(w[i]);
    u[i] = w[i] / out.scale[i];
  }
  out.v = orthonormalise(v); // a product of rotations: already right-handed
  out.u = orthonormalise(u);
  // orthonormalise made u right-handed; a mirroring map keeps its mirror in
  // the sign of the last scale factor.
  if (glm::dot(glm::cross(u[0], u[1]), u[2]) < 0.0) out.scale.z = -out.scale.z;
  return out;
}

void axisAngle(const Mat3& rotation, Vec3& axis, double& degrees) {
  glm::dquat q = glm::quat_cast(rotation);
  if (q.w < 0.0) q = -q;
  const Vec3 v(q.x, q.y, q.z);
  const double s = glm::length(v);
  if (s == 0.0) {
    axis = Vec3(0.0, 0.0, 1.0);
    degrees = 0.0;
    return;
  }
  axis = v / s;
  degrees = glm::degrees(2.0 * std::atan2(s, q.w));
}

} // namespace prism
