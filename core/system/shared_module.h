// Prism's own optional parts, built as shared modules and loaded with dlopen
// on first use so that a run which does not need them does not pay for
// loading them: libprism_oiio.so (OpenImageIO, core/io/oiio_module.h) and
// libprism_mpi.so (Open MPI, mpi/mpi_module.h).
#pragma once

#include <string>

namespace prism {

struct SharedModule {
  void* handle = nullptr; // null when it could not be loaded
  std::string error;      // then: every place looked in, and why each failed
};

// Loads `fileName` from beside the executable (the build tree: build/prism;
// build/tests/* one folder down), or from the install tree's LIBDIR/prism
// found from the executable's folder or, for a shared object that links the
// core (a Python extension module), from the folders above that object
// (shared_module.cpp says why each place is tried).
SharedModule loadSharedModule(const char* fileName);

} // namespace prism
