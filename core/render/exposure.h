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

// The same exposure, sRGB-encoded (`prism render --srgb`): the exposed value
// as a fraction of 255, e = radiance * scale / 255 clamped to [0, 1], through
// the sRGB transfer function (core/texture/srgb.h): round(255 * srgb(e)).
// 0 for NaN or a value <= 0, as exposeChannel.
std::uint8_t exposeChannelSrgb(float radiance, float scale);

// Interleaved 8-bit RGB of a whole radiance buffer: exposeChannel, or with
// `srgb` exposeChannelSrgb, of each channel.
std::vector<std::uint8_t> exposeImage(const std::vector<Rgb>& radiance, float scale,
                                      bool srgb = false);

} // namespace prism
