// The image-texture half of libprism_oiio.so (core/io/oiio_module.h): images
// are read once, decoded to linear float RGB, and served to a private
// OpenImageIO TextureSystem from memory, which builds the MIP levels on
// demand (the ImageCache's `automip`) and filters each lookup over the
// footprint it is given. Decoding before the TextureSystem sees the pixels is
// what makes its filters average light rather than sRGB code values: the
// TextureSystem of OpenImageIO 2.4 has no colour conversion of its own.
#include "core/io/module_error.h"
#include "core/io/oiio_module.h"
#include "core/texture/srgb.h"

#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace {

// Images larger than this many texels are refused: bounded memory for a
// scene that names a huge (or lying) file. 2^26 texels is 768 MB of floats.
constexpr long long kMaxTexels = 1ll << 26;

struct LinearImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb; // rows from the top, 3 floats per texel
};

// Hands a LinearImage to the ImageCache as if it were a file. The image is
// found through the open() configuration ("prism:image", a pointer), which
// the ImageCache keeps and passes again whenever it reopens the "file".
class MemoryImageInput final : public OIIO::ImageInput {
public:
  const char* format_name() const override { return "prism-memory"; }
  bool open(const std::string&, OIIO::ImageSpec&) override { return false; }
  bool open(const std::string&, OIIO::ImageSpec& newspec, const OIIO::ImageSpec& config) override {
    const OIIO::ParamValue* p = config.find_attribute("prism:image", OIIO::TypeDesc::PTR);
    if (p == nullptr) return false;
    image_ = *static_cast<const LinearImage* const*>(p->data());
    m_spec = OIIO::ImageSpec(image_->width, image_->height, 3, OIIO::TypeDesc::FLOAT);
    newspec = m_spec;
    return true;
  }
  bool close() override {
    image_ = nullptr;
    return true;
  }
  bool seek_subimage(int subimage, int miplevel) override { return subimage == 0 && miplevel == 0; }
  bool read_native_scanline(int subimage, int miplevel, int y, int, void* data) override {
    if (subimage != 0 || miplevel != 0 || image_ == nullptr || y < 0 || y >= image_->height)
      return false;
    const std::size_t row = std::size_t(image_->width) * 3;
    std::memcpy(data, image_->rgb.data() + std::size_t(y) * row, row * sizeof(float));
    return true;
  }

private:
  const LinearImage* image_ = nullptr;
};

OIIO::ImageInput* createMemoryInput() { return new MemoryImageInput; }

// One TextureSystem (with its own ImageCache) for the process, made on first
// use and never destroyed: OpenImageIO 2.4's TextureSystem::destroy deletes
// through a pointer of the wrong type (AddressSanitizer reports a
// new-delete-type-mismatch), and one cache for all scenes bounds the memory
// of MIP levels however many scenes the previewer reloads. Each library's
// images have names of their own, and are invalidated when it goes.
OIIO::TextureSystem* textureSystem() {
  static OIIO::TextureSystem* const system = [] {
    OIIO::TextureSystem* ts = OIIO::TextureSystem::create(false);
    OIIO::ImageCache* cache = ts->imagecache();
    cache->attribute("automip", 1);
    cache->attribute("forcefloat", 1);
    return ts;
  }();
  return system;
}

struct Library {
  std::string prefix; // unique to the library: its images' names start with it
  std::mutex mutex;   // loading only; lookups are the TextureSystem's, thread-safe
  std::vector<std::unique_ptr<LinearImage>> images;
  std::vector<OIIO::ustring> names;
  std::vector<OIIO::TextureSystem::TextureHandle*> handles;
};

bool floatingPoint(OIIO::TypeDesc format) {
  return format.basetype == OIIO::TypeDesc::FLOAT || format.basetype == OIIO::TypeDesc::HALF ||
         format.basetype == OIIO::TypeDesc::DOUBLE;
}

// sRGB for integer pixels unless the file says it holds linear values.
bool decodesAsSrgb(const OIIO::ImageSpec& spec, int encoding) {
  if (encoding != 0) return encoding == 1;
  if (floatingPoint(spec.format)) return false;
  const std::string space = spec.get_string_attribute("oiio:ColorSpace");
  return !OIIO::Strutil::iequals(space, "linear");
}

