// How far a rendered picture is from a reference picture of the same scene,
// size and exposure model (docs/choosing-settings.md): the measures `prism
// sweep` reports for every setting.
#pragma once

#include "core/render/film.h"

#include <vector>

namespace prism {

struct ImageError {
  // Root mean square difference of linear radiance, over every channel of
  // every pixel (radiance units, before exposure).
  double rmse = 0.0;
  // Peak signal-to-noise ratio of the 8-bit output against the reference's
  // 8-bit output, in dB: 10 log10(255^2 / MSE). +infinity when they are equal.
  double psnr = 0.0;
  // The largest difference of one channel of one pixel, in 8-bit levels, and
  // where it is (the first such pixel in row-major order).
  int worstLevels = 0;
  int worstX = 0, worstY = 0;
  // The share of pixels with some channel more than 2 levels off.
  double over2 = 0.0;

  bool operator==(const ImageError&) const = default;
};

// `radiance` and `reference` are linear radiance of `width` x `height`
// pixels; each is exposed by its own avgmax, as its picture file would be:
// a setting that changes the exposure changes every pixel of what its user
// sees, and that is part of its error.
ImageError compareImages(const std::vector<Rgb>& radiance, double avgmax,
                         const std::vector<Rgb>& reference, double referenceAvgmax, int width,
                         int height);

} // namespace prism
