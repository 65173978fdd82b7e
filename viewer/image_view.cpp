#include "image_view.h"

#include "camera_controls.h"
#include "input_latch.h"
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

float statusHeight(const WindowState& state) { return kStatusHeight * state.uiScale; }

ImageLayout layoutImage(float windowWidth, float windowHeight, const WindowState& state,
                        int imageWidth, int imageHeight) {
  ImageLayout l;
  l.windowWidth = windowWidth;
  l.areaWidth = std::max(1.0f, windowWidth - panelWidth(state));
  l.areaHeight = std::max(1.0f, windowHeight - statusHeight(state));
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
  const auto inArea = [&](glm::dvec2 p) {
    return p.x >= 0.0 && p.x < double(l.areaWidth) && p.y >= 0.0 && p.y < double(l.areaHeight);
  };
  const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
  const bool onImage = inArea(mouse) && !io.WantCaptureMouse; // not over or busy with the panel
  const CameraSpec& camera = c.scene().camera;
  glm::dvec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  if (drag.button < 0) {
    for (int button : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle}) {
      if (!onImage || !ImGui::IsMouseClicked(button)) continue;
      drag.button = button;
      c.beginGesture(); // the whole drag is one undo step
      // The motion since the press counts (under load a whole drag can fit in
      // one frame); the pointer's jump to where it was pressed does not.
      delta = mouse - pressedAt(button).value_or(mouse);
    }
    if (drag.button < 0) {
      if (onImage && io.MouseWheel != 0.0f)
        c.setCamera(zoom(camera, std::pow(kZoomPerWheelStep, double(io.MouseWheel))));
      return;
    }
  }
  // The motion up to the release counts too.
  const double dx = delta.x / double(l.zoom); // image pixels
  const double dy = delta.y / double(l.zoom);
  if (dx != 0.0 || dy != 0.0) {
    if (drag.button == ImGuiMouseButton_Left && !io.KeyShift) {
      // Dragging right turns the scene right: the eye goes the other way.
      c.setCamera(orbit(camera, -dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel));
    } else {
      c.setCamera(pan(camera, dx, dy, c.settings().height));
    }
  }
  if (!ImGui::IsMouseDown(drag.button)) {
    drag.button = -1;
    c.endGesture();
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

void drawStatusLine(const ViewController& c, const WindowState& state, const ImageLayout& l) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float y = l.areaHeight, h = statusHeight(state);
  const bool errors = !c.sceneErrors().empty();
  draw->AddRectFilled(ImVec2(0.0f, y), ImVec2(l.windowWidth, y + h),
                      errors ? IM_COL32(110, 30, 30, 255) : IM_COL32(30, 32, 38, 255));
  const SessionProgress& p = c.progress();
  if (p.phase != SessionPhase::Done) {
    const float barWidth = l.windowWidth * float(state.estimate.timeFraction());
    draw->AddRectFilled(ImVec2(0.0f, y + h - 3.0f), ImVec2(barWidth, y + h),
                        IM_COL32(90, 150, 255, 255));
  }
  std::string text = phaseText(p) + "   " + state.estimate.text();
  char exposure[96];
  std::snprintf(exposure, sizeof exposure, "   avgmax %.4g%s%s", state.exposure.avgmax(),
                state.exposure.locked() ? " (locked)" : "",
                state.exposure.ev() != 0.0 ? " with EV offset" : "");
  text += exposure;
  char zoom[32];
  std::snprintf(zoom, sizeof zoom, l.zoom == 1.0f ? "   1:1" : "   %.0f%% (fit)",
                100.0 * double(l.zoom));
  text += zoom;
  if (errors) text += "   scene errors: see the panel; showing the last good scene";
  if (!state.note.empty()) text += "   " + state.note;
  const ImVec2 at(8.0f * state.uiScale, y + 0.5f * (h - ImGui::GetFontSize()));
  draw->PushClipRect(ImVec2(0.0f, y), ImVec2(l.windowWidth, y + h));
  draw->AddText(at, IM_COL32(225, 228, 235, 255), text.c_str());
  draw->PopClipRect();
}

} // namespace prism
