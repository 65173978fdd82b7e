#include "core/io/picture_formats.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

namespace prism {

namespace fs = std::filesystem;

// 8-bit RGB PNG as OpenImageIO 2.4 writes it: an oFFs chunk of (0, 0), the
// Software and Description texts, libpng's default filters and compression.
void writePng8(const fs::path& file, const fs::path& target, int width, int height,
               const std::uint8_t* rgb, const std::string& description, bool srgb) {
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
    if (srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
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

} // namespace prism
