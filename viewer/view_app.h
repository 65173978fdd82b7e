// The previewer's window: GLFW, the image drawn by ImageDisplay, the ImGui
// panel, mouse navigation and light markers, and the frame loop that keeps
// all of it responsive while the render threads work.
#pragma once

#include "view_controller.h"
#include "view_script.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace prism {

// Starts GLFW. Returns false, with the reason in `why`, when there is no
// display to open a window on.
bool openWindowSystem(std::string& why);
void closeWindowSystem();

// How far loading the scene has got, for the window that is already open.
struct LoadProgress {
  std::atomic<int> stage{0};              // 0: reading the files, 1: building the hierarchy
  std::atomic<std::size_t> primitives{0}; // known from stage 1 on
};

// The previewer ready to run: a controller over the loaded scene, or the
// exit code of a failure already reported on stderr (a scene error, say).
struct PreparedView {
  std::unique_ptr<ViewController> controller;
  int exitCode = 0;
};

struct ViewAppOptions {
  std::string scenePath;                           // for the title and the loading screen
  int width = 0, height = 0;                       // the image size, when known before loading
  std::optional<std::vector<ScriptAction>> script; // a scripted session
  std::string dumpWidgets; // write the widgets of every frame to this file (for tests)
  std::string savePath;    // the Save field's initial text
  // Reads the scene and builds the controller (and so the hierarchy); runs on
  // a thread of its own while the window shows how far it got.
  std::function<PreparedView(LoadProgress&)> prepare;
};

// Opens the window at once and runs the previewer until the window closes or
// the script quits, and returns the exit code. Returns nothing, with the
// reason in `why`, when no window with OpenGL 3.3 could be created (the
// caller falls back to a headless render). Needs openWindowSystem() first.
std::optional<int> runViewApp(const ViewAppOptions& options, std::string& why);

} // namespace prism
