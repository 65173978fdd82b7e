// The previewer's control panel (Dear ImGui) and keyboard shortcuts. Widgets
// edit copies of the session's values and forward every change to the
// ViewController, which restarts the render; display-only options (overlay,
// markers) live in PanelState and never restart anything.
#pragma once

#include "frame_stats.h"
#include "view_controller.h"

#include <string>

namespace prism {

struct PanelState {
  std::string savePath; // the Save field
  bool overlay = false; // tint supersampled pixels
  bool markers = true;  // draw the lights over the image
  bool quit = false;    // Ctrl+Q
};

// Width of the panel in pixels at the default font.
inline constexpr float kPanelWidth = 360.0f;

// Draws the panel docked at the right edge of a `width` x `height` window.
void drawControlPanel(ViewController& controller, PanelState& state, const FrameStats& frames,
                      float width, float height);

// R / F5 reload, O overlay, L markers, Home reset camera, Ctrl+S save, Ctrl+Q
// quit; ignored while a text field has the keyboard.
void handleShortcuts(ViewController& controller, PanelState& state);

// One-line description of where the render is, e.g. "pass 1, 4x4 level, 37%".
std::string phaseText(const SessionProgress& progress);

} // namespace prism
