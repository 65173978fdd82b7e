// Per-pixel linear radiance as image formation fills it in (SPEC 2). Render
// workers write disjoint tiles of it; nothing here is clamped or exposed.
#pragma once

#include "core/math.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prism {

using Rgb = glm::vec3; // float RGB radiance, as SPEC 2 keeps it per pixel

inline Rgb toRgb(const Color& c) { return Rgb(float(c.r), float(c.g), float(c.b)); }

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
