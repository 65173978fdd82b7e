#include "core/io/shape_text/shape_text.h"

#include "core/math/affine_decompose.h"

#include <algorithm>
#include <charconv>

namespace prism::sc {

std::string num(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::string vec(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

std::ostream& TextOut::line(int depth) {
  return out_ << std::string(std::size_t(std::min(depth, kMaxIndent)) * 2, ' ');
}

void TextOut::placed(const Mat3& a, const Vec3& offset, int depth) {
  const RotationScaleRotation d = decompose(a);
  line(depth) << "translate " << vec(offset) << "\n";
  Vec3 axis;
  double degrees;
  axisAngle(d.u, axis, degrees);
  line(depth) << "rotate " << vec(axis) << " " << num(degrees) << "\n";
  line(depth) << "scale " << vec(d.scale) << "\n";
  axisAngle(glm::transpose(d.v), axis, degrees);
  line(depth) << "rotate " << vec(axis) << " " << num(degrees) << "\n";
}

} // namespace prism::sc
