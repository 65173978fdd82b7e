#include "core/texture/image_map.h"

#include <array>

namespace prism {

namespace {
constexpr std::array<std::string_view, 4> kWrapNames = {"repeat", "clamp", "mirror", "black"};
constexpr std::array<std::string_view, 3> kEncodingNames = {"auto", "srgb", "linear"};

template <class E, std::size_t N>
std::optional<E> named(const std::array<std::string_view, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return E(i);
  return std::nullopt;
}
} // namespace

std::string_view imageWrapName(ImageWrap wrap) { return kWrapNames[std::size_t(wrap)]; }
std::optional<ImageWrap> imageWrapNamed(std::string_view name) {
  return named<ImageWrap>(kWrapNames, name);
}
std::string_view imageEncodingName(ImageEncoding encoding) {
  return kEncodingNames[std::size_t(encoding)];
}
std::optional<ImageEncoding> imageEncodingNamed(std::string_view name) {
  return named<ImageEncoding>(kEncodingNames, name);
}

} // namespace prism
