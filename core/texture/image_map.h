// An image texture as a material carries it (`image`, `uv`;
// docs/scene-language.md#image-textures): the material's colour C_mat is
// multiplied by the image's colour at the surface coordinates of the hit,
// filtered over the ray's footprint. The pixels live in the scene's
// ImageLibrary (image_library.h); a material holds only the index and how
// to map the surface coordinates onto the image.
#pragma once

#include "core/math/math.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace prism {

inline constexpr std::uint32_t kNoImage = 0xFFFFFFFFu;

// What a lookup outside [0, 1] finds: the image repeated, its edge
// stretched, the image mirrored at each edge, or black.
enum class ImageWrap : std::uint8_t { Repeat, Clamp, Mirror, Black };

// How the file's numbers relate to radiance: sRGB-encoded (linearised on
// reading), already linear, or decided from the file (integer pixels are
// sRGB unless the file says linear; floating-point pixels are linear).
enum class ImageEncoding : std::uint8_t { Auto, Srgb, Linear };

std::string_view imageWrapName(ImageWrap wrap);
std::optional<ImageWrap> imageWrapNamed(std::string_view name);
std::string_view imageEncodingName(ImageEncoding encoding);
std::optional<ImageEncoding> imageEncodingNamed(std::string_view name);

struct ImageMap {
  std::uint32_t image = kNoImage; // index into the scene's ImageLibrary
  // Surface coordinates (u, v) map to image coordinates
  // s = u scale.x + offset.x, t = v scale.y + offset.y, where (0, 0) is the
  // image's bottom-left corner and (1, 1) its top-right (v runs up the
  // image, as OBJ's vt does).
  Vec2 scale{1.0};
  Vec2 offset{0.0};
  ImageWrap wrap = ImageWrap::Repeat;
  bool filtered = true; // false: the nearest texel of the full-size image
  // The largest value of each channel in the image (from the library), so
  // bounds over the scene's materials hold for any lookup: the filters used
  // are weighted averages with non-negative weights.
  Color peak{1.0};

  bool active() const { return image != kNoImage; }
  bool operator==(const ImageMap&) const = default;
};

// What an image lookup found, for the ray tree.
struct ImageLookup {
  std::uint32_t image = kNoImage; // kNoImage: none was made
  Vec2 st{0.0};                   // image coordinates (ImageMap)
  Vec2 dx{0.0}, dy{0.0};          // the footprint's two axes in image coordinates
  double footprint = 0.0;         // the ray cone's width at the hit, in world units
  Color value{0.0};               // the filtered linear colour
};

} // namespace prism
