// What the space along a ray segment does to the radiance travelling back
// along it (docs/rendering-model.md#fog-and-absorption): outside every solid
// the scene's fog, inside a transmitting solid its material's absorption.
// Both are exact to their formulas, with the distance d the segment's length
// (infinite for a ray that meets nothing):
//
//   fog         exp(-density d) L + (1 - exp(-density d)) C_fog
//   absorption  exp(-sigma_c d) L_c, per channel c
//
// Only a scene with fog or an absorbing material calls these. The radiance
// is saturated first (math.h), so a transmittance of 0 gives 0, not NaN.
#pragma once

#include "core/math/math.h"
#include "core/scene/scene.h"

#include <cmath>

namespace prism {

// The share of radiance that crosses `distance` at `coefficient` per unit
// length: 1 for a clear medium even across an infinite distance (where the
// product would be 0 * inf), 0 for an absorbing one across it.
inline double transmittance(double coefficient, double distance) {
  return coefficient > 0.0 ? std::exp(-coefficient * distance) : 1.0;
}

inline Color throughFog(const Color& far, double distance, const Fog& fog) {
  const double e = transmittance(fog.density, distance);
  return e * saturated(far) + (1.0 - e) * fog.color;
}

inline Color throughAbsorber(const Color& far, double distance, const Color& absorption) {
  const Color c = saturated(far);
  return {c.r * transmittance(absorption.r, distance), c.g * transmittance(absorption.g, distance),
          c.b * transmittance(absorption.b, distance)};
}

} // namespace prism
