// The images a scene's textures read, each loaded once: decoded to linear RGB
// and looked up filtered over a footprint by a backend: OpenImageIO's
// TextureSystem in the module libprism_oiio.so (core/io/oiio_module.h,
// oiioTextureBackend), loaded only by a scene that has images. Shared,
// immutable after loading, by the copies of a scene; lookups are safe from
// any thread.
#pragma once

#include "core/texture/image_map.h"
#include "core/texture/texture_backend.h"

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace prism {

struct ImageInfo {
  std::string path;        // as resolved when loaded (absolute), for messages and writers
  ImageEncoding asked{};   // what the scene asked for
  ImageEncoding decoded{}; // what the pixels were decoded from: Srgb or Linear
  int width = 0;
  int height = 0;
  Color peak{0.0}; // the largest linear value of each channel
};

class ImageLibrary {
public:
  explicit ImageLibrary(const TextureBackend& backend) : backend_(backend) {}
  ~ImageLibrary();
  ImageLibrary(const ImageLibrary&) = delete;
  ImageLibrary& operator=(const ImageLibrary&) = delete;

  // The index of the image at `path` decoded as `encoding`, read now unless
  // the same path and encoding were read before; or why it cannot be read.
  std::variant<std::uint32_t, std::string> load(const std::string& path, ImageEncoding encoding);

  std::size_t size() const { return infos_.size(); }
  const ImageInfo& info(std::uint32_t image) const { return infos_[image]; }

  // The image's linear colour at image coordinates (s, t) ((0, 0) the
  // bottom-left corner, (1, 1) the top-right) over the footprint spanned by
  // the image-coordinate vectors dx and dy (a parallelogram; zero: a point),
  // with the map's wrap and filtering. Black if the lookup fails.
  Color lookup(const ImageMap& map, Vec2 st, Vec2 dx, Vec2 dy) const;

private:
  TextureBackend backend_;
  void* library_ = nullptr; // the backend's, made on the first load
  std::vector<ImageInfo> infos_;
};

} // namespace prism
