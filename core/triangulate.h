// Splits a polygon (possibly concave, possibly a little non-planar, as faces
// of imported meshes are) into triangles over its own vertex indices.
#pragma once

#include "core/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace prism {

// Triangles (indices into `points`, in the polygon's own winding) covering a
// simple polygon: a fan when the polygon is convex, ear clipping in the plane
// of its Newell normal otherwise. Fewer than 3 points give none. A polygon
// that is not simple gets a best effort (the remaining vertices as a fan), and
// so does a concave one of more than kMaxEarClipping vertices: ear clipping
// costs up to n^3 steps, and a hostile file must not hang the reader.
inline constexpr std::size_t kMaxEarClipping = 256;
std::vector<std::array<std::uint32_t, 3>> triangulate(std::span<const Vec3> points);

} // namespace prism
