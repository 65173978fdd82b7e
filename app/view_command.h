// `prism view`: the interactive previewer, or a headless render when there is
// no display to show it on. Also makes `view` the command of `prism SCENE`.
#pragma once

#include "render_command.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace prism {

struct ViewCommandOptions {
  RenderCommandOptions render; // scene, -o (the Save field; the fallback's output), settings
  std::string script;          // a scripted session (see viewer/view_script.h)
  std::string dumpWidgets;     // --dump-widgets: the window's widgets, every frame (tests)
  std::string sweep;           // --sweep: the scene's sweep table [SCENE-STEM.sweep.csv beside it]
};

// Registers the `view` subcommand and its options on `app`.
CLI::App* addViewCommand(CLI::App& app, ViewCommandOptions& options);

// The arguments with `view` inserted when the first one names an existing file
// rather than a subcommand or an option: `prism SCENE ...` is `prism view SCENE ...`.
std::vector<const char*> withDefaultCommand(const CLI::App& app, int argc, char** argv);

int runViewCommand(const ViewCommandOptions& options);

} // namespace prism
