#include "core/io/picture_writer.h"

#include "core/io/image_io.h"
#include "core/render/exposure.h"

#include <cmath>
#include <cstdio>

namespace prism {

namespace {

// The scale an 8-bit picture is exposed with.
float scaleOf(const RenderResult& result, const PictureExposure& exposure) {
  if (exposure.automatic) return exposureScale(result.avgmax);
  return float(double(exposureScale(exposure.avgmax)) * std::exp2(exposure.ev));
}

} // namespace

std::string exposureDescription(const RenderResult& result, const PictureExposure& exposure,
                                bool floatRadiance) {
  char text[200];
  if (floatRadiance) {
    std::snprintf(text, sizeof text,
                  "Prism: linear radiance before exposure (the render's avgmax is %.9g)",
                  result.avgmax);
  } else if (exposure.automatic) {
    std::snprintf(text, sizeof text,
                  "Prism: automatic exposure, value = min(255, round(radiance * 128 / avgmax)), "
                  "avgmax = %.9g",
                  result.avgmax);
  } else {
    std::snprintf(text, sizeof text,
                  "Prism: the previewer's exposure, value = min(255, round(radiance * 128 / "
                  "%.9g * 2^%.3g)); the render's own avgmax is %.9g",
                  exposure.avgmax, exposure.ev, result.avgmax);
  }
  return text;
}

void writePicture(const std::filesystem::path& path, const RenderResult& result, bool floatRadiance,
                  const PictureExposure& exposure) {
  const Film& film = result.film;
  const std::string description = exposureDescription(result, exposure, floatRadiance);
  if (floatRadiance) {
    writeImageFloat(path, film.width, film.height, film.radiance, description);
  } else {
    writeImage8(path, film.width, film.height,
                exposeImage(film.radiance, scaleOf(result, exposure)), description);
  }
}

} // namespace prism
