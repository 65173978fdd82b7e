// The picture-writing half of libprism_oiio.so (core/io/oiio_module.h): the
// only code of the core that includes OpenImageIO. Built into the module, not
// into prism_core.
#include "core/io/module_error.h"
#include "core/io/oiio_module.h"

#include <OpenImageIO/imageio.h>

#include <string>

extern "C" __attribute__((visibility("default"))) int prism_oiio_supports(const char* formatPath) {
  if (OIIO::ImageOutput::create(formatPath)) return 1;
  OIIO::geterror(); // consume the message so it does not leak into a later error
  return 0;
}

extern "C" __attribute__((visibility("default"))) int
prism_oiio_write(const char* formatPath, const char* filePath, int width, int height, int isFloat,
                 const void* pixels, const char* description, char* error, std::size_t errorSize) {
  const OIIO::TypeDesc type = isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  auto out = OIIO::ImageOutput::create(formatPath);
  if (!out) {
    const std::string why = OIIO::geterror();
    prism::copyModuleError(error, errorSize, why.empty() ? "unknown image format" : why);
    return 0;
  }
  OIIO::ImageSpec spec(width, height, 3, type);
  spec.attribute("compression", "zip");
  spec.attribute("Software", "Prism");
  if (description && *description) spec.attribute("ImageDescription", description);
  if (!out->open(filePath, spec)) {
    prism::copyModuleError(error, errorSize, out->geterror());
    return 0;
  }
  if (!out->write_image(type, pixels)) {
    const std::string why = out->geterror();
    out->close();
    prism::copyModuleError(error, errorSize, why);
    return 0;
  }
  if (!out->close()) {
    prism::copyModuleError(error, errorSize, out->geterror());
    return 0;
  }
  return 1;
}
