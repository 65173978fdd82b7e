// The previewer's display path, drawn for real through Mesa's software OpenGL
// (OSMesa, offscreen, no X): the shader's 8-bit output must equal the CPU's
// exposeChannel, which writes the TIFF, on every pixel. This binary links
// libOSMesa instead of libGL, so gl* calls reach the OSMesa context.
#include "viewer/display.h"
#include "viewer/gl.h"

#include "core/render/exposure.h"

#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace prism {
namespace {

constexpr int kFrameWidth = 200;
constexpr int kFrameHeight = 120;

class DisplayTest : public ::testing::Test {
protected:
  void SetUp() override {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    ASSERT_NE(context_, nullptr) << "OSMesa could not create a 3.3 core context";
    frame_.assign(std::size_t(kFrameWidth) * kFrameHeight * 4, 0);
    ASSERT_TRUE(
        OSMesaMakeCurrent(context_, frame_.data(), GL_UNSIGNED_BYTE, kFrameWidth, kFrameHeight));
    display_ = std::make_unique<ImageDisplay>();
  }
  void TearDown() override {
    display_.reset(); // its GL objects go while the context is still current
    if (context_) OSMesaDestroyContext(context_);
  }

  // Clears to a marker colour, draws `radiance` at (x, y) and reads the frame back.
  std::vector<std::uint8_t> drawAndRead(int width, int height, const std::vector<Rgb>& radiance,
                                        const std::vector<std::uint8_t>& mask,
                                        const DisplayView& view) {
    glViewport(0, 0, kFrameWidth, kFrameHeight);
    glClearColor(7.0f / 255.0f, 11.0f / 255.0f, 13.0f / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    display_->upload(width, height, radiance, mask);
    display_->draw(view);
    glFinish();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return readPixelsRgb(0, 0, kFrameWidth, kFrameHeight);
  }

  OSMesaContext context_ = nullptr;
  std::vector<std::uint8_t> frame_;
  std::unique_ptr<ImageDisplay> display_;
};

// Radiance values that probe every branch of exposeChannel at `scale`: exact
// integers, exact halves and their float neighbours (rounding), values around
// 255 (clamping), zero, negative and infinite radiance, then random values.
std::vector<Rgb> probeValues(float scale, std::size_t count) {
  std::vector<float> v;
  const float inf = std::numeric_limits<float>::infinity();
  for (int k = 0; k <= 256; ++k) {
    for (float target : {float(k), float(k) + 0.5f}) {
      const float r = target / scale;
      v.push_back(r);
      v.push_back(std::nextafter(r, 0.0f));
      v.push_back(std::nextafter(r, inf));
    }
  }
  for (float r :
       {0.0f, -0.0f, -1.0f, 1e-30f, 1e30f, inf, 255.0f / scale, 254.5f / scale, 300.0f / scale})
    v.push_back(r);
  std::mt19937 random(12345);
  std::uniform_real_distribution<float> uniform(0.0f, 3.0f / scale * 128.0f);
  while (v.size() < count * 3)
    v.push_back(uniform(random));
  std::vector<Rgb> pixels(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Shuffle channels so each branch is exercised in r, g and b.
    pixels[i] = Rgb(v[(i * 3) % v.size()], v[(i * 3 + count + 1) % v.size()],
                    v[(i * 3 + 2 * count + 2) % v.size()]);
  }
  return pixels;
}

// Every pixel of the drawn rectangle equals exposeChannel; every pixel outside
// it keeps the clear colour.
void expectExposed(const std::vector<std::uint8_t>& frame, int width, int height,
                   const std::vector<Rgb>& radiance, float scale, int x0, int y0) {
  int mismatches = 0;
  for (int fy = 0; fy < kFrameHeight; ++fy) {
    for (int fx = 0; fx < kFrameWidth; ++fx) {
      const std::uint8_t* got = &frame[(std::size_t(fy) * kFrameWidth + std::size_t(fx)) * 3];
      // Frame rows are top-down; the view's y0 counts from the bottom.
      const int ix = fx - x0;
      const int iy = fy - (kFrameHeight - y0 - height);
      std::uint8_t want[3] = {7, 11, 13};
      if (ix >= 0 && ix < width && iy >= 0 && iy < height) {
        const Rgb& c = radiance[std::size_t(iy) * std::size_t(width) + std::size_t(ix)];
        want[0] = exposeChannel(c.r, scale);
        want[1] = exposeChannel(c.g, scale);
        want[2] = exposeChannel(c.b, scale);
      }
      for (int ch = 0; ch < 3; ++ch) {
        if (got[ch] != want[ch] && ++mismatches <= 10) {
          const Rgb& c = radiance[std::size_t(std::max(iy, 0)) * std::size_t(width) +
                                  std::size_t(std::max(ix, 0))];
          ADD_FAILURE() << "frame pixel (" << fx << ", " << fy << ") channel " << ch << ": shader "
                        << int(got[ch]) << ", exposeChannel " << int(want[ch]) << " (radiance "
                        << c[ch] << ", scale " << scale << ")";
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST_F(DisplayTest, ShaderEqualsExposeChannelWithPowerOfTwoScale) {
  const int w = 64, h = 48;
  const float scale = exposureScale(1.0); // 128: halves are exact in float
  ASSERT_EQ(scale, 128.0f);
  const auto radiance = probeValues(scale, std::size_t(w) * h);
  const std::vector<std::uint8_t> mask(radiance.size(), 0);
  DisplayView view;
  view.x = 5;
  view.y = 9;
  view.scale = scale;
  expectExposed(drawAndRead(w, h, radiance, mask, view), w, h, radiance, scale, view.x, view.y);
}

TEST_F(DisplayTest, ShaderEqualsExposeChannelWithArbitraryScale) {
  const int w = 150, h = 100;
  for (double avgmax : {0.716458, 3.3, 1e-3, 1234.5}) {
    const float scale = exposureScale(avgmax);
    const auto radiance = probeValues(scale, std::size_t(w) * h);
    const std::vector<std::uint8_t> mask(radiance.size(), 1); // ignored: overlay off
    DisplayView view;
    view.x = 31;
    view.y = 0;
    view.scale = scale;
    SCOPED_TRACE(avgmax);
    expectExposed(drawAndRead(w, h, radiance, mask, view), w, h, radiance, scale, view.x, view.y);
  }
}

TEST_F(DisplayTest, ZeroAvgmaxIsBlack) {
  const int w = 40, h = 30;
  const float scale = exposureScale(0.0);
  ASSERT_EQ(scale, 0.0f);
  auto radiance = probeValues(1.0f, std::size_t(w) * h);
  for (Rgb& c : radiance) // inf * 0 is NaN; a film never holds inf
    for (int i = 0; i < 3; ++i)
      c[i] = std::min(c[i], 1e30f);
  const std::vector<std::uint8_t> mask(radiance.size(), 0);
  DisplayView view;
  view.scale = scale;
  const auto frame = drawAndRead(w, h, radiance, mask, view);
  expectExposed(frame, w, h, radiance, scale, 0, 0);
}

TEST_F(DisplayTest, OverlayTintsOnlySupersampledPixels) {
  const int w = 16, h = 8;
  std::vector<Rgb> radiance(std::size_t(w) * h, Rgb(0.5f, 0.25f, 0.125f));
  std::vector<std::uint8_t> mask(radiance.size(), 0);
  for (std::size_t i = 0; i < mask.size(); i += 3)
    mask[i] = 1;
  DisplayView view;
  view.scale = 128.0f;
  view.overlay = true;
  const auto frame = drawAndRead(w, h, radiance, mask, view);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* got =
          &frame[(std::size_t(kFrameHeight - h + y) * kFrameWidth + std::size_t(x)) * 3];
      const bool tinted = got[0] != 64 || got[1] != 32 || got[2] != 16;
      EXPECT_EQ(tinted, mask[std::size_t(y) * w + std::size_t(x)] != 0) << x << ", " << y;
    }
  }
}

TEST_F(DisplayTest, ScaledToFitSamplesNearestPixels) {
  // At zoom 0.5 each framebuffer pixel shows one image pixel of its 2x2 block.
  const int w = 32, h = 16;
  std::vector<Rgb> radiance(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      radiance[std::size_t(y) * w + std::size_t(x)] =
          Rgb(float(x) / 128.0f, float(y) / 128.0f, 0.0f);
  const std::vector<std::uint8_t> mask(radiance.size(), 0);
  DisplayView view;
  view.scale = 128.0f;
  view.zoom = 0.5f;
  const auto frame = drawAndRead(w, h, radiance, mask, view);
  for (int y = 0; y < h / 2; ++y) {
    for (int x = 0; x < w / 2; ++x) {
      const std::uint8_t* got =
          &frame[(std::size_t(kFrameHeight - h / 2 + y) * kFrameWidth + std::size_t(x)) * 3];
      EXPECT_EQ(got[0] / 2, x) << x << ", " << y;
      EXPECT_EQ(got[1] / 2, y) << x << ", " << y;
    }
  }
}

} // namespace
} // namespace prism
