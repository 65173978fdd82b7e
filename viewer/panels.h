// The previewer's control panel (Dear ImGui) and keyboard shortcuts. Widgets
// edit copies of the session's values and forward every change to the
// ViewController, which restarts the render; what only changes the display
// (overlay, markers, exposure lock, the panel itself) lives in WindowState and
// never restarts anything. Every widget goes through viewer/widgets.h, so
// `--dump-widgets` lists it.
#pragma once

#include "frame_stats.h"
#include "live_exposure.h"
#include "open_dialog.h"
#include "progress_estimate.h"
#include "view_controller.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace prism {

// How the picture sits in its area: 1:1, or scaled down to fit (the
// default), or zoomed by the user (nearest-neighbour pixels past 1:1), the
// camera untouched either way.
struct PictureView {
  bool fit = true;
  float zoom = 1.0f;            // window pixels per image pixel, when not fitting
  glm::vec2 centre{0.5f, 0.5f}; // the image point (fractions of its size) at the area's centre
};

// A render pinned for comparison with the live one (A/B).
struct PinnedRender {
  bool valid = false;
  std::uint64_t generation = 0; // bumped by every pin
  SessionImage image;
  float scale = 0.0f; // its exposure when pinned
  RenderSettings settings;
  SessionProgress progress; // its statistics when pinned
};
enum class CompareMode { Off, Flip, Split };

// What the window keeps besides the controller: display options and
// estimates, from frame to frame.
struct WindowState {
  std::string savePath;                // the Save field
  std::string scenePath;               // the Save scene field
  bool overlay = false;                // tint supersampled pixels (O)
  bool markers = true;                 // draw the lights over the image (L)
  bool panelVisible = true;            // Tab hides the panel, leaving the picture
  bool showHelp = false;               // F1: the keys, over everything
  bool quit = false;                   // Ctrl+Q
  float uiScale = 1.0f;                // the monitor's content scale (HiDPI)
  std::string note;                    // a message for the status line, until the next one
  bool panelGesture = false;           // a panel widget is held: its edits are one undo step
  LiveExposure exposure;               // steady automatic exposure, or locked, with EV
  ProgressEstimate estimate;           // time left
  PictureView picture;                 // zoom and pan of the picture
  std::optional<glm::ivec2> hovered;   // the pixel under the mouse
  std::optional<glm::ivec2> inspected; // the pixel clicked: its ray tree is shown
  std::string rayTree;                 // of `inspected`, for the scene as it is now
  std::uint64_t rayTreeRestarts = 0;   // the render it was traced for
  bool saveWindowExposure = false;     // Save uses the window's exposure, not the automatic one
  PinnedRender pinned;
  CompareMode compare = CompareMode::Off;
  bool showPinned = false; // flip: the pinned render is on screen
  float split = 0.5f;      // split: where the pinned render begins, a fraction of the width
  OpenDialog open;         // Ctrl+O
  RecentFiles recent{RecentFiles::defaultStore()};
};

// Width of the panel in pixels at the default font (scaled by uiScale).
inline constexpr float kPanelWidth = 360.0f;
float panelWidth(const WindowState& state);

// Draws the panel docked at the right edge of a `width` x `height` window
// (nothing when the panel is hidden). `shownZoom` is the picture's zoom now.
void drawControlPanel(ViewController& controller, WindowState& state, const FrameStats& frames,
                      float width, float height, float shownZoom);

// The key overlay (F1): every key and mouse action of the window.
void drawHelp(WindowState& state, float width, float height);

// R / F5 reload, O overlay, L markers, E exposure lock, Home reset camera, Tab
// panel, F1 help, Ctrl+Z undo, Ctrl+Shift+Z / Ctrl+Y redo, Ctrl+S save, Ctrl+Q
// quit; ignored while a text field has the keyboard.
void handleShortcuts(ViewController& controller, WindowState& state);

// Keeps the render as it is now for comparison (P).
void pinRender(const ViewController& controller, WindowState& state);

// The picture at 1:1 where it is (1).
void setPictureActualSize(WindowState& state);

// Saves the picture, saying in the status line when the scene files have
// errors and what is saved is the last good scene.
void savePicture(ViewController& controller, WindowState& state);

// One-line description of where the render is, e.g. "pass 1, 4x4 level".
std::string phaseText(const SessionProgress& progress);

} // namespace prism
