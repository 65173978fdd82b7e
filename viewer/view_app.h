// The previewer's window: GLFW, the image drawn by ImageDisplay, the ImGui
// panel, mouse navigation and light markers, and the frame loop that keeps
// all of it responsive while the render threads work.
#pragma once

#include "view_controller.h"
#include "view_script.h"

#include <optional>
#include <string>
#include <vector>

namespace prism {

// Starts GLFW. Returns false, with the reason in `why`, when there is no
// display to open a window on.
bool openWindowSystem(std::string& why);
void closeWindowSystem();

struct ViewAppOptions {
  ViewOptions view;
  std::optional<std::vector<ScriptAction>> script; // a scripted session
  std::vector<std::string> warnings;               // loading the scene reported these
  std::string dumpWidgets; // write the widgets of every frame to this file (for tests)
};

// Runs the previewer on `scene` until the window closes or the script quits,
// and returns the exit code. Returns nothing, with the reason in `why`, when
// no window with OpenGL 3.3 could be created (the caller falls back to a
// headless render). Needs openWindowSystem() first.
std::optional<int> runViewApp(Scene scene, const ViewAppOptions& options, std::string& why);

} // namespace prism
