#include "core/math/affine_decompose.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace prism {

namespace {

// Cyclic Jacobi rotations: the eigenvectors (columns of `vectors`) and
// eigenvalues of a symmetric 3x3 matrix, to full double precision.
void symmetricEigen(Mat3 m, Mat3& vectors, Vec3& values) {
  vectors = Mat3(1.0);
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    const double diag = m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2];
    if (off <= 1e-32 * diag) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (m[p][q] == 0.0) continue;
        const double theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
        const double t =
            std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        Mat3 r(1.0); // rotation in the (p, q) plane
        r[p][p] = c;
        r[q][q] = c;
        r[q][p] = s; // column q, row p
        r[p][q] = -s;
        m = glm::transpose(r) * m * r;
        vectors = vectors * r;
      }
    }
  }
  values = Vec3(m[0][0], m[1][1], m[2][2]);
}

// Makes the columns exactly orthonormal and right-handed.
Mat3 orthonormalise(const Mat3& m) {
  const Vec3 x = glm::normalize(m[0]);
  const Vec3 y = glm::normalize(m[1] - glm::dot(m[1], x) * x);
  return Mat3(x, y, glm::cross(x, y));
}

} // namespace

RotationScaleRotation decompose(const Mat3& a) {
  RotationScaleRotation out;
  Vec3 values;
  symmetricEigen(glm::transpose(a) * a, out.v, values);
  out.v = orthonormalise(out.v);
  // a v = u diag(scale): the columns of a v, normalised, are u.
  const Mat3 av = a * out.v;
  for (int i = 0; i < 3; ++i)
    out.scale[i] = glm::length(av[i]);
  Mat3 u;
  for (int i = 0; i < 3; ++i)
    u[i] = av[i] / out.scale[i];
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
