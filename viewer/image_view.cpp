#include "image_view.h"

#include "camera_controls.h"
#include "input_latch.h"
#include "panels.h"

#include "core/render/exposure.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prism {

namespace {

constexpr double kOrbitDegreesPerPixel = 0.3;
constexpr double kZoomPerWheelStep = 0.9;
constexpr float kPictureZoomPerStep = 1.25f;
constexpr double kDragThreshold = 3.0; // pixels the pointer moves before a press is a drag

} // namespace

float statusHeight(const WindowState& state) { return kStatusHeight * state.uiScale; }

std::string pixelText(const ViewController& c, const WindowState& state, glm::ivec2 pixel) {
  const SessionImage& image = c.image();
  if (pixel.x >= image.width || pixel.y >= image.height) return "";
  const Rgb& r =
      image.radiance[std::size_t(pixel.y) * std::size_t(image.width) + std::size_t(pixel.x)];
  const float scale = state.exposure.scale();
  char text[160];
  std::snprintf(text, sizeof text, "pixel (%d, %d): radiance %.4g %.4g %.4g -> %d %d %d", pixel.x,
                pixel.y, double(r.r), double(r.g), double(r.b), int(exposeChannel(r.r, scale)),
                int(exposeChannel(r.g, scale)), int(exposeChannel(r.b, scale)));
  return text;
}

ImageLayout layoutImage(float windowWidth, float windowHeight, const WindowState& state,
                        int imageWidth, int imageHeight) {
  ImageLayout l;
  l.windowWidth = windowWidth;
  l.areaWidth = std::max(1.0f, windowWidth - panelWidth(state));
  l.areaHeight = std::max(1.0f, windowHeight - statusHeight(state));
  l.imageWidth = imageWidth;
  l.imageHeight = imageHeight;
  if (imageWidth <= 0 || imageHeight <= 0) return l;
  l.fit = state.picture.fit;
  l.zoom = l.fit ? fitZoom(l) : state.picture.zoom;
  const glm::vec2 centre = l.fit ? glm::vec2(0.5f) : state.picture.centre;
  // Whole pixels, so that at 1:1 every image pixel is exactly one window pixel.
  l.left = std::floor(0.5f * l.areaWidth - centre.x * float(imageWidth) * l.zoom);
  l.top = std::floor(0.5f * l.areaHeight - centre.y * float(imageHeight) * l.zoom);
  return l;
}

float fitZoom(const ImageLayout& l) {
  if (l.imageWidth <= 0 || l.imageHeight <= 0) return 1.0f;
  return std::min({1.0f, l.areaWidth / float(l.imageWidth), l.areaHeight / float(l.imageHeight)});
}

std::optional<glm::ivec2> pixelAt(const ImageLayout& l, ImVec2 point) {
  const float x = (point.x - l.left) / l.zoom, y = (point.y - l.top) / l.zoom;
  if (!(point.x >= 0.0f && point.x < l.areaWidth && point.y >= 0.0f && point.y < l.areaHeight))
    return std::nullopt;
  if (!(x >= 0.0f && y >= 0.0f && x < float(l.imageWidth) && y < float(l.imageHeight)))
    return std::nullopt;
  return glm::ivec2(int(x), int(y));
}

void zoomPicture(WindowState& state, const ImageLayout& l, float factor, ImVec2 about) {
  if (l.imageWidth <= 0 || l.imageHeight <= 0) return;
  const float zoom = std::clamp(l.zoom * factor, std::min(kMinZoom, fitZoom(l)), kMaxZoom);
  // The image point under `about` stays under it.
  const glm::vec2 point((about.x - l.left) / l.zoom, (about.y - l.top) / l.zoom);
  const glm::vec2 left(about.x - point.x * zoom, about.y - point.y * zoom);
  state.picture.fit = false;
  state.picture.zoom = zoom;
  state.picture.centre = glm::vec2((0.5f * l.areaWidth - left.x) / (float(l.imageWidth) * zoom),
                                   (0.5f * l.areaHeight - left.y) / (float(l.imageHeight) * zoom));
}

