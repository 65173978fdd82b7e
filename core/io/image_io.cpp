#include "core/io/image_io.h"

#include "core/io/oiio_module.h"
#include "core/io/pending_file.h"

#include <png.h>
#include <tiffio.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <unistd.h>

namespace prism {

namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The formats written here directly (libtiff, libpng) rather than through the
// OpenImageIO module; the extensions OpenImageIO gives them.
bool isTiff(const std::string& ext) { return ext == ".tif" || ext == ".tiff" || ext == ".tx"; }
bool isPng(const std::string& ext) { return ext == ".png"; }

[[noreturn]] void failWrite(const fs::path& path, const std::string& why) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + why);
}

// "YYYY:MM:DD HH:MM:SS" in local time, as OpenImageIO stamps a TIFF it writes.
std::string tiffDateTime() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
  return text;
}

// libtiff reports through process-wide handlers; the last message of this
// thread becomes the exception's text.
thread_local std::string tiffMessage;
void tiffErrorHandler(const char* module, const char* format, va_list args) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, args);
  tiffMessage = module ? std::string(module) + ": " + text : std::string(text);
}

// 8-bit RGB TIFF laid out as OpenImageIO 2.4 writes it (the same tags, values
// and order, zip compression with the horizontal predictor, 32 rows per
// strip, the directory checkpointed before the pixels), so that pictures stay
// byte-identical to those of earlier builds (but for DateTime).
void writeTiff8(const fs::path& file, const fs::path& target, int width, int height,
                const std::uint8_t* rgb, const std::string& description) {
  TIFFSetErrorHandler(tiffErrorHandler);
  TIFFSetWarningHandler(nullptr);
  tiffMessage.clear();
  TIFF* tif = TIFFOpen(file.c_str(), "w");
  if (!tif) failWrite(target, tiffMessage.empty() ? "cannot open" : tiffMessage);
  std::unique_ptr<TIFF, void (*)(TIFF*)> guard(tif, TIFFClose);
  const int rowsPerStrip = 32;
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, width);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, height);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 3);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 8);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
  TIFFSetField(tif, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
  TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
  TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
  TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, rowsPerStrip);
  TIFFSetField(tif, TIFFTAG_SOFTWARE, "Prism");
  if (!description.empty()) TIFFSetField(tif, TIFFTAG_IMAGEDESCRIPTION, description.c_str());
  TIFFSetField(tif, TIFFTAG_DATETIME, tiffDateTime().c_str());
  TIFFCheckpointDirectory(tif);
  // Each strip is predicted and deflated here, with zlib at level 6, as
  // OpenImageIO does, then written raw: libtiff's own deflate may be
  // libdeflate (Debian's is), whose bytes differ.
  const std::size_t rowBytes = std::size_t(width) * 3;
  std::vector<std::uint8_t> strip, packed;
  for (int y = 0, s = 0; y < height; y += rowsPerStrip, ++s) {
    const int rows = std::min(rowsPerStrip, height - y);
    strip.assign(rgb + rowBytes * y, rgb + rowBytes * (y + rows));
    for (int r = 0; r < rows; ++r) { // horizontal differencing, right to left
      std::uint8_t* row = strip.data() + rowBytes * r;
      for (std::size_t i = rowBytes - 1; i >= 3; --i)
        row[i] = std::uint8_t(row[i] - row[i - 3]);
    }
    uLongf packedSize = compressBound(uLong(strip.size()));
    packed.resize(packedSize);
    if (compress2(packed.data(), &packedSize, strip.data(), uLong(strip.size()), 6) != Z_OK)
      failWrite(target, "zlib failed");
    if (TIFFWriteRawStrip(tif, uint32_t(s), packed.data(), tmsize_t(packedSize)) < 0)
      failWrite(target, tiffMessage.empty() ? "write failed" : tiffMessage);
  }
  guard.release();
  TIFFClose(tif); // writes the directory; libtiff reports no failure here
  if (!tiffMessage.empty()) failWrite(target, tiffMessage);
}

// 8-bit RGB PNG as OpenImageIO 2.4 writes it: an oFFs chunk of (0, 0), the
// Software and Description texts, libpng's default filters and compression.
void writePng8(const fs::path& file, const fs::path& target, int width, int height,
               const std::uint8_t* rgb, const std::string& description) {
  std::FILE* fp = std::fopen(file.c_str(), "wb");
  if (!fp) failWrite(target, "cannot open");
  std::string why;
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, &why,
      [](png_structp p, png_const_charp msg) {
        *static_cast<std::string*>(png_get_error_ptr(p)) = msg;
        png_longjmp(p, 1);
      },
      [](png_structp, png_const_charp) {});
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, nullptr);
    std::fclose(fp);
    failWrite(target, "out of memory");
  }
  // No C++ object with a destructor may live between setjmp and a longjmp.
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    rows[std::size_t(y)] = const_cast<png_bytep>(rgb + std::size_t(width) * 3 * std::size_t(y));
  png_text texts[2]{};
  texts[0].compression = PNG_TEXT_COMPRESSION_NONE;
  texts[0].key = const_cast<char*>("Software");
  texts[0].text = const_cast<char*>("Prism");
  texts[1].compression = PNG_TEXT_COMPRESSION_NONE;
  texts[1].key = const_cast<char*>("Description");
  texts[1].text = const_cast<char*>(description.c_str());
  volatile bool ok = false; // set after setjmp, read after a longjmp
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, fp);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 6);
    png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
    png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
    png_set_text(png, info, texts, description.empty() ? 1 : 2);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    ok = true;
  }
  png_destroy_write_struct(&png, &info);
  const bool closed = std::fclose(fp) == 0;
  if (!ok) failWrite(target, why.empty() ? "PNG error" : why);
  if (!closed) failWrite(target, "cannot close");
}

void writeThroughModule(const fs::path& path, const fs::path& file, int width, int height,
                        bool isFloat, const void* pixels, const std::string& description) {
  auto write = reinterpret_cast<PrismOiioWriteFn>(oiioModuleSymbol("prism_oiio_write"));
  char error[1024] = "";
  if (!write(path.c_str(), file.c_str(), width, height, isFloat ? 1 : 0, pixels,
             description.c_str(), error, sizeof error))
    failWrite(path, error[0] ? error : "unknown error");
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
  const std::string ext = lowerExtension(path);
  if (isTiff(ext) || isPng(ext)) return;
  auto supports = reinterpret_cast<PrismOiioSupportsFn>(oiioModuleSymbol("prism_oiio_supports"));
  if (!supports(path.c_str()))
    throw std::runtime_error("cannot write '" + path.string() +
                             "': no image format for the extension '" + path.extension().string() +
                             "'");
}

bool isFloatFormat(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".exr" || ext == ".hdr";
}

void writeImage8(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& rgb,
                 const std::string& description) {
  const std::string ext = lowerExtension(path);
  PendingFile file(path);
  if (isTiff(ext))
    writeTiff8(file.tempPath(), path, width, height, rgb.data(), description);
  else if (isPng(ext))
    writePng8(file.tempPath(), path, width, height, rgb.data(), description);
  else
    writeThroughModule(path, file.tempPath(), width, height, false, rgb.data(), description);
  file.commit();
}

void writeImageFloat(const fs::path& path, int width, int height, const std::vector<Rgb>& radiance,
                     const std::string& description) {
  PendingFile file(path);
  writeThroughModule(path, file.tempPath(), width, height, true, radiance.data(), description);
  file.commit();
}

} // namespace prism
