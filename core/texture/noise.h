// Perlin's gradient noise (the "improved" noise of 2002: quintic fade, the
// twelve cube-edge gradients) and the fractal sums built from it, for the
// procedural textures (docs/rendering-model.md#textures).
#pragma once

#include "core/math/math.h"

namespace prism {

// Fixed, so a scene looks the same everywhere and forever: six octaves, each
// at twice the frequency (lacunarity) and half the amplitude (gain) of the
// one before.
constexpr int kNoiseOctaves = 6;
constexpr double kNoiseLacunarity = 2.0;
constexpr double kNoiseGain = 0.5;

// Gradient noise: 0 at every integer lattice point, |n| <= 2 everywhere,
// and |n(p) - n(q)| <= kNoiseLipschitz |p - q|_1 (the derivation is in
// noise.cpp). Repeats every 256 units along each axis; a coordinate beyond
// 2^53 in magnitude (no fractional part left) gives 0.
double gradientNoise(const Vec3& p);
constexpr double kNoiseLipschitz = 8.5;

// Fractional Brownian motion: sum over the octaves i of gain^i n(lac^i p).
double fractalNoise(const Vec3& p);
// Turbulence: the same sum of |n|, which has creases where n changes sign
// (the veins of marble).
double turbulence(const Vec3& p);

} // namespace prism
