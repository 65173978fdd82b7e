// Vector types and the few scalar helpers the renderer shares. Geometry and
// radiance are computed in double precision: scenes must render from 1e-4 to 1e4
// units (docs/rendering-model.md) and double keeps round-off far below any modelled detail.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace prism {

using Vec2 = glm::dvec2; // surface coordinates (u, v)
using Vec3 = glm::dvec3;
using Color = glm::dvec3; // linear RGB radiance; never clamped before exposure
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;

inline double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

inline double maxAbsComponent(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace prism
