// The scene's primitives, stored compactly by kind and in world space. A
// PrimitiveRef names one of them. Every primitive also records where in which
// file it was written, for the --pixel ray tree and for error messages.
#pragma once

#include "core/math/aabb.h"

#include <cstdint>

namespace prism {

// A shape kind: its place in the list of kinds (ShapeKinds in shape_kinds.h),
// named there as kindOf<Sphere> and the like. The order is the tie-break
// between coincident surfaces.
enum class PrimitiveKind : std::uint8_t {};

struct PrimitiveRef {
  PrimitiveKind kind{};
  std::uint32_t index = 0;

  bool operator==(const PrimitiveRef&) const = default;
  // Orders hits at exactly the same distance (coincident surfaces), so every
  // acceleration structure picks the same one whatever order it visits them in.
  bool operator<(const PrimitiveRef& o) const {
    return kind != o.kind ? kind < o.kind : index < o.index;
  }
};

// Where a primitive was written: index into Scene::files and 1-based line.
struct Origin {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

} // namespace prism
