#include "display.h"

#include "gl.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace prism {

namespace {

// A triangle that covers the viewport, made from gl_VertexID alone (no buffers).
constexpr const char* kVertexShader = R"(#version 330 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

// exposeChannel in GLSL. Rounding half away from zero is written as a
// comparison with floor(v) + 0.5 rather than round() (whose halves GLSL leaves
// open) or floor(v + 0.5) (wrong just below a half: 0.49999997 + 0.5 rounds up
// to 1.0). Only floor and comparisons touch v = radiance * scale, so no fused
// multiply-add can change it. Texels are fetched by integer coordinate: no
// filtering, no interpolation.
constexpr const char* kFragmentShader = R"(#version 330 core
uniform sampler2D radiance;
uniform sampler2D supersampled;
uniform ivec2 imageSize;
uniform vec2 origin;     // lower-left corner of the image, framebuffer pixels
uniform float zoom;      // framebuffer pixels per image pixel
uniform float scale;     // 128 / avgmax
uniform bool overlay;
out vec4 color;

float expose(float radianceValue) {
  float v = radianceValue * scale;
  if (!(v > 0.0)) return 0.0;  // also NaN
  if (v >= 255.0) return 255.0;
  float f = floor(v);
  return v >= f + 0.5 ? f + 1.0 : f;
}

void main() {
  ivec2 texel = ivec2(floor((gl_FragCoord.xy - origin) / zoom));
  texel.y = imageSize.y - 1 - texel.y;  // image row 0 is the top
  texel = clamp(texel, ivec2(0), imageSize - 1);
  vec3 c = texelFetch(radiance, texel, 0).rgb;
  vec3 exposed = vec3(expose(c.r), expose(c.g), expose(c.b));
  if (overlay && texelFetch(supersampled, texel, 0).r > 0.0)
    exposed = mix(exposed, vec3(255.0, 0.0, 200.0), 0.55);
  color = vec4(exposed / 255.0, 1.0);
}
)";

// Throws with the driver's log when compiling a shader or linking a program
// (`object`) failed `status`, deleting the object first. The three GL
// functions are the shader's or the program's versions.
template <class GetStatus, class GetLog, class Delete>
void requireBuilt(GLuint object, GLenum status, GetStatus getStatus, GetLog getLog, Delete destroy,
                  const char* failure) {
  GLint ok = GL_FALSE;
  getStatus(object, status, &ok);
  if (ok) return;
  char log[2048] = {};
  getLog(object, sizeof log, nullptr, log);
  destroy(object);
  throw std::runtime_error(std::string("display shader ") + failure + ": " + log);
}

unsigned compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  requireBuilt(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader,
               "does not compile");
  return shader;
}

unsigned makeTexture() {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

} // namespace

ImageDisplay::ImageDisplay() {
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  requireBuilt(program_, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram,
               "does not link");
  glGenVertexArrays(1, &vertexArray_);
  radianceTexture_ = makeTexture();
  maskTexture_ = makeTexture();
}

ImageDisplay::~ImageDisplay() {
  glDeleteTextures(1, &maskTexture_);
  glDeleteTextures(1, &radianceTexture_);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteProgram(program_);
}

void ImageDisplay::upload(int width, int height, const std::vector<Rgb>& radiance,
                          const std::vector<std::uint8_t>& supersampled) {
  const bool resized = width != width_ || height != height_;
  width_ = width;
  height_ = height;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // mask rows are not 4-byte aligned
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glBindTexture(GL_TEXTURE_2D, radianceTexture_);
  if (resized) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width, height, 0, GL_RGB, GL_FLOAT, radiance.data());
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_FLOAT, radiance.data());
  }
  glBindTexture(GL_TEXTURE_2D, maskTexture_);
  if (resized) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, width, height, 0, GL_RED, GL_UNSIGNED_BYTE,
                 supersampled.data());
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RED, GL_UNSIGNED_BYTE,
                    supersampled.data());
  }
}

void ImageDisplay::draw(const DisplayView& view) const {
  if (width_ <= 0 || height_ <= 0) return;
  // The image's rectangle, within the clip rectangle: the viewport. The
  // shader finds each fragment's texel from the origin and the zoom, so the
  // viewport may be any part of the image (a zoom of 64 would make the whole
  // image far larger than a viewport may be).
  long long x0 = view.x, y0 = view.y;
  long long x1 = x0 + std::max(1LL, (long long)(double(width_) * view.zoom + 0.5));
  long long y1 = y0 + std::max(1LL, (long long)(double(height_) * view.zoom + 0.5));
  if (view.clipWidth > 0) {
    x0 = std::max<long long>(x0, view.clipX);
    y0 = std::max<long long>(y0, view.clipY);
    x1 = std::min<long long>(x1, (long long)view.clipX + view.clipWidth);
    y1 = std::min<long long>(y1, (long long)view.clipY + view.clipHeight);
  }
  if (x1 <= x0 || y1 <= y0) return;
  glViewport(int(x0), int(y0), int(x1 - x0), int(y1 - y0));
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_FRAMEBUFFER_SRGB); // the shader writes display values, not linear ones
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, radianceTexture_);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, maskTexture_);
  glUniform1i(glGetUniformLocation(program_, "radiance"), 0);
  glUniform1i(glGetUniformLocation(program_, "supersampled"), 1);
  glUniform2i(glGetUniformLocation(program_, "imageSize"), width_, height_);
  glUniform2f(glGetUniformLocation(program_, "origin"), float(view.x), float(view.y));
  glUniform1f(glGetUniformLocation(program_, "zoom"), view.zoom);
  glUniform1f(glGetUniformLocation(program_, "scale"), view.scale);
  glUniform1i(glGetUniformLocation(program_, "overlay"), view.overlay ? 1 : 0);
  glBindVertexArray(vertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
}

std::vector<std::uint8_t> readPixelsRgb(int x, int y, int width, int height) {
  std::vector<std::uint8_t> bottomUp(std::size_t(width) * std::size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glReadPixels(x, y, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
  // GL's rows run bottom-up; pictures are written top-down.
  std::vector<std::uint8_t> topDown(bottomUp.size());
  const std::size_t row = std::size_t(width) * 3;
  for (int r = 0; r < height; ++r) {
    std::copy_n(bottomUp.begin() + std::ptrdiff_t(std::size_t(height - 1 - r) * row), row,
                topDown.begin() + std::ptrdiff_t(std::size_t(r) * row));
  }
  return topDown;
}

} // namespace prism
