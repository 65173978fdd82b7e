#include "core/io/oiio_module.h"
#include "core/texture/image_library.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism {

namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleName = "libprism_oiio.so";

struct Module {
  void* handle = nullptr;
  std::string error; // why it could not be loaded
};

Module loadModule() {
  Module m;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    m.error = "cannot locate the executable: " + ec.message();
    return m;
  }
  const fs::path dir = exe.parent_path();
  const std::vector<fs::path> candidates = {
      dir / kModuleName,                                 // build tree: build/prism
      dir.parent_path() / kModuleName,                   // build tree: build/tests/*, build/bench/*
      dir.parent_path() / "lib" / "prism" / kModuleName, // install tree: bin/../lib/prism
  };
  std::string tried;
  for (const fs::path& p : candidates) {
    if (!fs::exists(p, ec)) {
      tried += "\n  " + p.string() + " (not found)";
      continue;
    }
    m.handle = dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (m.handle) return m;
    const char* why = dlerror();
    tried += "\n  " + p.string() + " (" + (why ? why : "dlopen failed") + ")";
  }
  m.error = std::string("the OpenImageIO module ") + kModuleName + " could not be loaded:" + tried;
  return m;
}

} // namespace

void* oiioModuleSymbol(const char* name) {
  static std::once_flag once;
  static Module module;
  std::call_once(once, [] { module = loadModule(); });
  if (!module.handle) throw std::runtime_error(module.error);
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
    b.load = reinterpret_cast<decltype(b.load)>(oiioModuleSymbol("prism_oiio_texture_load"));
    b.lookup =
        reinterpret_cast<PrismTextureLookupFn>(oiioModuleSymbol("prism_oiio_texture_lookup"));
    return b;
  }();
  return backend;
}

} // namespace prism
