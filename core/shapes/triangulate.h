// Splits a polygon (possibly concave, possibly a little non-planar, as faces
// of imported meshes and NFF polygon patches are) into triangles over its own
// vertex indices.
//
// The polygon is projected onto the coordinate plane its Newell normal is most
// nearly perpendicular to, and mirrored there if needed so that it runs
// counterclockwise. Then:
// - a convex polygon is fanned from vertex 0: (0, i, i + 1);
// - a concave one of at most kEarClippingLimit vertices is ear clipped (O(n^3)
//   at worst, so only for small ones), as Prism always did, so that the
//   pictures of existing scenes do not change;
// - a larger concave one (or a small one ear clipping cannot finish, which a
//   degenerate but simple polygon can cause) is cut into y-monotone pieces by a
//   sweep line and each piece triangulated in linear time (de Berg et al.,
//   Computational Geometry, ch. 3): O(n log n) time and O(n) memory whatever
//   the input. The sweep orders vertices lexicographically by (v, u), so equal
//   heights, horizontal and collinear edges need no special case.
// The same sweep checks that the polygon is simple (Shamos and Hoey: only
// edges adjacent on the sweep line can meet first).
//
// For a simple polygon the n - 2 triangles tile it exactly. The sweep checks
// that its triangles do (as many as there should be, none turned backwards);
// should round-off on a nearly degenerate polygon spoil them, that is reported
// like a polygon that is not simple. Any other input (self-intersecting,
// touching itself, repeated vertices, all points collinear, NaN or infinite
// coordinates, winding more than once) still returns, in O(n log n), at most
// n - 2 triangles of the polygon's own indices (the sweep's when they pass
// that check, else the fan), but they are a best effort and `simple` is false,
// so that callers can warn.
#pragma once

#include "core/math/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace prism {

// Concave polygons of up to this many vertices are ear clipped, as before the
// sweep existed: the triangles of existing scenes' faces, and so their
// pictures (smooth patches interpolate normals across them), stay the same.
// Ear clipping's n^3 worst case is only microseconds at this size; larger
// polygons always take the sweep.
inline constexpr std::size_t kEarClippingLimit = 64;

// Triangles in the polygon's own winding (counterclockwise seen from where its
// Newell normal points), each the indices of three of its vertices.
struct Triangulation {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // False when the polygon, as projected, is not simple: two edges meet other
  // than at their shared vertex (crossing, touching, overlapping), a vertex is
  // repeated (even right after itself), it has no area, it has fewer than three
  // vertices, or a coordinate is not finite or beyond 1e100 in magnitude (where
  // areas could overflow). The triangles are then a best effort.
  bool simple = true;
};

// The warning a reader gives for `count` polygons of kind `what` ("face")
// whose triangulation was not simple.
std::string notSimpleWarning(std::size_t count, const std::string& what);

// Triangulates `points` (a closed polygon; the last vertex joins the first).
// Fewer than 3 points give no triangles, 3 give {0, 1, 2}. `earClippingLimit`
// is for tests, which pass 0 to take the sweep for small polygons too.
// Polygons of more than 2^30 vertices (beyond 32-bit indices of the pieces the
// sweep makes) give no triangles.
Triangulation triangulatePolygon(std::span<const Vec3> points,
                                 std::size_t earClippingLimit = kEarClippingLimit);

// triangulatePolygon(points).triangles, for callers that do not warn.
std::vector<std::array<std::uint32_t, 3>> triangulate(std::span<const Vec3> points);

} // namespace prism
