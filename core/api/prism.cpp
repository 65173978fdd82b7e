#include "core/api/prism.h"

#include "core/io/image_io.h"
#include "core/io/picture_writer.h"
#include "core/io/scene_loader.h"
#include "core/math/model_range.h"
#include "core/render/exposure.h"
#include "core/render/parallel.h"
#include "core/render/pixel_tree.h"
#include "core/system/memory_budget.h"
#include "core/system/system_info.h"

#include <chrono>
#include <cmath>
#include <mutex>

namespace prism::api {

struct LoadedScene::State {
  Scene scene;
  std::string name; // the file, or the name given with the text
  std::vector<std::string> warnings;
  double loadSeconds = 0.0;
  // Built once, on the first render: lights and camera are not part of it.
  mutable std::once_flag built;
  mutable std::unique_ptr<Accel> accel;
  mutable double buildSeconds = 0.0;
};

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

void checkLight(const Light& light) {
  require(withinModelRange(light.position),
          std::string("a light's position must be within +-") + kMaxCoordinateText);
  for (int c = 0; c < 3; ++c)
    require(std::isfinite(light.intensity[c]) && light.intensity[c] >= 0.0,
            "a light's intensity must be finite and non-negative in each of r, g, b");
}

void checkIndex(std::size_t index, std::size_t count) {
  if (index >= count)
    throw std::out_of_range("there is no light " + std::to_string(index) + " (the scene has " +
                            std::to_string(count) + ")");
}

RenderSettings settingsFor(const LoadedScene& scene, const RenderOptions& o) {
  require((o.width == 0) == (o.height == 0), "width and height must be given together, or neither");
  require(o.width >= 0 && o.width <= 32768 && o.height >= 0 && o.height <= 32768,
          "width and height must be from 1 to 32768 pixels");
  require(o.depth >= 1 && o.depth <= 1000, "depth must be from 1 to 1000");
  require(o.thresh >= 0.0 && o.thresh <= 1.0, "thresh must be in [0, 1]");
  require(o.bailout >= 0.0 && o.bailout <= 255.0, "bailout must be in [0, 255]");
  require(o.threads >= 0 && o.threads <= 1024, "threads must be from 0 to 1024");
  RenderSettings s;
  s.width = o.width != 0 ? o.width : scene.width();
  s.height = o.height != 0 ? o.height : scene.height();
  s.maxDepth = o.depth;
  s.thresh = o.thresh;
  s.noAa = !o.antialias;
  s.jitter = o.jitter;
  s.bailout = o.bailout;
  s.threads = resolveThreadCount(o.threads);
  return s;
}

} // namespace

LoadedScene::LoadedScene(std::unique_ptr<State> state) : state_(std::move(state)) {}
LoadedScene::LoadedScene(LoadedScene&&) noexcept = default;
LoadedScene& LoadedScene::operator=(LoadedScene&&) noexcept = default;
LoadedScene::~LoadedScene() = default;

LoadedScene LoadedScene::fromFile(const std::filesystem::path& path) {
  auto state = std::make_unique<State>();
  const auto start = Clock::now();
  std::vector<Diagnostic> warnings;
  state->scene = loadAnyScene(path, &warnings);
  state->loadSeconds = secondsSince(start);
  state->name = path.string();
  for (const Diagnostic& d : warnings)
    state->warnings.push_back(formatWarning(d));
  return LoadedScene(std::move(state));
}

LoadedScene LoadedScene::fromText(std::string_view text, const std::string& name) {
  auto state = std::make_unique<State>();
  const auto start = Clock::now();
  state->scene = parseScene(text, name);
  state->loadSeconds = secondsSince(start);
  state->name = name;
  return LoadedScene(std::move(state));
}

const std::vector<std::string>& LoadedScene::warnings() const { return state_->warnings; }
const CameraSpec& LoadedScene::camera() const { return state_->scene.camera; }
const std::vector<Light>& LoadedScene::lights() const { return state_->scene.lights; }
int LoadedScene::width() const { return state_->scene.width; }
int LoadedScene::height() const { return state_->scene.height; }
const Scene& LoadedScene::scene() const { return state_->scene; }
const std::string& LoadedScene::name() const { return state_->name; }
double LoadedScene::loadSeconds() const { return state_->loadSeconds; }
double LoadedScene::buildSeconds() const { return state_->buildSeconds; }

void LoadedScene::setCamera(const CameraSpec& camera) {
  if (const std::optional<std::string> problem = cameraSpecProblem(camera))
    throw std::invalid_argument(*problem);
  state_->scene.camera = camera;
}

