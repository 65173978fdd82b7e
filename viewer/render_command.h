// `prism render`: load a scene, render it headless, write the picture and the
// statistics. Also the --pixel ray-tree mode.
#pragma once

#include "core/accel.h"
#include "core/renderer.h"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace prism {

struct RenderCommandOptions {
  std::string scene;
  std::string output;       // image path; the format follows its extension
  std::optional<int> depth; // max ray depth (default 5)
  double thresh = 0.1;      // antialiasing threshold
  std::vector<int> size;    // W H, overriding the scene's `resolution`
  int threads = 0;          // 0: all cores
  bool jitter = false;
  bool floatTiff = false; // write float radiance instead of 8-bit pixels
  AccelKind accel = AccelKind::Bvh;
  std::string statsJson;  // where to write the statistics as JSON
  std::vector<int> pixel; // X Y: print this pixel's ray tree instead of rendering
  bool quiet = false;     // no progress, no statistics on stderr
};

// Exit codes of SPEC 5: 0 success, 1 render/IO failure, 2 usage or scene error.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// Adds the options every rendering command shares (--depth, --thresh, --size,
// --threads, --jitter, --accel) to `command`, filling `options`.
void addRenderSettingsOptions(CLI::App& command, RenderCommandOptions& options);

// Adds the `render` subcommand to `app`, filling `options`.
CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& options);

int runRenderCommand(const RenderCommandOptions& options);

} // namespace prism
