// The patterns of the solid textures: each maps a point of texture space
// (already divided by the texture's scale) to a value in [0, 1].
//   checker   cubes of side 1, 0 on the cube at the origin, alternating
//   stripes   slabs of thickness 1 across x: 0 for floor(x) even, 1 odd
//   gradient  x - floor(x): a ramp along x, repeating every unit
//   noise     0.5 + 0.5 fractalNoise(p), clamped
//   marble    thin veins across x, one per unit: s^3 with
//             s = 1 - |sin(pi (x + kMarbleSwirl turbulence(p)))|
//   wood      rings around the z axis: the fractional part of
//             sqrt(x^2 + y^2) + kWoodWobble turbulence(p)
// A cell boundary belongs to the cell above it (floor). A point with a
// non-finite coordinate (none reaches here from a valid scene) gives 0.
#pragma once

#include "core/math/math.h"
#include "core/texture/texture.h"

namespace prism {

constexpr double kMarbleSwirl = 0.75;
constexpr double kWoodWobble = 0.1;

double patternValue(TextureKind kind, const Vec3& p);

} // namespace prism
