// The C interface between an ImageLibrary (core/texture/image_library.h) and
// the code that reads and filters its images: OpenImageIO's TextureSystem in
// the module libprism_oiio.so (core/io/oiio_texture_entry.cpp), reached
// through function pointers (core/io/oiio_module.h, oiioTextureBackend) so
// that only a scene with images loads it.
#pragma once

#include <cstddef>

namespace prism {

extern "C" {
// A library of images read once, linearised, and looked up filtered.
using PrismTextureCreateFn = void* (*)();
using PrismTextureDestroyFn = void (*)(void* library);
// What a loaded image is: its size, the encoding it was decoded from (1 sRGB,
// 2 linear) and the largest value of each linear channel.
struct PrismTextureInfo {
  int width;
  int height;
  int encoding;
  float peak[3];
};
// Reads the image at `path` (encoding 0 auto, 1 sRGB, 2 linear) into the
// library. Returns its index, or -1 with `error` filled.
using PrismTextureLoadFn = int (*)(void* library, const char* path, int encoding,
                                   PrismTextureInfo* info, char* error, std::size_t errorSize);
// The filtered linear RGB of image `index` at (s, t) over the footprint
// spanned by (dsdx, dtdx) and (dsdy, dtdy), in image coordinates with t = 0
// at the top. wrap: 0 repeat, 1 clamp, 2 mirror, 3 black. Returns 0 on
// failure (then rgb is black).
using PrismTextureLookupFn = int (*)(void* library, int index, float s, float t, float dsdx,
                                     float dtdx, float dsdy, float dtdy, int wrap, int filtered,
                                     float* rgb);
}

// A backend's entry points.
struct TextureBackend {
  PrismTextureCreateFn create;
  PrismTextureDestroyFn destroy;
  PrismTextureLoadFn load;
  PrismTextureLookupFn lookup;
};

} // namespace prism
