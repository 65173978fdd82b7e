#include "core/texture/texture.h"

#include <array>

namespace prism {

namespace {
constexpr std::array<std::string_view, 7> kNames = {"none",  "checker", "stripes", "gradient",
                                                    "noise", "marble",  "wood"};
}

std::string_view textureKindName(TextureKind kind) { return kNames[std::size_t(kind)]; }

std::optional<TextureKind> textureKindNamed(std::string_view name) {
  for (std::size_t i = 1; i < kNames.size(); ++i)
    if (kNames[i] == name) return TextureKind(i);
  return std::nullopt;
}

} // namespace prism
