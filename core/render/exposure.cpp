#include "core/render/exposure.h"

#include "core/texture/srgb.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

float exposureScale(double avgmax) {
  if (!(avgmax > 0.0) || !std::isfinite(avgmax)) return 0.0f;
  // Below avgmax = 128 / 3.4e38 the scale is not a float: such a picture is
  // exposed with the largest float scale (darker than the model asks) rather
  // than with an infinite one, which would turn a black pixel into NaN.
  return float(std::min(128.0 / avgmax, double(std::numeric_limits<float>::max())));
}

std::uint8_t exposeChannel(float radiance, float scale) {
  const float value = radiance * scale;
  if (!(value > 0.0f)) return 0; // also catches NaN
  if (value >= 255.0f) return 255;
  return std::uint8_t(std::round(value)); // std::round: halves away from zero
}

std::uint8_t exposeChannelSrgb(float radiance, float scale) {
  const float value = radiance * scale;
  if (!(value > 0.0f)) return 0; // also catches NaN
  if (value >= 255.0f) return 255;
  return std::uint8_t(std::lround(255.0 * linearToSrgb(double(value) / 255.0)));
}

namespace {

// Each channel through `channel`, a function the compiler can inline.
template <class Channel>
std::vector<std::uint8_t> exposeEach(const std::vector<Rgb>& radiance, float scale,
                                     Channel channel) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(radiance.size() * 3);
  for (const Rgb& c : radiance) {
    bytes.push_back(channel(c.r, scale));
    bytes.push_back(channel(c.g, scale));
    bytes.push_back(channel(c.b, scale));
  }
  return bytes;
}

} // namespace

std::vector<std::uint8_t> exposeImage(const std::vector<Rgb>& radiance, float scale, bool srgb) {
  return srgb ? exposeEach(radiance, scale, exposeChannelSrgb)
              : exposeEach(radiance, scale, exposeChannel);
}

} // namespace prism
