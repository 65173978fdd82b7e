// A textured material at a point, and the bounds over everything a textured
// material can blend to (for the bailout and the work estimate).
#pragma once

#include "core/scene/material.h"

namespace prism {

// What the lookup found, for the ray tree.
struct TextureLookup {
  Vec3 point{0.0}; // in texture space, before dividing by the scale
  double value = 0.0;
};

// The material at world point `p`: `m` itself when untextured, otherwise C,
// kdr, ksr, kst and e blended linearly between m's values (value 0) and its
// texture's (value 1). ir and absorption stay m's; the result has no texture.
Material textureAt(const Material& m, const Vec3& p, TextureLookup* lookup = nullptr);

// m's coefficients blended to pattern value `value` in [0, 1] (0: m's own,
// 1: its texture's), without the texture.
Material textureBlend(const Material& m, double value);

// Per coefficient, the largest (ceiling) or smallest (floor) of the two ends:
// every blend lies between them. Used where a bound over the scene's
// materials is taken: for the products C kdr a blend may exceed both ends
// (0.5 (1, 0) + 0.5 (0, 1) gives 0.25 > 0), but never the product of the
// ceilings. An image's colour runs from 0 to its peak per channel. `m`
// itself when untextured; the result has no image.
Material coefficientCeiling(const Material& m);
Material coefficientFloor(const Material& m);

} // namespace prism
