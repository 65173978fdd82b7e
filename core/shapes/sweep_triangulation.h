// The sweep-line triangulation of a polygon of any size in O(n log n) time
// and O(n) memory; how it works is told in core/shapes/sweep_triangulation.cpp.
// core/shapes/triangulate.h decides when it is used.
#pragma once

#include "core/shapes/plane_geometry.h"

#include <vector>

namespace prism {

struct SweepResult {
  std::vector<Triangle2> triangles; // in the caller's indices (`original`)
  bool simple = true;               // no edges met, no vertex repeated
  bool certified = true;            // the triangles provably tile the polygon
};

// Triangulates `polygon` (counterclockwise in its plane, no vertex equal to
// the one before it); `original` is the caller's index of each vertex.
SweepResult sweepTriangulate(std::vector<P2> polygon, std::vector<std::uint32_t> original);

} // namespace prism
