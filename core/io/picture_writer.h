// The picture of a finished render as a file: what `prism render` writes and
// what the previewer's Save writes, so the two agree byte for byte. Formats
// that keep float radiance (.exr, .hdr, or any with floatRadiance) get the
// radiance before exposure; the others the 8-bit picture. The file says in
// its metadata (ImageDescription) how it was exposed.
#pragma once

#include "core/render/renderer.h"

#include <filesystem>
#include <ostream>
#include <string>

namespace prism {

// How an 8-bit picture is exposed. By default the automatic exposure
// (128 / avgmax of the render's own pass 1); the previewer may ask for the
// exposure its window shows instead: locked at another avgmax, offset by EV.
struct PictureExposure {
  bool automatic = true;
  double avgmax = 0.0; // when not automatic
  double ev = 0.0;     // stops added (when not automatic)
  // The 8-bit values sRGB-encoded after exposure (`prism render --srgb`,
  // exposeChannelSrgb) rather than the model's linear values.
  bool srgb = false;
};

// The metadata text for a picture of `result` exposed as `exposure`.
std::string exposureDescription(const RenderResult& result, const PictureExposure& exposure,
                                bool floatRadiance);

// Writes the picture (atomically). Throws std::runtime_error on failure.
void writePicture(const std::filesystem::path& path, const RenderResult& result, bool floatRadiance,
                  const PictureExposure& exposure = {});

// The same file's bytes, in the format named by `extension` (".png"), to
// `out` (`prism render -o -`): written to a temporary file in the temporary
// directory (the image libraries write files), copied, and removed. Throws
// std::runtime_error, naming `shownAs`, on failure.
void writePictureTo(std::ostream& out, const std::string& shownAs, const std::string& extension,
                    const RenderResult& result, bool floatRadiance,
                    const PictureExposure& exposure = {});

} // namespace prism
