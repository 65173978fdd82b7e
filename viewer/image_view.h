// The left part of the window: where the image goes (1:1, or scaled down to
// fit), the mouse navigation on it, the light markers and the status line
// under it. ImGui draw lists only; the image itself is drawn by ImageDisplay.
#pragma once

#include "panels.h"
#include "view_controller.h"

namespace prism {

// Window pixels (origin top-left), for the image at its current size.
struct ImageLayout {
  float areaWidth = 0.0f; // the region left of the panel, above the status line
  float windowWidth = 0.0f;
  float areaHeight = 0.0f;
  float left = 0.0f; // the image's top-left corner
  float top = 0.0f;
  float zoom = 1.0f; // window pixels per image pixel: 1, or less to fit
  int imageWidth = 0;
  int imageHeight = 0;
};

// Height of the status line at the default font (scaled by uiScale); it runs
// under the picture and the panel, the whole width of the window.
inline constexpr float kStatusHeight = 24.0f;
float statusHeight(const WindowState& state);

ImageLayout layoutImage(float windowWidth, float windowHeight, const WindowState& state,
                        int imageWidth, int imageHeight);

// A mouse drag that began on the image (not on the panel): which button.
struct ImageDrag {
  int button = -1; // ImGuiMouseButton, or -1 when no drag is under way
};

// Orbit (left drag), pan (right or middle drag, or shift + left drag) and zoom
// (wheel) when the mouse works on the image rather than on the panel. A drag
// moves the camera by the motion since the button went down (never by the
// pointer's jump to where it was pressed) up to its release, and is one undo
// step.
void navigateWithMouse(ViewController& controller, const ImageLayout& layout, ImageDrag& drag);

// Numbered circles where the lights are, in the colour of their intensity.
void drawLightMarkers(const ViewController& controller, const ImageLayout& layout);

// The line under the image and the panel: phase, time left, exposure, how the
// picture is scaled, and any scene errors or notes.
void drawStatusLine(const ViewController& controller, const WindowState& state,
                    const ImageLayout& layout);

} // namespace prism
