#include "core/io/image_io.h"

#include "core/io/pending_file.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <stdexcept>
#include <unistd.h>

namespace prism {

namespace {

namespace fs = std::filesystem;
using OIIO::TypeDesc;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void writeAtomically(const fs::path& path, int width, int height, TypeDesc type, const void* pixels,
                     const std::string& description) {
  PendingFile file(path);
  auto fail = [&](const std::string& why) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + why);
  };
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) fail(OIIO::geterror().empty() ? "unknown image format" : OIIO::geterror());
  OIIO::ImageSpec spec(width, height, 3, type);
  spec.attribute("compression", "zip");
  spec.attribute("Software", "Prism");
  if (!description.empty()) spec.attribute("ImageDescription", description);
  if (!out->open(file.tempPath().string(), spec)) fail(out->geterror());
  if (!out->write_image(type, pixels)) {
    const std::string why = out->geterror();
    out->close();
    fail(why);
  }
  if (!out->close()) fail(out->geterror());
  file.commit();
}

} // namespace

void checkWritableFile(const fs::path& path) {
  auto fail = [&](const std::string& why) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + why);
  };
  if (path.filename().empty()) fail("not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(dir, error)) fail("no such directory '" + dir.string() + "'");
  if (access(dir.c_str(), W_OK) != 0) fail("directory '" + dir.string() + "' is not writable");
  if (fs::is_directory(path, error)) fail("it is a directory");
}

void checkWritable(const fs::path& path) {
  checkWritableFile(path);
  if (!OIIO::ImageOutput::create(path.string())) {
    OIIO::geterror(); // consume the message so it does not leak into a later error
    throw std::runtime_error("cannot write '" + path.string() +
                             "': no image format for the extension '" + path.extension().string() +
                             "'");
  }
}

bool isFloatFormat(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".exr" || ext == ".hdr";
}

void writeImage8(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& rgb,
                 const std::string& description) {
  writeAtomically(path, width, height, TypeDesc::UINT8, rgb.data(), description);
}

void writeImageFloat(const fs::path& path, int width, int height, const std::vector<Rgb>& radiance,
                     const std::string& description) {
  writeAtomically(path, width, height, TypeDesc::FLOAT, radiance.data(), description);
}

} // namespace prism
