#include "core/io/picture_writer.h"

#include "core/io/image_io.h"
#include "core/io/pending_file.h"
#include "core/render/exposure.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

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
  } else if (exposure.automatic && exposure.srgb) {
    std::snprintf(text, sizeof text,
                  "Prism: automatic exposure, sRGB-encoded, value = round(255 * "
                  "srgb_encode(min(1, radiance * 128 / avgmax / 255))), avgmax = %.9g",
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
  if (!floatRadiance && !exposure.automatic && exposure.srgb)
    return std::string(text) + "; then sRGB-encoded";
  return text;
}

namespace {

// Writes the picture into `file` (format by its extension), errors naming `target`.
void writePictureInto(const std::filesystem::path& file, const std::filesystem::path& target,
                      const RenderResult& result, bool floatRadiance,
                      const PictureExposure& exposure) {
  const Film& film = result.film;
  const std::string description = exposureDescription(result, exposure, floatRadiance);
  if (floatRadiance) {
    writeImageFloatInto(file, target, film.width, film.height, film.radiance, description);
  } else {
    const float scale = scaleOf(result, exposure);
    writeImage8Into(file, target, film.width, film.height,
                    exposeImage(film.radiance, scale, exposure.srgb), description, exposure.srgb);
  }
}

} // namespace

void writePicture(const std::filesystem::path& path, const RenderResult& result, bool floatRadiance,
                  const PictureExposure& exposure) {
  PendingFile file(path);
  writePictureInto(file.tempPath(), path, result, floatRadiance, exposure);
  file.commit();
}

void writePictureTo(std::ostream& out, const std::string& shownAs, const std::string& extension,
                    const RenderResult& result, bool floatRadiance,
                    const PictureExposure& exposure) {
  // Never committed: the destructor (or a signal) removes the temporary.
  PendingFile file(std::filesystem::temp_directory_path() /
                   ("prism-" + std::to_string(getpid()) + extension));
  writePictureInto(file.tempPath(), shownAs, result, floatRadiance, exposure);
  std::ifstream in(file.tempPath(), std::ios::binary);
  if (!in || !(out << in.rdbuf()) || !out.flush())
    throw std::runtime_error("cannot write the picture to " + shownAs);
}

} // namespace prism
