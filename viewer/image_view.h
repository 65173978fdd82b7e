// The left part of the window: where the image goes (1:1, or scaled down to
// fit), the mouse navigation on it, the light markers and the status line
// under it. ImGui draw lists only; the image itself is drawn by ImageDisplay.
#pragma once

#include "panels.h"
#include "view_controller.h"

#include <imgui.h>

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace prism {

// Window pixels (origin top-left), for the image at its current size.
struct ImageLayout {
  float areaWidth = 0.0f; // the region left of the panel, above the status line
  float windowWidth = 0.0f;
  float areaHeight = 0.0f;
  float left = 0.0f; // the image's top-left corner
  float top = 0.0f;
  float zoom = 1.0f; // window pixels per image pixel
  bool fit = true;   // 1:1 or scaled down to fit, as opposed to zoomed by the user
  int imageWidth = 0;
  int imageHeight = 0;
};

// Height of the status line at the default font (scaled by uiScale); it runs
// under the picture and the panel, the whole width of the window.
inline constexpr float kStatusHeight = 24.0f;
float statusHeight(const WindowState& state);

ImageLayout layoutImage(float windowWidth, float windowHeight, const WindowState& state,
                        int imageWidth, int imageHeight);

// The zoom at which the picture fits its area (1 when it fits at 1:1).
float fitZoom(const ImageLayout& layout);

// The picture's zoom limits, window pixels per image pixel.
inline constexpr float kMinZoom = 1.0f / 16.0f;
inline constexpr float kMaxZoom = 64.0f;

// Zooms the picture by `factor` keeping the image point under `about` (window
// pixels) where it is; the camera does not move.
void zoomPicture(WindowState& state, const ImageLayout& layout, float factor, ImVec2 about);

// The image pixel under a window point, if any.
std::optional<glm::ivec2> pixelAt(const ImageLayout& layout, ImVec2 point);

// "pixel (12, 34): radiance 0.1 0.2 0.3 -> 16 32 48": what the picture holds
// there and the 8-bit value the window shows for it.
std::string pixelText(const ViewController& controller, const WindowState& state, glm::ivec2 pixel);

// Shows pixel `pixel`'s ray tree in the panel.
void inspect(const ViewController& controller, WindowState& state, glm::ivec2 pixel);

// A mouse press that began on the image (not on the panel).
struct ImageDrag {
  int button = -1;         // ImGuiMouseButton, or -1 when none is under way
  bool picture = false;    // Ctrl was held: it moves the picture, not the camera
  bool moved = false;      // past the threshold: a drag, not a click
  glm::dvec2 pending{0.0}; // motion not applied yet (below the threshold)
  ImVec2 start;            // where it was pressed
};

// The mouse on the picture (not on the panel): orbit (left drag), pan (right
// or middle drag, or shift + left drag) and zoom (wheel) the camera; move
// (Ctrl + drag) and zoom (Ctrl + wheel) the picture; inspect a pixel (click).
// A drag moves by the motion since the button went down (never by the
// pointer's jump to where it was pressed) up to its release, and a camera
// drag is one undo step. Also notes the pixel under the mouse.
void navigateWithMouse(ViewController& controller, const ImageLayout& layout, WindowState& state,
                       ImageDrag& drag);

// Numbered circles where the lights are, in the colour of their intensity.
void drawLightMarkers(const ViewController& controller, const ImageLayout& layout);

// The line under the image and the panel: phase, time left, exposure, how the
// picture is scaled, and any scene errors or notes.
void drawStatusLine(const ViewController& controller, const WindowState& state,
                    const ImageLayout& layout);

} // namespace prism
