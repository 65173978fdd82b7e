// Pictures written by the program under test, read back with OIIO and
// compared pixel for pixel; small pictures for scenes to read, written with
// OIIO by tests that do not link the renderer.
#pragma once

#include "test_files.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace prism::test {

struct Picture {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<std::uint8_t> pixels; // interleaved, row 0 at the top
  const std::uint8_t* at(int x, int y) const {
    return &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels)];
  }
};

inline std::optional<Picture> readPicture(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return std::nullopt;
  const OIIO::ImageSpec& spec = in->spec();
  Picture p;
  p.width = spec.width;
  p.height = spec.height;
  p.channels = spec.nchannels;
  p.pixels.resize(std::size_t(p.width) * std::size_t(p.height) * std::size_t(p.channels));
  if (!in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::UINT8, p.pixels.data()))
    return std::nullopt;
  return p;
}

// Interleaved 8-bit RGB (row 0 at the top) as a picture of `path`'s format;
// false if it cannot be written.
inline bool writePicture8(const fs::path& path, int width, int height,
                          const std::vector<std::uint8_t>& rgb) {
  auto out = OIIO::ImageOutput::create(path.string());
  return out &&
         out->open(path.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)) &&
         out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) && out->close();
}

// True when a and b have the same size and equal RGB in every pixel.
inline bool sameRgb(const Picture& a, const Picture& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y)[c] != b.at(x, y)[c]) return false;
  return true;
}

// Where `small` appears pixel for pixel (RGB) inside `big`, if anywhere.
inline std::optional<std::pair<int, int>> findExact(const Picture& big, const Picture& small) {
  for (int oy = 0; oy + small.height <= big.height; ++oy) {
    for (int ox = 0; ox + small.width <= big.width; ++ox) {
      bool match = true;
      for (int y = 0; y < small.height && match; ++y)
        for (int x = 0; x < small.width && match; ++x)
          for (int c = 0; c < 3 && match; ++c)
            match = big.at(ox + x, oy + y)[c] == small.at(x, y)[c];
      if (match) return std::make_pair(ox, oy);
    }
  }
  return std::nullopt;
}

} // namespace prism::test
