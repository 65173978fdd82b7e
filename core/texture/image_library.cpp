#include "core/texture/image_library.h"

#include <filesystem>

namespace prism {

ImageLibrary::~ImageLibrary() {
  if (library_ != nullptr) backend_.destroy(library_);
}

std::variant<std::uint32_t, std::string> ImageLibrary::load(const std::string& path,
                                                            ImageEncoding encoding) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::string resolved = ec ? path : absolute.lexically_normal().string();
  for (std::uint32_t i = 0; i < infos_.size(); ++i)
    if (infos_[i].path == resolved && infos_[i].asked == encoding) return i;
  if (library_ == nullptr) library_ = backend_.create();
  PrismTextureInfo found{};
  char error[512] = "";
  const int index =
      backend_.load(library_, resolved.c_str(), int(encoding), &found, error, sizeof error);
  if (index < 0) return std::string(error);
  ImageInfo info;
  info.path = resolved;
  info.asked = encoding;
  info.decoded = found.encoding == 1 ? ImageEncoding::Srgb : ImageEncoding::Linear;
  info.width = found.width;
  info.height = found.height;
  info.peak = Color(found.peak[0], found.peak[1], found.peak[2]);
  infos_.push_back(std::move(info));
  return std::uint32_t(index);
}

Color ImageLibrary::lookup(const ImageMap& map, Vec2 st, Vec2 dx, Vec2 dy) const {
  float rgb[3];
  // OpenImageIO's t runs down the image; ours up (as OBJ's vt).
  backend_.lookup(library_, int(map.image), float(st.x), float(1.0 - st.y), float(dx.x),
                  float(-dx.y), float(dy.x), float(-dy.y), int(map.wrap), map.filtered ? 1 : 0,
                  rgb);
  return {rgb[0], rgb[1], rgb[2]};
}

} // namespace prism