void navigateWithMouse(ViewController& c, const ImageLayout& l, WindowState& state,
                       ImageDrag& drag) {
  const ImGuiIO& io = ImGui::GetIO();
  const auto inArea = [&](glm::dvec2 p) {
    return p.x >= 0.0 && p.x < double(l.areaWidth) && p.y >= 0.0 && p.y < double(l.areaHeight);
  };
  const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
  const bool onImage = inArea(mouse) && !io.WantCaptureMouse; // not over or busy with the panel
  state.hovered = onImage ? pixelAt(l, io.MousePos) : std::nullopt;
  const CameraSpec& camera = c.scene().camera;
  glm::dvec2 delta(io.MouseDelta.x, io.MouseDelta.y);
  if (drag.button < 0) {
    for (int button : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle}) {
      if (!onImage || !ImGui::IsMouseClicked(button)) continue;
      drag.button = button;
      drag.picture = io.KeyCtrl; // Ctrl + drag moves the picture, not the camera
      drag.pending = glm::dvec2(0.0);
      drag.moved = false;
      drag.start = io.MousePos;
      if (!drag.picture) c.beginGesture(); // the whole drag is one undo step
      // The motion since the press counts (under load a whole drag can fit in
      // one frame); the pointer's jump to where it was pressed does not.
      delta = mouse - pressedAt(button).value_or(mouse);
    }
    if (drag.button < 0) {
      if (onImage && io.MouseWheel != 0.0f) {
        if (io.KeyCtrl) { // the picture: zoom about the pointer
          zoomPicture(state, l, std::pow(kPictureZoomPerStep, io.MouseWheel), io.MousePos);
        } else { // the camera: toward or away from lookat
          c.apply(CameraEdit{zoom(camera, std::pow(kZoomPerWheelStep, double(io.MouseWheel)))});
        }
      }
      return;
    }
  }
  // A drag begins once the pointer has moved a few pixels from the press; a
  // press and release without that is a click, which inspects the pixel.
  drag.pending += delta;
  if (!drag.moved && glm::length(drag.pending) >= kDragThreshold) drag.moved = true;
  if (drag.moved && drag.pending != glm::dvec2(0.0)) {
    const double dx = drag.pending.x / double(l.zoom); // image pixels
    const double dy = drag.pending.y / double(l.zoom);
    if (drag.picture) {
      state.picture.fit = false;
      state.picture.zoom = l.zoom;
      state.picture.centre =
          (l.fit ? glm::vec2(0.5f) : state.picture.centre) -
          glm::vec2(float(dx) / float(l.imageWidth), float(dy) / float(l.imageHeight));
    } else if (drag.button == ImGuiMouseButton_Left && !io.KeyShift) {
      // Dragging right turns the scene right: the eye goes the other way.
      c.apply(CameraEdit{orbit(camera, -dx * kOrbitDegreesPerPixel, dy * kOrbitDegreesPerPixel)});
    } else {
      c.apply(CameraEdit{pan(camera, dx, dy, c.settings().height)});
    }
    drag.pending = glm::dvec2(0.0);
  }
  if (!ImGui::IsMouseDown(drag.button)) {
    if (!drag.moved && drag.button == ImGuiMouseButton_Left) {
      if (const std::optional<glm::ivec2> pixel = pixelAt(l, drag.start)) inspect(c, state, *pixel);
    }
    if (!drag.picture) c.endGesture();
    drag.button = -1;
  }
}

void inspect(const ViewController& c, WindowState& state, glm::ivec2 pixel) {
  state.inspected = pixel;
  state.rayTree = c.pixelRayTree(pixel.x, pixel.y);
  state.rayTreeRestarts = c.progress().restarts;
}

void drawLightMarkers(const ViewController& c, const ImageLayout& l) {
  const Scene& scene = c.scene();
  const RenderSettings s = c.settings();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  // The part of the picture in view (zoomed in, it may overflow its area).
  const ImVec2 min(std::max(l.left, 0.0f), std::max(l.top, 0.0f));
  const ImVec2 max(std::min(l.left + float(s.width) * l.zoom, l.areaWidth),
                   std::min(l.top + float(s.height) * l.zoom, l.areaHeight));
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
  std::snprintf(zoom, sizeof zoom, l.zoom == 1.0f ? "   1:1" : "   %.0f%%%s",
                100.0 * double(l.zoom), l.fit ? " (fit)" : "");
  text += zoom;
  if (state.hovered) text += "   " + pixelText(c, state, *state.hovered);
  if (errors) text += "   scene errors: see the panel; showing the last good scene";
  if (!state.note.empty()) text += "   " + state.note;
  const ImVec2 at(8.0f * state.uiScale, y + 0.5f * (h - ImGui::GetFontSize()));
  draw->PushClipRect(ImVec2(0.0f, y), ImVec2(l.windowWidth, y + h));
  draw->AddText(at, IM_COL32(225, 228, 235, 255), text.c_str());
  draw->PopClipRect();
}

} // namespace prism
