#include "core/system/shared_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace prism {

namespace fs = std::filesystem;

namespace {

// The folder of the shared object this code was linked into when it is not
// the program: the Python extension (python/), which carries its own copy of
// the modules beside it. Empty for the program itself.
fs::path libraryFolder(const fs::path& exe) {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&loadSharedModule), &info) == 0 || info.dli_fname == nullptr)
    return {};
  std::error_code ec;
  const fs::path self = fs::canonical(info.dli_fname, ec);
  if (ec || self == exe) return {};
  return self.parent_path();
}

} // namespace

SharedModule loadSharedModule(const char* fileName) {
  SharedModule m;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    m.error = "cannot locate the executable: " + ec.message();
    return m;
  }
  const fs::path dir = exe.parent_path();
  std::vector<fs::path> candidates = {
      dir / fileName,                                 // build tree: build/prism
      dir.parent_path() / fileName,                   // build tree: build/tests/*, build/bench/*
      dir.parent_path() / "lib" / "prism" / fileName, // install tree: bin/../lib/prism
  };
  if (const fs::path library = libraryFolder(exe); !library.empty())
    candidates.push_back(library / fileName); // beside the Python extension
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
  m.error = std::string(fileName) + " could not be loaded:" + tried;
  return m;
}

} // namespace prism
