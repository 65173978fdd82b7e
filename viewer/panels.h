// The previewer's control panel (Dear ImGui) and keyboard shortcuts. Widgets
// edit copies of the session's values and forward every change to the
// ViewController, which restarts the render; what only changes the display
// (overlay, markers, exposure lock, the panel itself) lives in WindowState and
// never restarts anything. Every widget goes through viewer/widgets.h, so
// `--dump-widgets` lists it.
#pragma once

#include "frame_stats.h"
#include "live_exposure.h"
#include "progress_estimate.h"
#include "view_controller.h"

#include <string>

namespace prism {

// What the window keeps besides the controller: display options and
// estimates, from frame to frame.
struct WindowState {
  std::string savePath;      // the Save field
  std::string scenePath;     // the Save scene field
  bool overlay = false;      // tint supersampled pixels (O)
  bool markers = true;       // draw the lights over the image (L)
  bool panelVisible = true;  // Tab hides the panel, leaving the picture
  bool showHelp = false;     // F1: the keys, over everything
  bool quit = false;         // Ctrl+Q
  float uiScale = 1.0f;      // the monitor's content scale (HiDPI)
  std::string note;          // a message for the status line, until the next one
  bool panelGesture = false; // a panel widget is held: its edits are one undo step
  LiveExposure exposure;     // steady automatic exposure, or locked, with EV
  ProgressEstimate estimate; // time left
};

// Width of the panel in pixels at the default font (scaled by uiScale).
inline constexpr float kPanelWidth = 360.0f;
float panelWidth(const WindowState& state);

// Draws the panel docked at the right edge of a `width` x `height` window
// (nothing when the panel is hidden).
void drawControlPanel(ViewController& controller, WindowState& state, const FrameStats& frames,
                      float width, float height);

// The key overlay (F1): every key and mouse action of the window.
void drawHelp(WindowState& state, float width, float height);

// R / F5 reload, O overlay, L markers, E exposure lock, Home reset camera, Tab
// panel, F1 help, Ctrl+Z undo, Ctrl+Shift+Z / Ctrl+Y redo, Ctrl+S save, Ctrl+Q
// quit; ignored while a text field has the keyboard.
void handleShortcuts(ViewController& controller, WindowState& state);

// Saves the picture, saying in the status line when the scene files have
// errors and what is saved is the last good scene.
void savePicture(ViewController& controller, WindowState& state);

// One-line description of where the render is, e.g. "pass 1, 4x4 level".
std::string phaseText(const SessionProgress& progress);

} // namespace prism
