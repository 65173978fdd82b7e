#include "core/io/image_io.h"

#include "core/io/file_extension.h"
#include "core/io/oiio_module.h"
#include "core/io/pending_file.h"
#include "core/io/picture_formats.h"

#include <stdexcept>
#include <unistd.h>

namespace prism {

namespace {

namespace fs = std::filesystem;

// The formats written here directly (libtiff, libpng) rather than through the
// OpenImageIO module; the extensions OpenImageIO gives them.
bool isTiff(const std::string& ext) { return ext == ".tif" || ext == ".tiff" || ext == ".tx"; }
bool isPng(const std::string& ext) { return ext == ".png"; }

// The format follows `file`'s extension; errors name `target`.
void writeThroughModule(const fs::path& target, const fs::path& file, int width, int height,
                        bool isFloat, const void* pixels, const std::string& description) {
  auto write = reinterpret_cast<PrismOiioWriteFn>(oiioModuleSymbol("prism_oiio_write"));
  char error[1024] = "";
  if (!write(file.c_str(), file.c_str(), width, height, isFloat ? 1 : 0, pixels,
             description.c_str(), error, sizeof error))
    failWrite(target, error[0] ? error : "unknown error");
}

} // namespace

void failWrite(const fs::path& target, const std::string& why) {
  throw std::runtime_error("cannot write '" + target.string() + "': " + why);
}

void checkWritableFile(const fs::path& path) {
  auto fail = [&](const std::string& why) { failWrite(path, why); };
  if (path.filename().empty()) fail("not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(dir, error)) fail("no such directory '" + dir.string() + "'");
  if (access(dir.c_str(), W_OK) != 0) fail("directory '" + dir.string() + "' is not writable");
  if (fs::is_directory(path, error)) fail("it is a directory");
}

bool hasImageFormat(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (isTiff(ext) || isPng(ext)) return true;
  auto supports = reinterpret_cast<PrismOiioSupportsFn>(oiioModuleSymbol("prism_oiio_supports"));
  return supports(path.c_str()) != 0;
}

void checkWritable(const fs::path& path) {
  checkWritableFile(path);
  if (!hasImageFormat(path))
    failWrite(path, "no image format for the extension '" + path.extension().string() + "'");
}

bool isFloatFormat(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".exr" || ext == ".hdr";
}

void writeImage8Into(const fs::path& file, const fs::path& target, int width, int height,
                     const std::vector<std::uint8_t>& rgb, const std::string& description,
                     bool srgb) {
  const std::string ext = lowerExtension(file);
  if (isTiff(ext))
    writeTiff8(file, target, width, height, rgb.data(), description);
  else if (isPng(ext))
    writePng8(file, target, width, height, rgb.data(), description, srgb);
  else
    writeThroughModule(target, file, width, height, false, rgb.data(), description);
}

void writeImageFloatInto(const fs::path& file, const fs::path& target, int width, int height,
                         const std::vector<Rgb>& radiance, const std::string& description) {
  writeThroughModule(target, file, width, height, true, radiance.data(), description);
}

void writeImage8(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& rgb,
                 const std::string& description, bool srgb) {
  PendingFile file(path);
  writeImage8Into(file.tempPath(), path, width, height, rgb, description, srgb);
  file.commit();
}

void writeImageFloat(const fs::path& path, int width, int height, const std::vector<Rgb>& radiance,
                     const std::string& description) {
  PendingFile file(path);
  writeImageFloatInto(file.tempPath(), path, width, height, radiance, description);
  file.commit();
}

} // namespace prism
