// A procedural solid texture as a material carries it (`texture`,
// docs/scene-language.md#textures): a pattern maps the hit point, carried into
// the texture's space, to a value in [0, 1], and the material's coefficients
// are blended between the material's own values (the value-0 end) and the
// texture's (the value-1 end). The blend itself is in core/scene/material_blend.h.
#pragma once

#include "core/math/math.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace prism {

enum class TextureKind : std::uint8_t { None, Checker, Stripes, Gradient, Noise, Marble, Wood };

// "checker" ... "wood" (and "none").
std::string_view textureKindName(TextureKind kind);
std::optional<TextureKind> textureKindNamed(std::string_view name);
// "checker, stripes, gradient, noise, marble, wood", for error messages.
constexpr std::string_view kTextureKindList = "checker, stripes, gradient, noise, marble, wood";

struct Texture {
  TextureKind kind = TextureKind::None;
  double scale = 1.0; // the pattern's size in texture-space units
  // The value-1 end (ir and absorption are never textured: a solid's index
  // and its inside are one).
  Color color{1.0};
  double kdr = 1.0;
  double ksr = 0.0;
  double kst = 0.0;
  double e = 1.0;
  // World point -> texture space: linear * p + offset. A scene's materials
  // hold the whole map, their primitive's object space composed in
  // (SceneBuilder::currentMaterial). Before that, a reader's current
  // material holds the identity, to be composed, or with `fromWorld` the
  // whole map already (`texture_space`), which is then kept as it is.
  Mat3 linear{1.0};
  Vec3 offset{0.0};
  bool fromWorld = false; // never set in a scene's materials

  bool active() const { return kind != TextureKind::None; }
  bool operator==(const Texture&) const = default;
};

} // namespace prism
