// Prism as a library (docs/library.md): load a scene from a file or from
// text, change its camera and lights, render it to linear float radiance with
// progress and cancellation, expose it and write it. What the `prism` program
// does, for programs of other people: the example in examples/ and the Python
// module (python/) use this header and nothing else of the core.
//
//   prism::api::LoadedScene scene = prism::api::LoadedScene::fromFile("table.sc");
//   prism::api::RenderOptions options;
//   options.depth = 3;
//   prism::api::Image image = prism::api::render(scene, options);
//   prism::api::write("table.tif", image);
//
// Failures throw: prism::SceneError (a std::runtime_error whose what() is one
// "FILE:LINE:COLUMN: error: ..." line per problem) for a scene, and
// std::invalid_argument for a value outside its documented range, naming it;
// std::runtime_error for a file that cannot be written. Every function may be
// called from any thread; a LoadedScene may be rendered by several threads at
// once as long as none edits it meanwhile.
#pragma once

#include "core/accel/accel.h"
#include "core/io/diagnostic.h"
#include "core/render/ray_tree.h"
#include "core/render/renderer.h"
#include "core/render/stats.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

namespace prism::api {

// A scene read and ready to render. Its geometry and materials are fixed
// once read (the acceleration structure is built on the first render and
// kept); its camera and lights may change between renders. Movable, not
// copyable: read the file again for a second, independent copy.
class LoadedScene {
public:
  // A .sc, .nff or .obj file, by its extension.
  static LoadedScene fromFile(const std::filesystem::path& path);
  // .sc text, shown as `name` in messages; its includes are resolved against
  // the folder of `name` (the working directory for a bare name).
  static LoadedScene fromText(std::string_view text, const std::string& name = "<string>");

  LoadedScene(LoadedScene&&) noexcept;
  LoadedScene& operator=(LoadedScene&&) noexcept;
  ~LoadedScene();

  // The problems that did not stop the reading, "FILE:LINE:COLUMN: warning: ...".
  const std::vector<std::string>& warnings() const;

  const CameraSpec& camera() const;
  // Throws std::invalid_argument, saying why, for a camera that gives no
  // view (eye at lookat, up along the view, fov outside (0, 180), ...).
  void setCamera(const CameraSpec& camera);

  // Light i of the scene file is lights()[i - 1].
  const std::vector<Light>& lights() const;
  // Throws std::invalid_argument for a position outside the representable
  // range or an intensity that is negative or not finite, and
  // std::out_of_range for an index past the last light.
  void setLight(std::size_t index, const Light& light);
  void addLight(const Light& light);
  void removeLight(std::size_t index);

  // The resolution the scene asks for: what a render uses by default.
  int width() const;
  int height() const;

  // The scene with its current camera and lights: primitives, materials,
  // bounds, for programs that inspect it.
  const Scene& scene() const;
  // Its acceleration structure, built on the first call.
  const Accel& accel() const;

  // The file, or the name given with the text.
  const std::string& name() const;
  // What reading the scene and building the structure took (wall seconds;
  // 0 before it was built).
  double loadSeconds() const;
  double buildSeconds() const;

private:
  struct State;
  explicit LoadedScene(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// What a render is asked to do (docs/rendering-model.md, docs/image-formation.md).
struct RenderOptions {
  int width = 0;         // pixels; 0: the scene's resolution
  int height = 0;        // both given or both 0
  int depth = 5;         // maximum ray depth, >= 1 (1: eye rays and shadows only)
  double thresh = 0.1;   // antialiasing threshold in [0, 1], a fraction of avgmax
  bool antialias = true; // false: pass 1 only, one ray per pixel centre
  bool jitter = false;   // jitter pass 2's sub-samples within their cells
  double bailout = 0.0;  // >= 0; 0 traces exactly (core/render/bailout.h)
  int threads = 0;       // 0: every core this process may run on
};

struct Progress {
  int pass = 1;          // 1: pixel centres, 2: adaptive antialiasing
  double fraction = 0.0; // of the whole render, 0..1
};
// Called after each tile, from the rendering threads, one call at a time.
using ProgressCallback = std::function<void(const Progress&)>;

// Thrown by render() when its stop token was triggered.
class Cancelled : public std::runtime_error {
public:
  Cancelled() : std::runtime_error("the render was cancelled") {}
};

// A finished render: the picture's linear radiance before exposure and what
// it cost.
struct Image {
  int width = 0;
  int height = 0;
  // width * height pixels, row by row from the top left; each glm::vec3 is
  // three floats r, g, b, so the data is width * height * 3 floats.
  std::vector<Rgb> radiance;
  // 1 where pass 2 supersampled the pixel, else 0.
  std::vector<std::uint8_t> supersampled;
  double avgmax = 0.0; // mean of max(r, g, b) over pass 1's pixel centres
  RenderStats stats;   // rays, times, settings (docs/statistics.md)
};

// Renders `scene` as `options` say; the same picture, bit for bit, as
// `prism render` with the same settings. Throws std::invalid_argument for
// options out of range and Cancelled once `stop` is requested (checked
// between tiles, so within milliseconds).
Image render(const LoadedScene& scene, const RenderOptions& options,
             const ProgressCallback& progress = {}, std::stop_token stop = {});

// The 8-bit picture, 3 bytes per pixel: the automatic exposure 128 / avgmax,
// or `avgmax` instead if positive; then the model's linear values, or the
// sRGB transfer function's with `srgb`.
std::vector<std::uint8_t> expose(const Image& image, bool srgb = false, double avgmax = 0.0);

struct WriteOptions {
  bool floatRadiance = false; // the radiance before exposure (implied by .exr, .hdr)
  bool srgb = false;          // 8-bit values sRGB-encoded after exposure
};
// Writes the picture as the file's extension says (.tif, .png, .exr, ...),
// atomically. Throws std::runtime_error naming the file on failure.
void write(const std::filesystem::path& path, const Image& image, const WriteOptions& options = {});

// The statistics as `prism render --stats-json` writes them.
std::string statsJson(const Image& image);

// The ray tree of pixel (x, y) at the size and depth of `options`: the
// centre ray, every hit, the terms of the shading formula per light and the
// secondary rays (what `prism render --pixel X Y` prints). `text` gets that
// printout if not null.
RayTreeNode pixelRayTree(const LoadedScene& scene, const RenderOptions& options, int x, int y,
                         std::string* text = nullptr);

} // namespace prism::api
