// `prism info SCENE` (alias `prism check`): reads a scene and describes it
// without building a hierarchy or rendering: the primitives by kind, lights,
// materials, images, image size and camera, the bounds of all primitives and
// the readers' warnings, as text or JSON on stdout. Errors go to stderr as
// FILE:LINE:COLUMN lines and the exit status is 2, for editors and CI.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace prism {

struct InfoCommandOptions {
  std::string scene;
  bool json = false; // the description as one JSON object
};

// Adds the `info` subcommand (and its alias `check`) to `app`, filling `options`.
CLI::App* addInfoCommand(CLI::App& app, InfoCommandOptions& options);

int runInfoCommand(const InfoCommandOptions& options);

} // namespace prism
