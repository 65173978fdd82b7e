// Whether triangles given by their corners bound a solid: what the .sc `mesh`
// block checks at its `end` before a mesh can be a CSG operand (solid_mesh.h).
// Corners are the same vertex exactly when their coordinates are equal; the
// mesh is closed and consistently oriented when every edge is run by exactly
// two triangles, once in each direction (so each directed edge appears once
// and so does its reverse). Its orientation is then the sign of the volume it
// encloses: positive when the triangles wind counterclockwise seen from
// outside.
#pragma once

#include "core/math/math.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace prism {

// The corners welded: distinct vertices, and each triangle's three indices
// into them.
struct WeldedMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};
WeldedMesh weld(std::span<const std::array<Vec3, 3>> triangles);

struct ClosureProblem {
  enum class Kind : std::uint8_t {
    Open,         // the edge from `from` to `to` of `triangle` is in no other triangle
    SameDirection // `other` runs the same edge the same way (or a third triangle has it)
  };
  Kind kind = Kind::Open;
  std::uint32_t triangle = 0; // the later of the two for SameDirection
  std::uint32_t other = 0;
  Vec3 from{0.0}, to{0.0};
};

// The first problem (by triangle, in the order given), or nothing when the
// mesh is closed and consistently oriented.
std::optional<ClosureProblem> closureProblem(const WeldedMesh& mesh);

// Six times the signed volume enclosed (positive for outward winding).
double signedVolume6(const WeldedMesh& mesh);

} // namespace prism
