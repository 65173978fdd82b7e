// How the dlopen'd OpenImageIO module (core/io/oiio_module.h) hands an error
// back: its entry points are C functions, so a message crosses into the
// caller's character buffer rather than as a C++ object.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>

namespace prism {

// Copies `why` into `error` (`size` bytes), cut short if it does not fit and
// always terminated; does nothing without a buffer.
inline void copyModuleError(char* error, std::size_t size, const std::string& why) {
  if (!error || size == 0) return;
  std::strncpy(error, why.c_str(), size - 1);
  error[size - 1] = '\0';
}

} // namespace prism
