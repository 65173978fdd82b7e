// The sRGB transfer function (IEC 61966-2-1): an encoded value in [0, 1] to
// linear radiance in [0, 1], and back. Image textures stored in sRGB are
// decoded with it before any filtering, so that averaging texels averages
// light, not code values.
#pragma once

#include <cmath>

namespace prism {

inline double srgbToLinear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

inline double linearToSrgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

} // namespace prism
