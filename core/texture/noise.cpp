#include "core/texture/noise.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace prism {

namespace {

// A permutation of 0..255 shuffled by a fixed 64-bit LCG (Knuth's MMIX
// constants), doubled so that perm[perm[x] + y] needs no wrap.
constexpr std::array<std::uint8_t, 512> makePermutation() {
  std::array<std::uint8_t, 256> p{};
  for (int i = 0; i < 256; ++i)
    p[std::size_t(i)] = std::uint8_t(i);
  std::uint64_t state = 0x5052495348ull; // "PRISH"
  for (int i = 255; i > 0; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const int j = int((state >> 33) % std::uint64_t(i + 1));
    const std::uint8_t t = p[std::size_t(i)];
    p[std::size_t(i)] = p[std::size_t(j)];
    p[std::size_t(j)] = t;
  }
  std::array<std::uint8_t, 512> doubled{};
  for (int i = 0; i < 512; ++i)
    doubled[std::size_t(i)] = p[std::size_t(i & 255)];
  return doubled;
}

constexpr std::array<std::uint8_t, 512> kPerm = makePermutation();

// 6t^5 - 15t^4 + 10t^3: 0 and 1 at the ends with zero first and second
// derivatives, so the noise is smooth across cells; fade(1 - t) = 1 - fade(t);
// its derivative 30 t^2 (1 - t)^2 is at most 15/8.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// g . d for one of the twelve gradients (+-1, +-1, 0) and permutations
// (Perlin's bit trick; 16 cases, four of them repeated).
double gradDot(int hash, double x, double y, double z) {
  const int h = hash & 15;
  const double u = h < 8 ? x : y;
  const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// The lattice cell of x modulo 256 and the position in it, without
// converting a large double to an integer (undefined beyond int's range).
struct Cell {
  int index;   // floor(x) mod 256
  double frac; // x - floor(x), in [0, 1]
};
Cell cellOf(double x) {
  const double f = std::floor(x);
  const double wrapped = f - 256.0 * std::floor(f / 256.0); // exact below 2^53
  return {int(wrapped) & 255, x - f};
}

double lerp(double t, double a, double b) { return a + t * (b - a); }

} // namespace

// The bounds claimed in noise.h. In a cell, n = sum over the eight corners c
// of W_c(p) L_c(p), with W_c a product of fade(t) or 1 - fade(t) per axis
// (the W_c sum to 1) and L_c = g_c . (p - c). Each g has two components +-1
// and one 0, and |p - c| <= 1 per axis, so |L_c| <= 2, hence |n| <= 2.
// d n / dx = sum_c (d W_c / dx) L_c + sum_c W_c g_c.x: the second sum is at
// most 1; the first pairs corners along x, fade'(x) (L_1yz - L_0yz) times the
// y, z weights (summing to 1), at most 15/8 * 4 = 7.5. So each partial
// derivative is at most 8.5, and n, continuous across cells, changes by at
// most 8.5 per unit moved along each axis.
double gradientNoise(const Vec3& p) {
  const Cell cx = cellOf(p.x), cy = cellOf(p.y), cz = cellOf(p.z);
  const double x = cx.frac, y = cy.frac, z = cz.frac;
  const double u = fade(x), v = fade(y), w = fade(z);
  const auto at = [](std::size_t i) { return int(kPerm[i]); };
  const int a = at(std::size_t(cx.index)) + cy.index;
  const int b = at(std::size_t(cx.index) + 1) + cy.index;
  const int aa = at(std::size_t(a)) + cz.index, ab = at(std::size_t(a) + 1) + cz.index;
  const int ba = at(std::size_t(b)) + cz.index, bb = at(std::size_t(b) + 1) + cz.index;
  const auto h = [&](int i) { return at(std::size_t(i)); };
  return lerp(
      w,
      lerp(v, lerp(u, gradDot(h(aa), x, y, z), gradDot(h(ba), x - 1, y, z)),
           lerp(u, gradDot(h(ab), x, y - 1, z), gradDot(h(bb), x - 1, y - 1, z))),
      lerp(v, lerp(u, gradDot(h(aa + 1), x, y, z - 1), gradDot(h(ba + 1), x - 1, y, z - 1)),
           lerp(u, gradDot(h(ab + 1), x, y - 1, z - 1), gradDot(h(bb + 1), x - 1, y - 1, z - 1))));
}

namespace {
template <class Octave> double octaveSum(const Vec3& p, Octave octave) {
  double sum = 0.0, amplitude = 1.0, frequency = 1.0;
  for (int i = 0; i < kNoiseOctaves; ++i) {
    sum += amplitude * octave(gradientNoise(frequency * p));
    amplitude *= kNoiseGain;
    frequency *= kNoiseLacunarity;
  }
  return sum;
}
} // namespace

double fractalNoise(const Vec3& p) {
  return octaveSum(p, [](double n) { return n; });
}

double turbulence(const Vec3& p) {
  return octaveSum(p, [](double n) { return std::abs(n); });
}

} // namespace prism