void LoadedScene::setLight(std::size_t index, const Light& light) {
  checkIndex(index, state_->scene.lights.size());
  checkLight(light);
  state_->scene.lights[index] = light;
}

void LoadedScene::addLight(const Light& light) {
  checkLight(light);
  state_->scene.lights.push_back(light);
}

void LoadedScene::removeLight(std::size_t index) {
  checkIndex(index, state_->scene.lights.size());
  state_->scene.lights.erase(state_->scene.lights.begin() + std::ptrdiff_t(index));
}

const Accel& LoadedScene::accel() const {
  std::call_once(state_->built, [this] {
    const auto start = Clock::now();
    state_->accel = makeAccel(state_->scene, AccelKind::Bvh);
    state_->buildSeconds = secondsSince(start);
  });
  return *state_->accel;
}

Image render(const LoadedScene& scene, const RenderOptions& options,
             const ProgressCallback& progress, std::stop_token stop) {
  const RenderSettings settings = settingsFor(scene, options);
  if (const std::optional<std::string> problem =
          memoryProblem(imageBytes(settings.width, settings.height, kRenderBytesPerPixel),
                        "a " + std::to_string(settings.width) + " x " +
                            std::to_string(settings.height) + " render"))
    throw std::runtime_error(*problem);
  const Accel& accel = scene.accel();

  const double cpuStart = processCpuSeconds();
  const auto start = Clock::now();
  RenderResult result = render(
      scene.scene(), accel, settings,
      [&](const RenderProgress& p) {
        if (progress) progress({p.pass, p.fraction});
      },
      stop.stop_possible() ? StopCheck([&stop] { return stop.stop_requested(); }) : StopCheck());
  if (result.cancelled) throw Cancelled();

  Image image;
  image.width = settings.width;
  image.height = settings.height;
  image.radiance = std::move(result.film.radiance);
  image.supersampled = std::move(result.film.supersampled);
  image.avgmax = result.avgmax;

  RenderStats& stats = image.stats;
  stats.wallSeconds = secondsSince(start);
  stats.cpuSeconds = processCpuSeconds() - cpuStart;
  stats.scene = scene.name();
  stats.machine = machineDescription();
  stats.accel = accelKindName(AccelKind::Bvh);
  stats.primitives = scene.scene().primitiveCount();
  stats.loadSeconds = scene.loadSeconds();
  stats.buildSeconds = scene.buildSeconds();
  recordInStats(settings, result, stats);
  return image;
}

namespace {

// The image as the writers take it: a finished render's film.
RenderResult asResult(const Image& image) {
  RenderResult result;
  result.film.width = image.width;
  result.film.height = image.height;
  result.film.radiance = image.radiance;
  result.film.supersampled = image.supersampled;
  result.avgmax = image.avgmax;
  result.counts = image.stats.counts;
  result.supersampledPixels = image.stats.supersampledPixels;
  return result;
}

void checkImage(const Image& image) {
  require(image.width > 0 && image.height > 0 &&
              image.radiance.size() == std::size_t(image.width) * std::size_t(image.height),
          "the image's radiance must hold width x height pixels");
}

} // namespace

std::vector<std::uint8_t> expose(const Image& image, bool srgb, double avgmax) {
  checkImage(image);
  require(std::isfinite(avgmax) && avgmax >= 0.0, "avgmax must be finite and non-negative");
  return exposeImage(image.radiance, exposureScale(avgmax > 0.0 ? avgmax : image.avgmax), srgb);
}

void write(const std::filesystem::path& path, const Image& image, const WriteOptions& options) {
  checkImage(image);
  PictureExposure exposure;
  exposure.srgb = options.srgb;
  writePicture(path, asResult(image), options.floatRadiance || isFloatFormat(path), exposure);
}

std::string statsJson(const Image& image) { return formatStatsJson(image.stats); }

RayTreeNode pixelRayTree(const LoadedScene& scene, const RenderOptions& options, int x, int y,
                         std::string* text) {
  const RenderSettings settings = settingsFor(scene, options);
  if (x < 0 || y < 0 || x >= settings.width || y >= settings.height)
    throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") is outside the " + std::to_string(settings.width) + " x " +
                                std::to_string(settings.height) + " image");
  RayCounts counts;
  RayTreeNode root = prism::pixelRayTree(scene.scene(), scene.accel(), settings, x, y, counts);
  if (text) *text = formatPixelRayTree(scene.scene(), settings, x, y, root, counts);
  return root;
}

} // namespace prism::api
