#include "core/sweep/image_error.h"

#include "core/render/exposure.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace prism {

ImageError compareImages(const std::vector<Rgb>& radiance, double avgmax,
                         const std::vector<Rgb>& reference, double referenceAvgmax, int width,
                         int height) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (radiance.size() != pixels || reference.size() != pixels)
    throw std::invalid_argument("compareImages: the pictures are not both " +
                                std::to_string(width) + " x " + std::to_string(height));
  ImageError error;
  if (pixels == 0) {
    error.psnr = std::numeric_limits<double>::infinity();
    return error;
  }
  const std::vector<std::uint8_t> shown = exposeImage(radiance, exposureScale(avgmax));
  const std::vector<std::uint8_t> ideal = exposeImage(reference, exposureScale(referenceAvgmax));

  double radianceSquares = 0.0;
  double levelSquares = 0.0;
  std::size_t over2 = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    int worstHere = 0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(radiance[i][c]) - double(reference[i][c]);
      radianceSquares += d * d;
      const int levels = std::abs(int(shown[3 * i + c]) - int(ideal[3 * i + c]));
      levelSquares += double(levels) * double(levels);
      worstHere = std::max(worstHere, levels);
    }
    if (worstHere > 2) ++over2;
    if (worstHere > error.worstLevels) {
      error.worstLevels = worstHere;
      error.worstX = int(i % std::size_t(width));
      error.worstY = int(i / std::size_t(width));
    }
  }
  const double samples = 3.0 * double(pixels);
  error.rmse = std::sqrt(radianceSquares / samples);
  const double mse = levelSquares / samples;
  error.psnr =
      mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  error.over2 = double(over2) / double(pixels);
  return error;
}

} // namespace prism
