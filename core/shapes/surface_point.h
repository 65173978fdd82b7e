// What the tracer learns of a surface at a hit point, beyond the distance:
// the record every shape kind hands to shading, so the tracer needs no
// kind-specific code, and material properties are looked up through it
// (Scene::materialAt; a textured one is then blended at the point, see
// core/scene/material_blend.h).
#pragma once

#include "core/math/math.h"

#include <cstdint>
#include <optional>

namespace prism {

// How much of the record a caller needs. The surface coordinates cost a few
// transcendental functions for curved kinds, so they are computed only for
// callers that use them (the --pixel ray tree; solid textures need only the
// point): a scene that uses none pays nothing.
enum class SurfaceDetail : std::uint8_t { Shading, WithCoordinates };

struct SurfacePoint {
  Vec3 point{0.0};
  Vec3 outward{0.0}; // unit geometric normal, outward: decides entering or leaving, offsets rays
  Vec3 shading{0.0}; // unit shading normal, outward (a smooth triangle's interpolated one)
  // Where rays leaving the outward side start, when not at the hit point itself
  // (a smooth triangle lifts them onto the curved surface its normals describe).
  std::optional<Vec3> outwardStart;
  // The size of the numbers the kind's intersection test computed with besides
  // the point and the ray's origin (roundoffScale in core/shapes/roundoff.h):
  // with them it bounds the point's round-off, which new rays must clear.
  double roundoffScale = 0.0;
  // Surface coordinates, each kind's own (docs/architecture.md lists them);
  // zero unless asked for with SurfaceDetail::WithCoordinates.
  Vec2 uv{0.0};
  // Which face of a compound shape was hit (a box's side, a cylinder's cap);
  // 0 for the kinds made of one surface.
  std::uint32_t part = 0;
  std::uint32_t material = 0; // index into Scene::materials
};

} // namespace prism
