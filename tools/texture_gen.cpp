// texture_gen: writes the image textures scenes/textures.sc uses, made here
// from Prism's own noise (core/texture/noise.h), so the repository ships no
// downloaded picture and anyone can make them again, byte for byte.
//
//   texture_gen [SCENES_DIR]   (default: the current directory) writes
//     SCENES_DIR/images/globe.png  1024 x 512, an imaginary planet in the
//         equirectangular (longitude, latitude) layout that spheres and
//         ellipsoids map images with: oceans, coasts, plains, deserts,
//         mountains, snow and polar ice, from fractal noise on the sphere
//         (sampled in 3D, so there is no seam at the date line and no pinch
//         at the poles)
//     SCENES_DIR/images/tiles.png  256 x 256, one repeat of a floor of 2 x 2
//         square tiles, cream and slate, with grout lines: a regular, high
//         contrast pattern, the hardest case for filtering toward a horizon
// The files are sRGB-encoded 8-bit PNG.
#include "core/io/image_io.h"
#include "core/texture/noise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

namespace {

using prism::Vec3;
constexpr double kPi = 3.14159265358979323846;

struct Rgb8 {
  double r, g, b; // 0..255
};

Rgb8 mix(const Rgb8& a, const Rgb8& b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

double smoothstep(double lo, double hi, double x) {
  const double t = std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

void put(std::vector<std::uint8_t>& rgb, const Rgb8& c) {
  for (const double v : {c.r, c.g, c.b})
    rgb.push_back(std::uint8_t(std::clamp(std::lround(v), 0l, 255l)));
}

// The planet's colour in the direction d (unit, y to the north pole).
Rgb8 planet(const Vec3& d) {
  const double height = prism::fractalNoise(1.7 * d + Vec3(11.3, 4.1, 7.7)) +
                        0.35 * prism::fractalNoise(5.0 * d + Vec3(2.2, 9.5, 1.3));
  const double moisture = prism::fractalNoise(2.3 * d + Vec3(31.0, 17.0, 5.0));
  const double latitude = std::abs(std::asin(std::clamp(d.y, -1.0, 1.0))) / (kPi / 2.0);
  constexpr double kSea = 0.04;
  Rgb8 c;
  if (height < kSea) {
    const Rgb8 deep{12, 32, 84}, shallow{34, 98, 152};
    c = mix(deep, shallow, smoothstep(-0.45, kSea, height));
  } else {
    const double h = height - kSea;
    const Rgb8 plain{66, 112, 44}, forest{34, 78, 36}, desert{196, 164, 104}, rock{118, 100, 82},
        snow{238, 238, 242};
    // Deserts where it is dry and not far from the equator.
    const double dry = smoothstep(0.05, 0.3, -moisture) * (1.0 - smoothstep(0.25, 0.5, latitude));
    c = mix(mix(plain, forest, smoothstep(0.0, 0.3, moisture)), desert, dry);
    c = mix(c, rock, smoothstep(0.25, 0.5, h));
    c = mix(c, snow, smoothstep(0.55, 0.7, h));
  }
  // Polar ice, its edge ragged by the noise.
  const double ice = smoothstep(0.8, 0.84, latitude + 0.08 * prism::fractalNoise(6.0 * d));
  return mix(c, {236, 242, 248}, ice);
}

void writeGlobe(const std::filesystem::path& path) {
  constexpr int kWidth = 1024, kHeight = 512;
  std::vector<std::uint8_t> rgb;
  rgb.reserve(std::size_t(kWidth) * kHeight * 3);
  for (int y = 0; y < kHeight; ++y) {
    // Row 0 is the north: v = 1 at the top (docs/scene-language.md#image-textures).
    const double latitude = (0.5 - (y + 0.5) / kHeight) * kPi;
    for (int x = 0; x < kWidth; ++x) {
      // u = 0.5 + atan2(d.x, d.z) / 2 pi, as spheres and ellipsoids map it.
      const double longitude = ((x + 0.5) / kWidth - 0.5) * 2.0 * kPi;
      const Vec3 d(std::cos(latitude) * std::sin(longitude), std::sin(latitude),
                   std::cos(latitude) * std::cos(longitude));
      put(rgb, planet(d));
    }
  }
  prism::writeImage8(path, kWidth, kHeight, rgb);
}

void writeTiles(const std::filesystem::path& path) {
  constexpr int kSide = 256, kTile = kSide / 2, kGrout = 5;
  const Rgb8 cream{228, 218, 196}, slate{52, 58, 70}, grout{132, 128, 120};
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const int tx = x / kTile, ty = y / kTile;
      const int ix = x % kTile, iy = y % kTile;
      // Half the grout on each side of a tile, so the repeat is seamless.
      const bool inGrout = std::min({ix, iy, kTile - 1 - ix, kTile - 1 - iy}) < kGrout / 2 + 1;
      Rgb8 c = (tx + ty) % 2 == 0 ? cream : slate;
      // A little mottling, so the tiles look like stone, not paint.
      const double n = prism::fractalNoise(Vec3(x, y, 3.5 * (tx + 2 * ty)) / 24.0);
      c = mix(c, {c.r * 0.85, c.g * 0.85, c.b * 0.85}, 0.5 + 0.5 * n);
      put(rgb, inGrout ? grout : c);
    }
  }
  prism::writeImage8(path, kSide, kSide, rgb);
}

} // namespace

int main(int argc, char** argv) {
  try {
    const std::filesystem::path dir = std::filesystem::path(argc > 1 ? argv[1] : ".") / "images";
    std::filesystem::create_directories(dir);
    writeGlobe(dir / "globe.png");
    writeTiles(dir / "tiles.png");
    std::printf("wrote %s and %s\n", (dir / "globe.png").c_str(), (dir / "tiles.png").c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "texture_gen: %s\n", e.what());
    return 1;
  }
}
