#include "core/system/shared_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

// Where the install puts the modules, as core/CMakeLists.txt computes it from
// the install layout (GNUInstallDirs): relative to the programs' folder
// (bin -> ../lib/x86_64-linux-gnu/prism with prefix /usr on Debian) and to
// the install prefix (lib/x86_64-linux-gnu/prism). Relative, so that an
// install moved elsewhere (`dpkg -x` into a scratch root, `cmake --install
// --prefix`) still finds its own modules.
#ifndef PRISM_MODULES_FROM_BINDIR
#error "PRISM_MODULES_FROM_BINDIR is set by core/CMakeLists.txt"
#endif
#ifndef PRISM_MODULES_IN_PREFIX
#error "PRISM_MODULES_IN_PREFIX is set by core/CMakeLists.txt"
#endif

namespace prism {

namespace fs = std::filesystem;

namespace {

// The shared object this code was linked into, when it is not the program
// itself: the core is a static library, so a Python extension module (or any
// shared library) that links it carries it. Empty for the program.
fs::path objectWithTheCore(const fs::path& exe) {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&loadSharedModule), &info) == 0 || !info.dli_fname) return {};
  const fs::path object = info.dli_fname;
  std::error_code ec;
  if (!object.is_absolute() || fs::equivalent(object, exe, ec)) return {};
  return object;
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
      // The build tree: build/prism and the modules beside it.
      dir / fileName,
      // The build tree: build/tests/*, build/bench/*, one folder down.
      dir.parent_path() / fileName,
      // The install tree: an installed program (prism, or another in the
      // same bin folder) and the modules in LIBDIR/prism.
      (dir / PRISM_MODULES_FROM_BINDIR / fileName).lexically_normal(),
  };
  // A shared object that links the core (a Python extension module) is
  // loaded by a program from anywhere (/usr/bin/python3, a virtualenv), so
  // the program's folder says nothing: the object lies somewhere under its
  // own install prefix instead, which is one of the folders above it. The
  // filesystem root is not tried: that would be the system's install, which
  // an object outside it (a build tree) must not pick up.
  if (const fs::path object = objectWithTheCore(exe); !object.empty()) {
    // The build tree's Python package carries its own copy beside the
    // extension (python/CMakeLists.txt).
    candidates.push_back(object.parent_path() / fileName);
    for (fs::path prefix = object.parent_path(); prefix.has_relative_path();
         prefix = prefix.parent_path())
      candidates.push_back(prefix / PRISM_MODULES_IN_PREFIX / fileName);
  }
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
