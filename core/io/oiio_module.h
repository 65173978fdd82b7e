// OpenImageIO kept out of the `prism` executable: every use of it (picture
// formats other than 8-bit TIFF and PNG, the charts of `prism sweep`) lives in
// the module libprism_oiio.so, loaded with dlopen on first use. Loading the
// library eagerly costs ~0.2 s CPU and ~100 MB RSS at every start-up (it pulls
// ~260 shared libraries), which `prism --version` or a small render should not pay.
#pragma once

#include "core/texture/texture_backend.h"

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
}

// The address of `name` in libprism_oiio.so, which is loaded on the first
// call. The module is looked for only beside the executable (the build tree,
// where tests live one folder down) and in ../lib/prism (an install tree),
// never on the library search path. Throws std::runtime_error naming the
// places tried when it is not found.
void* oiioModuleSymbol(const char* name);

// The module's image textures as an ImageLibrary's backend; loads the module
// (and throws as oiioModuleSymbol does) on the first call.
const TextureBackend& oiioTextureBackend();

} // namespace prism
