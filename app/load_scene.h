// Loading a scene for a command-line command: errors and warnings go to stderr
// in the FILE:LINE:COLUMN form, and the caller only decides what a failure means.
// Also the commands' reporting of failed file operations.
#pragma once

#include "core/scene/scene.h"

#include <functional>
#include <optional>
#include <string>

namespace prism {

// The scene at `path` (.sc, .nff or .obj), or nothing after printing why not.
// "-" reads .sc text from standard input, named `<stdin>` in messages, its
// includes resolved against the working directory.
std::optional<Scene> loadSceneReporting(const std::string& path);

// Runs `io` (checking or writing files); if it throws, prints
// "prism: error: WHAT" and returns false.
bool succeeds(const std::function<void()>& io);

} // namespace prism
