// `prism render`: load a scene, render it headless, write the picture and the
// statistics. Also the --pixel ray-tree mode.
#pragma once

#include "core/accel/accel.h"
#include "core/render/process_group.h"
#include "core/render/renderer.h"
#include "core/scene/camera.h"
#include "core/scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace prism {

// "-" as a file name (docs/command-line.md): the scene read from standard
// input, the picture or the JSON statistics written to standard output.
inline constexpr const char* kStdio = "-";

struct RenderCommandOptions {
  std::string scene;          // a file, or "-": the .sc text on standard input
  std::string output;         // image path; the format follows its extension ("-": stdout)
  std::string format;         // with `-o -`: the picture's format ("png", "tiff", ...)
  std::optional<int> depth;   // max ray depth (default 5)
  double thresh = 0.1;        // antialiasing threshold
  std::vector<int> size;      // W H, overriding the scene's `resolution`
  std::vector<double> eye;    // X Y Z, overriding the scene's camera (empty: the scene's)
  std::vector<double> lookat; // X Y Z
  std::optional<double> fov;  // degrees
  int threads = 0;            // 0: all cores
  bool jitter = false;
  bool noAa = false;      // pass 1 only
  double bailout = 0.0;   // W levels; 0 traces exactly
  bool floatTiff = false; // write float radiance instead of 8-bit pixels
  bool srgb = false;      // 8-bit values sRGB-encoded after exposure
  double scale = 100.0;   // percent of the scene's resolution (not with --size)
  std::vector<int> crop;  // X0 Y0 X1 Y1: pass 2 and the output only in this region
  AccelKind accel = AccelKind::Bvh;
  std::string statsJson;  // where to write the statistics as JSON ("-": stdout)
  std::vector<int> pixel; // X Y: print this pixel's ray tree instead of rendering
  bool quiet = false;     // no progress, no statistics on stderr
};

// Exit codes (docs/command-line.md): 0 success, 1 render/IO failure, 2 usage or scene error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// Adds the options every rendering command shares (--depth, --thresh, --size,
// --threads, --jitter, --no-aa, --bailout, --accel, --eye, --lookat, --fov) to `command`, filling
// `options`.
void addRenderSettingsOptions(CLI::App& command, RenderCommandOptions& options);

// The camera options, each on its own, checked with the scene language's rules
// before anything is loaded: --fov strictly between 0 and 180 degrees, points
// within +-kMaxCoordinate. Returns the message (without "prism: error: ").
std::optional<std::string> cameraOptionsProblem(const RenderCommandOptions& options);

// The one place the camera options are applied, for `render`, `view` and its
// headless fallback: puts them over `camera` (the loaded scene's) and checks
// the view they make as the scene language does (eye != lookat, the scene's
// `up` not parallel to the new view direction), after cameraOptionsProblem.
// On a problem `camera` is left as it was and the message is returned.
std::optional<std::string> applyCameraOptions(const RenderCommandOptions& options,
                                              CameraSpec& camera);
bool hasCameraOptions(const RenderCommandOptions& options);

// The one place the options become render settings, for `render`, `view` and
// its headless fallback: --size over the scene's resolution, depth, threshold,
// jitter, no-AA, bailout, threads; --scale (render only) shrinks the scene's
// resolution to PERCENT of each side, rounded, at least 1 pixel.
RenderSettings renderSettings(const RenderCommandOptions& options, const Scene& scene);

// Why an image of `settings`' size, at `bytesPerPixel`, cannot fit in memory
// ("a 32768 x 32768 render needs ..."), or nothing. `what`: "render", "preview".
std::optional<std::string> imageMemoryProblem(const RenderSettings& settings,
                                              std::uint64_t bytesPerPixel, const std::string& what);

// Adds the `render` subcommand to `app`, filling `options`.
CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& options);

// `group`: the processes of an MPI job rendering the picture together
// (docs/distributed.md), or null for a render on this process alone.
int runRenderCommand(const RenderCommandOptions& options, ProcessGroup* group = nullptr);

} // namespace prism
