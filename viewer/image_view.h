// The left part of the window: where the image goes (1:1, or scaled down to
// fit), the mouse navigation on it, the light markers and the status line
// under it. ImGui draw lists only; the image itself is drawn by ImageDisplay.
#pragma once

#include "view_controller.h"

namespace prism {

// Window pixels (origin top-left), for the image at its current size.
struct ImageLayout {
  float areaWidth = 0.0f; // the region left of the panel, above the status line
  float areaHeight = 0.0f;
  float left = 0.0f; // the image's top-left corner
  float top = 0.0f;
  float zoom = 1.0f; // window pixels per image pixel: 1, or less to fit
  int imageWidth = 0;
  int imageHeight = 0;
};

inline constexpr float kStatusHeight = 24.0f;

ImageLayout layoutImage(float windowWidth, float windowHeight, float panelWidth, int imageWidth,
                        int imageHeight);

// A mouse drag that began on the image (not on the panel): which button.
struct ImageDrag {
  int button = -1; // ImGuiMouseButton, or -1 when no drag is under way
};

// Orbit (left drag), pan (right or middle drag, or shift + left drag) and zoom
// (wheel) when the mouse works on the image rather than on the panel. A drag
// moves the camera from the frame after the button went down, so the jump of
// the pointer to where it was pressed never counts as motion.
void navigateWithMouse(ViewController& controller, const ImageLayout& layout, ImageDrag& drag);

// Numbered circles where the lights are, in the colour of their intensity.
void drawLightMarkers(const ViewController& controller, const ImageLayout& layout);

// The line under the image: phase, progress, exposure, and any scene errors.
void drawStatusLine(const ViewController& controller, const ImageLayout& layout);

} // namespace prism
