#include "core/texture/texture.h"

#include <array>

namespace prism {

namespace {
constexpr std::array<std::string_view, 7> kTextureKindNames = {
    "none", "checker", "stripes", "gradient", "noise", "marble", "wood"};
}

std::string_view textureKindName(TextureKind kind) { return kTextureKindNames[std::size_t(kind)]; }

std::optional<TextureKind> textureKindNamed(std::string_view name) {
  for (std::size_t i = 1; i < kTextureKindNames.size(); ++i)
    if (kTextureKindNames[i] == name) return TextureKind(i);
  return std::nullopt;
}

} // namespace prism