// Reads the file into linear RGB (grey is copied to all three channels, an
// alpha channel is ignored), or says why not.
std::string readLinear(const char* path, int encoding, LinearImage& out, bool& srgb) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    const std::string why = OIIO::geterror();
    return why.empty() ? "not an image OpenImageIO can read" : why;
  }
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0)
    return "not a 2D image with pixels";
  if ((long long)spec.width * spec.height > kMaxTexels)
    return std::to_string(spec.width) + " x " + std::to_string(spec.height) +
           " texels is more than the " + std::to_string(kMaxTexels) + " an image texture may have";
  const int channels = spec.nchannels;
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    const std::string why = in->geterror();
    return why.empty() ? "cannot read its pixels" : why;
  }
  srgb = decodesAsSrgb(spec, encoding);
  out.width = spec.width;
  out.height = spec.height;
  out.rgb.resize(std::size_t(spec.width) * spec.height * 3);
  for (std::size_t i = 0, n = std::size_t(spec.width) * spec.height; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const int from = channels >= 3 ? c : 0; // grey (and grey + alpha) to all three
      double v = pixels[i * std::size_t(channels) + std::size_t(from)];
      if (srgb) v = prism::srgbToLinear(std::clamp(v, 0.0, 1.0));
      // No NaN, infinity or negative light reaches a pixel.
      out.rgb[i * 3 + std::size_t(c)] = std::isfinite(v) && v > 0.0 ? float(v) : 0.0f;
    }
  }
  return {};
}

OIIO::TextureOpt::Wrap wrapOf(int wrap) {
  switch (wrap) {
  case 1: return OIIO::TextureOpt::WrapClamp;
  case 2: return OIIO::TextureOpt::WrapMirror;
  case 3: return OIIO::TextureOpt::WrapBlack;
  default: return OIIO::TextureOpt::WrapPeriodic;
  }
}

} // namespace

extern "C" __attribute__((visibility("default"))) void* prism_oiio_texture_create() {
  static std::atomic<unsigned long long> made{0};
  auto* library = new Library;
  library->prefix = "prism-image-" + std::to_string(made++) + "-";
  return library;
}

extern "C" __attribute__((visibility("default"))) void prism_oiio_texture_destroy(void* handle) {
  auto* library = static_cast<Library*>(handle);
  if (library == nullptr) return;
  // Its cache entries and tiles go before its pixels do.
  for (const OIIO::ustring& name : library->names)
    textureSystem()->imagecache()->invalidate(name, true);
  delete library;
}

extern "C" __attribute__((visibility("default"))) int
prism_oiio_texture_load(void* handle, const char* path, int encoding, prism::PrismTextureInfo* info,
                        char* error, std::size_t errorSize) {
  auto* library = static_cast<Library*>(handle);
  auto image = std::make_unique<LinearImage>();
  bool srgb = false;
  if (const std::string why = readLinear(path, encoding, *image, srgb); !why.empty()) {
    prism::copyModuleError(error, errorSize, why);
    return -1;
  }
  info->width = image->width;
  info->height = image->height;
  info->encoding = srgb ? 1 : 2;
  for (int c = 0; c < 3; ++c) {
    float peak = 0.0f;
    for (std::size_t i = std::size_t(c); i < image->rgb.size(); i += 3)
      peak = std::max(peak, image->rgb[i]);
    info->peak[c] = peak;
  }
  const std::lock_guard lock(library->mutex);
  const int index = int(library->images.size());
  const OIIO::ustring name(library->prefix + std::to_string(index));
  OIIO::ImageSpec config;
  const LinearImage* pointer = image.get();
  config.attribute("prism:image", OIIO::TypeDesc::PTR, &pointer);
  library->images.push_back(std::move(image));
  OIIO::TextureSystem* textures = textureSystem();
  OIIO::TextureSystem::TextureHandle* texture = nullptr;
  if (textures->imagecache()->add_file(name, createMemoryInput, &config))
    texture = textures->get_texture_handle(name);
  if (texture == nullptr || !textures->good(texture)) {
    textures->imagecache()->invalidate(name, true);
    library->images.pop_back();
    const std::string why = textures->geterror();
    prism::copyModuleError(error, errorSize, why.empty() ? "the texture system refused it" : why);
    return -1;
  }
  library->names.push_back(name);
  library->handles.push_back(texture);
  return index;
}

extern "C" __attribute__((visibility("default"))) int
prism_oiio_texture_lookup(void* handle, int index, float s, float t, float dsdx, float dtdx,
                          float dsdy, float dtdy, int wrap, int filtered, float* rgb) {
  auto* library = static_cast<Library*>(handle);
  OIIO::TextureOpt options;
  options.swrap = options.twrap = wrapOf(wrap);
  // Bilinear within a level: the filters are then weighted averages with
  // non-negative weights, so no lookup exceeds the image's largest texel
  // (the bicubic default rings past it; bounds over materials rely on this).
  options.interpmode = OIIO::TextureOpt::InterpBilinear;
  if (filtered == 0) {
    options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    options.interpmode = OIIO::TextureOpt::InterpClosest;
  }
  OIIO::TextureSystem* textures = textureSystem();
  OIIO::TextureSystem::Perthread* thread = textures->get_perthread_info();
  if (textures->texture(library->handles[std::size_t(index)], thread, options, s, t, dsdx, dtdx,
                        dsdy, dtdy, 3, rgb))
    return 1;
  textures->geterror(); // consumed, so it does not pile up
  rgb[0] = rgb[1] = rgb[2] = 0.0f;
  return 0;
}
