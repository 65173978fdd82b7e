#include "core/io/oiio_module.h"
#include "core/system/shared_module.h"
#include "core/texture/image_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace prism {

void* oiioModuleSymbol(const char* name) {
  static std::once_flag once;
  static SharedModule module;
  std::call_once(once, [] { module = loadSharedModule("libprism_oiio.so"); });
  if (!module.handle) throw std::runtime_error("the OpenImageIO module " + module.error);
  void* symbol = dlsym(module.handle, name);
  if (!symbol)
    throw std::runtime_error(std::string("the OpenImageIO module has no entry '") + name + "'");
  return symbol;
}

} // namespace prism

namespace prism {

const TextureBackend& oiioTextureBackend() {
  static const TextureBackend backend = [] {
    TextureBackend b;
    b.create =
        reinterpret_cast<PrismTextureCreateFn>(oiioModuleSymbol("prism_oiio_texture_create"));
    b.destroy =
        reinterpret_cast<PrismTextureDestroyFn>(oiioModuleSymbol("prism_oiio_texture_destroy"));
    b.load = reinterpret_cast<PrismTextureLoadFn>(oiioModuleSymbol("prism_oiio_texture_load"));
    b.lookup =
        reinterpret_cast<PrismTextureLookupFn>(oiioModuleSymbol("prism_oiio_texture_lookup"));
    return b;
  }();
  return backend;
}

} // namespace prism
