// Drawing the radiance buffer: texture upload and the exposure shader. The
// shader maps radiance to 8-bit values exactly as core/render/exposure's
// exposeChannel does (a test holds them equal through Mesa), so the window shows
// the pixels the saved TIFF will hold. Plain OpenGL 3.3 core: no ImGui and no
// window here, so an offscreen (OSMesa) test can link it against libOSMesa.
#pragma once

#include "core/render/film.h"

#include <cstdint>
#include <vector>

namespace prism {

// Where and how to draw the image, in framebuffer pixels with GL's orientation
// (origin at the bottom-left corner).
struct DisplayView {
  int x = 0; // lower-left corner of the image
  int y = 0;
  float zoom = 1.0f;    // framebuffer pixels per image pixel (1: 1:1, < 1: scaled to fit)
  float scale = 0.0f;   // exposure, exposureScale(avgmax): 128 / avgmax, 0 for black
  bool overlay = false; // tint the supersampled pixels
  // Only the part of the image inside this rectangle is drawn (a zoomed image
  // may be far larger than the window); none when clipWidth is 0.
  int clipX = 0, clipY = 0, clipWidth = 0, clipHeight = 0;
};

class ImageDisplay {
public:
  // Needs a current OpenGL 3.3 core context. Throws std::runtime_error when the
  // shader does not compile or link.
  ImageDisplay();
  ~ImageDisplay();
  ImageDisplay(const ImageDisplay&) = delete;
  ImageDisplay& operator=(const ImageDisplay&) = delete;

  // Replaces the image: `radiance` and `supersampled` hold width * height
  // pixels, row 0 at the top.
  void upload(int width, int height, const std::vector<Rgb>& radiance,
              const std::vector<std::uint8_t>& supersampled);

  // Draws the image into the rectangle `view` describes (width() * zoom by
  // height() * zoom pixels), within its clip rectangle; nothing outside both
  // is touched.
  void draw(const DisplayView& view) const;

  int width() const { return width_; }
  int height() const { return height_; }

private:
  unsigned program_ = 0;
  unsigned vertexArray_ = 0;
  unsigned radianceTexture_ = 0;
  unsigned maskTexture_ = 0;
  int width_ = 0;
  int height_ = 0;
};

// The current read framebuffer's pixels in [x, x + width) x [y, y + height) as
// interleaved 8-bit RGB, row 0 at the top (ready for writeImage8).
std::vector<std::uint8_t> readPixelsRgb(int x, int y, int width, int height);

} // namespace prism
