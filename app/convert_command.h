// `prism convert IN OUT.sc` / `prism convert IN OUT.pov`: reads a scene in
// any format Prism knows (.sc, .nff, .obj) and writes the equivalent .sc
// scene, or POV-Ray 3.7 scene description when OUT ends in .pov.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace prism {

struct ConvertCommandOptions {
  std::string input;  // .sc, .nff or .obj
  std::string output; // the .sc or .pov file to write
  bool quiet = false; // no summary line on stderr
};

// Adds the `convert` subcommand and its options to `app`, filling `options`.
CLI::App* addConvertCommand(CLI::App& app, ConvertCommandOptions& options);

int runConvertCommand(const ConvertCommandOptions& options);

} // namespace prism
