// `prism bench`: acceleration and throughput figures for scenes given on the
// command line and a scaling series on generated scenes of 10^3 to 10^6
// primitives (see docs/performance.md).
#pragma once

#include "core/accel/accel.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace prism {

struct BenchCommandOptions {
  std::vector<std::string> scenes;
  std::vector<AccelKind> accels{AccelKind::Bvh, AccelKind::Groups, AccelKind::None};
  int size = 512; // full renders and eye rays at size x size
  int depth = 5;
  double thresh = 0.1;
  int threads = 0;     // "all threads"; 0: every core
  double budget = 2.0; // seconds per throughput figure before sampling
  bool scaling = true; // run the scaling series
  std::size_t scalingMax = 1000000;
  std::string data;     // write the scaling series here (for gnuplot)
  bool latency = false; // measure the previewer's answer to a light move instead
  bool startup = false; // measure the cost of starting prism instead
};

// Adds the `bench` subcommand and its options to `app`, filling `options`.
CLI::App* addBenchCommand(CLI::App& app, BenchCommandOptions& options);

int runBenchCommand(const BenchCommandOptions& options);

} // namespace prism
