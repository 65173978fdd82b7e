// OpenImageIO kept out of the `prism` executable: every use of it (picture
// formats other than 8-bit TIFF and PNG, the charts of `prism sweep`) lives in
// the module libprism_oiio.so, loaded with dlopen on first use. Loading the
// library eagerly costs ~0.2 s CPU and ~100 MB RSS at every start-up (it pulls
// ~260 shared libraries), which `prism --version` or a small render should not pay.
#pragma once

#include <cstddef>

namespace prism {

// The C interface of libprism_oiio.so (core/io/oiio_module_entry.cpp).
extern "C" {
// 1 when OpenImageIO has a writer for the extension of `formatPath`.
using PrismOiioSupportsFn = int (*)(const char* formatPath);
// Writes `pixels` (RGB, 8-bit or float) at `filePath` in the format chosen by
// the extension of `formatPath`. Returns 0 and fills `error` on failure.
using PrismOiioWriteFn = int (*)(const char* formatPath, const char* filePath, int width,
                                 int height, int isFloat, const void* pixels,
                                 const char* description, char* error, std::size_t errorSize);

// Image textures (core/texture/image_library.h; core/io/oiio_texture_entry.cpp):
// a library of images read once, linearised, and looked up filtered through
// an OpenImageIO TextureSystem of its own.
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

// The address of `name` in libprism_oiio.so, which is loaded on the first
// call. The module is looked for only beside the executable (the build tree,
// where tests live one folder down) and in ../lib/prism (an install tree),
// never on the library search path. Throws std::runtime_error naming the
// places tried when it is not found.
void* oiioModuleSymbol(const char* name);

struct TextureBackend;
// The module's image textures as an ImageLibrary's backend; loads the module
// (and throws as oiioModuleSymbol does) on the first call.
const TextureBackend& oiioTextureBackend();

} // namespace prism
