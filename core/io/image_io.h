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

// Whether a picture can be written in the format of `path`'s extension
// (TIFF and PNG always; others when the OpenImageIO module has a writer).
bool hasImageFormat(const std::filesystem::path& path);

// Interleaved 8-bit RGB (row 0 at the top). `description`, when given, is
// stored as the file's ImageDescription (how the picture was exposed).
// `srgb`: the values are sRGB-encoded, and a PNG says so with an sRGB chunk
// (other formats in the description only). Throws std::runtime_error on failure.
void writeImage8(const std::filesystem::path& path, int width, int height,
                 const std::vector<std::uint8_t>& rgb, const std::string& description = "",
                 bool srgb = false);

// Float RGB radiance (for OpenEXR, or a float TIFF). Throws std::runtime_error.
void writeImageFloat(const std::filesystem::path& path, int width, int height,
                     const std::vector<Rgb>& radiance, const std::string& description = "");

// The same two, written straight into `file` (no temporary of their own, no
// rename), in the format of `file`'s extension; errors name `target`. For a
// caller that owns the file, as a PendingFile's temporary.
void writeImage8Into(const std::filesystem::path& file, const std::filesystem::path& target,
                     int width, int height, const std::vector<std::uint8_t>& rgb,
                     const std::string& description, bool srgb);
void writeImageFloatInto(const std::filesystem::path& file, const std::filesystem::path& target,
                         int width, int height, const std::vector<Rgb>& radiance,
                         const std::string& description);

} // namespace prism
