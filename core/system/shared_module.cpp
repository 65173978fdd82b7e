#include "core/system/shared_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace prism {

namespace fs = std::filesystem;

SharedModule loadSharedModule(const char* fileName) {
  SharedModule m;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    m.error = "cannot locate the executable: " + ec.message();
    return m;
  }
  const fs::path dir = exe.parent_path();
  const std::vector<fs::path> candidates = {
      dir / fileName,                                 // build tree: build/prism
      dir.parent_path() / fileName,                   // build tree: build/tests/*, build/bench/*
      dir.parent_path() / "lib" / "prism" / fileName, // install tree: bin/../lib/prism
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
  m.error = std::string(fileName) + " could not be loaded:" + tried;
  return m;
}

} // namespace prism
