// Per-pixel linear radiance as image formation fills it in (docs/image-formation.md). Render
// workers write disjoint tiles of it; nothing here is clamped or exposed.
#pragma once

#include "core/math/math.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace prism {

using Rgb = glm::vec3; // float RGB radiance, as image formation keeps it per pixel

// Radiance beyond the largest float (3.4e38) is stored as the largest float,
// so the film never holds an infinity: avgmax and the exposure stay finite
// and such a pixel exposes to 255 (or, if all of them saturate, to 128). A NaN
// (which the tracer never produces) would be stored as 0, never shown.
inline float toFilm(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return x < kMax ? float(x) : (x >= kMax ? float(kMax) : 0.0f);
}

inline Rgb toRgb(const Color& c) { return Rgb(toFilm(c.r), toFilm(c.g), toFilm(c.b)); }

struct Film {
  Film() = default;
  Film(int w, int h)
      : width(w), height(h), centre(std::size_t(w) * std::size_t(h), Rgb(0.0f)),
        radiance(centre.size(), Rgb(0.0f)), supersampled(centre.size(), 0) {}

  std::size_t index(int x, int y) const {
    return std::size_t(y) * std::size_t(width) + std::size_t(x);
  }
  std::size_t pixelCount() const { return centre.size(); }

  int width = 0;
  int height = 0;
  std::vector<Rgb> centre;                // pass 1: one sample at each pixel centre
  std::vector<Rgb> radiance;              // the picture: centre, or the mean of 16 sub-samples
  std::vector<std::uint8_t> supersampled; // 1 where pass 2 replaced the centre sample
};

} // namespace prism
