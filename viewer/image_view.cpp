#include "image_view.h"

#include "camera_controls.h"
#include "panels.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prism {

namespace {

constexpr double kOrbitDegreesPerPixel = 0.3;
constexpr double kZoomPerWheelStep = 0.9;

} // namespace

ImageLayout layoutImage(float windowWidth, float windowHeight, float panelWidth, int imageWidth,
                        int imageHeight) {
  ImageLayout l;
  l.areaWidth = std::max(1.0f, windowWidth - panelWidth);
  l.areaHeight = std::max(1.0f, windowHeight - kStatusHeight);
  l.imageWidth = imageWidth;
  l.imageHeight = imageHeight;
  if (imageWidth <= 0 || imageHeight <= 0) return l;
  l.zoom = std::min({1.0f, l.areaWidth / float(imageWidth), l.areaHeight / float(imageHeight)});
  // Whole pixels, so that at 1:1 every image pixel is exactly one window pixel.
  l.left = std::floor((l.areaWidth - float(imageWidth) * l.zoom) * 0.5f);
  l.top = std::floor((l.areaHeight - float(imageHeight) * l.zoom) * 0.5f);
  return l;
}

void navigateWithMouse(ViewController& c, const ImageLayout& l, ImageDrag& drag) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool inside = io.MousePos.x >= 0.0f && io.MousePos.x < l.areaWidth &&
                      io.MousePos.y >= 0.0f && io.MousePos.y < l.areaHeight;
  const bool onImage = inside && !io.WantCaptureMouse; // not over or busy with the panel
  const CameraSpec& camera = c.scene().camera;
  if (drag.button < 0) {
    for (int button : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle})
      if (onImage && ImGui::IsMouseClicked(button)) drag.button = button;
    if (onImage && io.MouseWheel != 0.0f)
      c.setCamera(zoom(camera, std::pow(kZoomPerWheelStep, double(io.MouseWheel))));
    return;
  }
  if (!ImGui::IsMouseDown(drag.button)) {
    drag.button = -1;
    return;
  }
  const double dx = double(io.MouseDelta.x) / double(l.zoom); // image pixels
  const double dy = double(io.MouseDelta.y) / double(l.zoom);
  if (dx == 0.0 && dy == 0.0) return;
  if (drag.button == ImGuiMouseButton_Left && !io.KeyShift) {
    // Dragging right turns the scene right: the eye goes the other way.
    c.setCamera(orbit(camera, -dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel));
  } else {
    c.setCamera(pan(camera, dx, dy, c.settings().height));
  }
}

void drawLightMarkers(const ViewController& c, const ImageLayout& l) {
  const Scene& scene = c.scene();
  const RenderSettings s = c.settings();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 min(l.left, l.top);
  const ImVec2 max(l.left + float(s.width) * l.zoom, l.top + float(s.height) * l.zoom);
  constexpr float kInset = 12.0f; // off-screen lights are pinned this far inside the border
  draw->PushClipRect(min, max, true);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const auto at = projectToScreen(scene.camera, s.width, s.height, light.position);
    if (!at) continue; // behind the eye: no meaningful place on screen
    ImVec2 p(l.left + float(at->x) * l.zoom, l.top + float(at->y) * l.zoom);
    const bool inside = p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y;
    p.x = std::clamp(p.x, min.x + kInset, std::max(min.x + kInset, max.x - kInset));
    p.y = std::clamp(p.y, min.y + kInset, std::max(min.y + kInset, max.y - kInset));
    const double peak = std::max(1e-9, maxComponent(light.intensity));
    const ImU32 fill =
        ImGui::GetColorU32(ImVec4(float(light.intensity.r / peak), float(light.intensity.g / peak),
                                  float(light.intensity.b / peak), 1.0f));
    draw->AddCircleFilled(p, 7.0f, IM_COL32(0, 0, 0, 200));
    if (inside) {
      draw->AddCircleFilled(p, 5.0f, fill);
      draw->AddCircle(p, 9.0f, IM_COL32(255, 255, 255, 230), 0, 1.5f);
    } else {
      draw->AddCircle(p, 5.0f, fill, 0, 2.0f); // hollow: the light is out of the picture
    }
    char label[24];
    std::snprintf(label, sizeof label, "%zu", i + 1);
    const ImVec2 text(p.x + (p.x > max.x - 30.0f ? -20.0f : 10.0f),
                      p.y + (p.y < min.y + 24.0f ? 2.0f : -18.0f));
    draw->AddText(ImVec2(text.x + 1.0f, text.y + 1.0f), IM_COL32(0, 0, 0, 220), label);
    draw->AddText(text, IM_COL32(255, 255, 255, 255), label);
  }
  draw->PopClipRect();
}

void drawStatusLine(const ViewController& c, const ImageLayout& l) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float y = l.areaHeight;
  const bool errors = !c.sceneErrors().empty();
  draw->AddRectFilled(ImVec2(0.0f, y), ImVec2(l.areaWidth, y + kStatusHeight),
                      errors ? IM_COL32(110, 30, 30, 255) : IM_COL32(30, 32, 38, 255));
  const SessionProgress& p = c.progress();
  const float barWidth = l.areaWidth * float(p.fraction);
  if (p.phase != SessionPhase::Done)
    draw->AddRectFilled(ImVec2(0.0f, y + kStatusHeight - 3.0f), ImVec2(barWidth, y + kStatusHeight),
                        IM_COL32(90, 150, 255, 255));
  char text[256];
  std::snprintf(text, sizeof text, "%s    avgmax %.4g  scale %.4g    %s", phaseText(p).c_str(),
                p.avgmax, double(c.exposure()),
                errors ? "scene errors: see the panel; showing the last good scene"
                       : (l.zoom < 1.0f ? "scaled to fit" : "1:1"));
  draw->AddText(ImVec2(8.0f, y + 5.0f), IM_COL32(225, 228, 235, 255), text);
}

} // namespace prism
