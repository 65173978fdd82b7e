// Automatic exposure (docs/image-formation.md): radiance * 128 / avgmax, rounded half away
// from zero, pegged at 255. One function for every consumer (the image writer
// here, the previewer's shader mirrors it), computed in single precision as a
// GPU computes it.
#pragma once

#include "core/render/film.h"

#include <cstdint>
#include <vector>

namespace prism {

// 128 / avgmax, or 0 when avgmax is 0 (an all-black image stays black).
float exposureScale(double avgmax);

std::uint8_t exposeChannel(float radiance, float scale);

// Interleaved 8-bit RGB of a whole radiance buffer.
std::vector<std::uint8_t> exposeImage(const std::vector<Rgb>& radiance, float scale);

} // namespace prism
