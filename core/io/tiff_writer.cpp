#include "core/io/picture_formats.h"

#include <tiffio.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

namespace prism {

namespace {

namespace fs = std::filesystem;

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

} // namespace

// 8-bit RGB TIFF with the tags and values OpenImageIO 2.4 gives it (zip
// compression with the horizontal predictor, 32 rows per strip), so a file
// reads as it did from earlier builds; the strips are compressed alike, but
// the directory comes after them (OpenImageIO writes it first and rewrites it).
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
  // Each strip is predicted and deflated here, with zlib at level 6, as
  // OpenImageIO does, then written raw: libtiff's own deflate may be
  // libdeflate (Debian's is), whose output differs from one version to the next.
  const std::size_t rowBytes = std::size_t(width) * 3;
  std::vector<std::uint8_t> strip, packed;
  for (int y = 0, s = 0; y < height; y += rowsPerStrip, ++s) {
    const int rows = std::min(rowsPerStrip, height - y);
    strip.assign(rgb + rowBytes * y, rgb + rowBytes * (y + rows));
    for (int r = 0; r < rows; ++r) { // horizontal differencing, right to left
      std::uint8_t* row = strip.data() + rowBytes * r;
      for (std::size_t i = rowBytes; i-- > 3;)
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

} // namespace prism
