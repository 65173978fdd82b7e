// The two picture formats Prism writes itself, 8-bit RGB TIFF and PNG, with
// libtiff and libpng rather than through OpenImageIO (core/io/oiio_module.h):
// they are what nearly every render writes, and linking OpenImageIO into the
// executable made every start-up pay for its ~260 libraries. The PNG has the
// bytes OpenImageIO 2.4 wrote for the same picture, the TIFF its tags and
// compressed strips, so files read as those of earlier builds. Called by image_io.cpp, which owns
// the temporary file (`file`) and the name reported in errors (`target`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace prism {

void writeTiff8(const std::filesystem::path& file, const std::filesystem::path& target, int width,
                int height, const std::uint8_t* rgb, const std::string& description);

// `srgb`: the file gets an sRGB chunk (rendering intent perceptual), which
// says its values are sRGB-encoded; without it, no colour-space chunk at all.
void writePng8(const std::filesystem::path& file, const std::filesystem::path& target, int width,
               int height, const std::uint8_t* rgb, const std::string& description,
               bool srgb = false);

// Throws std::runtime_error("cannot write 'TARGET': WHY").
[[noreturn]] void failWrite(const std::filesystem::path& target, const std::string& why);

} // namespace prism
