// Writing pictures with OpenImageIO, at the edge of the renderer. The format
// follows the file extension; a file is written completely or not at all
// (written to a temporary name beside it, then renamed).
#pragma once

#include "core/render/film.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace prism {

// True for formats that keep float radiance (.exr, .hdr): they get the raw
// radiance before exposure rather than 8-bit pixels.
bool isFloatFormat(const std::filesystem::path& path);

// Throws std::runtime_error, before any work is spent, when a file could not
// be written at `path`: no such directory, one that is not writable, or a
// directory of that name.
void checkWritableFile(const std::filesystem::path& path);

// checkWritableFile, and an image format for the extension.
void checkWritable(const std::filesystem::path& path);

// Interleaved 8-bit RGB (row 0 at the top). `description`, when given, is
// stored as the file's ImageDescription (how the picture was exposed). Throws
// std::runtime_error on failure.
void writeImage8(const std::filesystem::path& path, int width, int height,
                 const std::vector<std::uint8_t>& rgb, const std::string& description = "");

// Float RGB radiance (for OpenEXR, or a float TIFF). Throws std::runtime_error.
void writeImageFloat(const std::filesystem::path& path, int width, int height,
                     const std::vector<Rgb>& radiance, const std::string& description = "");

} // namespace prism
