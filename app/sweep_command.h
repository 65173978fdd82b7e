// `prism sweep SCENE -o DIR`: renders a reference picture of the scene and
// the scene under a grid of settings, and writes what each setting costs
// and how far its picture is from the reference (docs/choosing-settings.md):
// DIR/sweep.csv, DIR/sweep.json, DIR/reference.png and the plots.
#pragma once

#include "core/render/process_group.h"
#include "core/sweep/sweep_runner.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace prism {

struct SweepCommandOptions {
  std::string scene;
  std::string output;                        // the folder of the results (created if missing)
  std::vector<int> size;                     // W H, overriding the scene's resolution
  bool quick = false;                        // the scene's picture at 128 pixels on its longer side
  int threads = 0;                           // 0: all cores
  bool quiet = false;                        // no progress and no summary on stderr
  double minSeconds = kSweepMinTimedSeconds; // SweepGrid::minTimedSeconds
};

// The --quick size: the scene's aspect at 128 pixels on the longer side.
inline constexpr int kQuickSweepSide = 128;

CLI::App* addSweepCommand(CLI::App& app, SweepCommandOptions& options);

// `group`: the processes of an MPI job sharing the sweep's settings
// (docs/distributed.md), or null for a sweep on this process alone.
int runSweepCommand(const SweepCommandOptions& options, ProcessGroup* group = nullptr);

} // namespace prism
