#include "panels.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace prism {

namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kDimColour{0.62f, 0.64f, 0.68f, 1.0f};

// Drag speed for a value of about `magnitude`: ~200 pixels of mouse to double it.
float dragSpeed(double magnitude) { return float(std::max(1e-3, magnitude * 0.005)); }

void sceneSection(ViewController& c) {
  const std::string name = std::filesystem::path(c.scenePath()).filename().string();
  ImGui::Text("%s", name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.scenePath().c_str());
  const Scene& s = c.scene();
  ImGui::SameLine();
  ImGui::TextColored(kDimColour, "%zu primitives, %zu lights", s.primitiveCount(), s.lights.size());
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 90.0f);
  if (ImGui::Button("Reload (R)", ImVec2(90.0f, 0.0f))) c.reload();
  if (c.reloading()) ImGui::TextColored(kDimColour, "Reading the scene files...");
  if (!c.sceneWarnings().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDimColour);
    for (const std::string& w : c.sceneWarnings())
      ImGui::TextWrapped("%s", w.c_str());
    ImGui::PopStyleColor();
  }
  if (const std::string failure = c.renderFailure(); !failure.empty())
    ImGui::TextColored(kErrorColour, "The render failed: %s", failure.c_str());
  if (!c.sceneErrors().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("The scene has errors; showing the last good one:");
    for (const std::string& e : c.sceneErrors())
      ImGui::TextWrapped("%s", e.c_str());
    ImGui::PopStyleColor();
  }
}

void renderSection(ViewController& c) {
  RenderSettings s = c.settings();
  bool changed = false;
  changed |= ImGui::SliderInt("max depth", &s.maxDepth, 1, std::max(16, s.maxDepth), "%d",
                              ImGuiSliderFlags_AlwaysClamp);
  float thresh = float(s.thresh);
  if (ImGui::SliderFloat("threshold", &thresh, 0.0f, 1.0f, "%.3f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    s.thresh = double(thresh);
    changed = true;
  }
  changed |= ImGui::Checkbox("jitter sub-samples", &s.jitter);
  ImGui::SameLine();
  ImGui::TextColored(kDimColour, "   image %d x %d", s.width, s.height);
  if (changed) c.setSettings(s);
}

void lightsSection(ViewController& c) {
  const Scene& scene = c.scene();
  Color ambient = scene.ambient;
  if (ImGui::DragScalarN("ambient", ImGuiDataType_Double, &ambient[0], 3,
                         dragSpeed(std::max(0.05, maxComponent(ambient))), nullptr, nullptr,
                         "%.3f")) {
    c.setAmbient(glm::max(ambient, Color(0.0)));
  }
  const double extent = glm::length(scene.camera.eye - scene.camera.lookat);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Light light = scene.lights[i];
    ImGui::PushID(int(i));
    char label[32];
    std::snprintf(label, sizeof label, "light %zu", i + 1);
    bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, &light.position[0], 3,
                                      dragSpeed(extent), nullptr, nullptr, "%.2f");
    const double peak = std::max(1e-9, maxComponent(light.intensity));
    if (ImGui::DragScalarN("##intensity", ImGuiDataType_Double, &light.intensity[0], 3,
                           dragSpeed(peak), nullptr, nullptr, "%.2f")) {
      light.intensity = glm::max(light.intensity, Color(0.0)); // SPEC 4: never negative
      changed = true;
    }
    // The intensity's hue, at full brightness, in place of a label.
    ImGui::SameLine();
    const ImVec4 swatch(float(light.intensity.r / peak), float(light.intensity.g / peak),
                        float(light.intensity.b / peak), 1.0f);
    ImGui::ColorButton("##colour", swatch, ImGuiColorEditFlags_NoTooltip, ImVec2(12.0f, 12.0f));
    ImGui::SameLine(0.0f, 4.0f);
    ImGui::TextUnformatted("intensity");
    if (changed) c.setLight(i, light);
    ImGui::PopID();
  }
}

void cameraSection(ViewController& c) {
  const CameraSpec& cam = c.scene().camera;
  ImGui::TextColored(kDimColour, "eye %.2f %.2f %.2f   lookat %.2f %.2f %.2f", cam.eye.x, cam.eye.y,
                     cam.eye.z, cam.lookat.x, cam.lookat.y, cam.lookat.z);
  if (ImGui::Button("Reset (Home)")) c.resetCamera();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the scene file's camera");
  ImGui::SameLine();
  ImGui::TextColored(kDimColour, "drag: orbit, right-drag: pan, wheel: zoom");
}

void displaySection(ViewController& c, PanelState& state) {
  ImGui::Checkbox("supersampled pixels (O)", &state.overlay);
  ImGui::SameLine();
  ImGui::Checkbox("lights (L)", &state.markers);
  const SessionProgress& p = c.progress();
  ImGui::Text("avgmax %.5g   scale %.5g (128 / avgmax)", p.avgmax, double(c.exposure()));
  if (p.phase == SessionPhase::Coarse)
    ImGui::TextColored(kDimColour, "live: from the %lld pixel centres so far", p.pass1Pixels);
}

void statisticsSection(ViewController& c, const FrameStats& frames) {
  const SessionProgress& p = c.progress();
  const RenderSettings s = c.settings();
  ImGui::ProgressBar(float(p.fraction), ImVec2(-1.0f, 0.0f), phaseText(p).c_str());
  const double pixels = std::max(1.0, double(s.width) * double(s.height));
  const RayCounts& r = p.counts;
  const double seconds = std::max(p.elapsedSeconds, 1e-9);
  ImGui::Text("elapsed %.2f s   %.2f M rays/s", p.elapsedSeconds,
              double(r.total()) / seconds * 1e-6);
  if (ImGui::BeginTable("rays", 4, ImGuiTableFlags_SizingStretchProp)) {
    // Rays per pixel by kind, two kinds a row.
    auto cell = [&](const char* kind, double count) {
      ImGui::TableNextColumn();
      ImGui::TextColored(kDimColour, "%s", kind);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", count / pixels);
    };
    cell("eye, pass 1", double(r.eyePrimary));
    cell("eye, antialiasing", double(r.eyeAntialias));
    cell("shadow", double(r.shadow));
    cell("reflected", double(r.reflected));
    cell("transmitted", double(r.transmitted));
    cell("all rays / pixel", double(r.total()));
    ImGui::EndTable();
  }
  ImGui::Text("supersampled %lld pixels (%.1f%%)", p.supersampledPixels,
              100.0 * double(p.supersampledPixels) / pixels);
  ImGui::TextColored(kDimColour, "restarts %llu   window %.0f fps", (unsigned long long)p.restarts,
                     frames.recentFps());
}

void saveSection(ViewController& c, PanelState& state) {
  ImGui::SetNextItemWidth(-70.0f);
  ImGui::InputText("##path", &state.savePath);
  ImGui::SameLine();
  const bool busy = c.saveJob().busy();
  ImGui::BeginDisabled(busy || state.savePath.empty());
  if (ImGui::Button("Save", ImVec2(-1.0f, 0.0f))) c.save(state.savePath);
  ImGui::EndDisabled();
  const SaveJob& job = c.saveJob();
  if (job.state() == SaveJob::State::WaitingForRender) {
    ImGui::ProgressBar(float(c.progress().fraction), ImVec2(-1.0f, 0.0f),
                       "finishing the render...");
  } else if (job.state() == SaveJob::State::Failed) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("%s", job.message().c_str());
    ImGui::PopStyleColor();
  } else if (job.state() != SaveJob::State::Idle) {
    ImGui::TextWrapped("%s", job.message().c_str());
  }
}

} // namespace

std::string phaseText(const SessionProgress& p) {
  char text[96];
  switch (p.phase) {
  case SessionPhase::Coarse:
    std::snprintf(text, sizeof text, "pass 1, %dx%d level   %.0f%%", p.level, p.level,
                  100.0 * p.fraction);
    break;
  case SessionPhase::Antialias:
    std::snprintf(text, sizeof text, "pass 2, antialiasing   %.0f%%", 100.0 * p.fraction);
    break;
  case SessionPhase::Done:
    std::snprintf(text, sizeof text, "done in %.2f s", p.elapsedSeconds);
    break;
  }
  return text;
}

void drawControlPanel(ViewController& c, PanelState& state, const FrameStats& frames, float width,
                      float height) {
  ImGui::SetNextWindowPos(ImVec2(width - kPanelWidth, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar;
  ImGui::Begin("Prism", nullptr, flags);
  ImGui::PushItemWidth(-110.0f); // room for the labels
  auto section = [](const char* title) {
    return ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen);
  };
  sceneSection(c);
  if (section("Render")) renderSection(c);
  if (section("Lights")) lightsSection(c);
  if (section("Camera")) cameraSection(c);
  if (section("Display")) displaySection(c, state);
  if (section("Save")) saveSection(c, state);
  if (section("Statistics")) statisticsSection(c, frames);
  ImGui::PopItemWidth();
  ImGui::End();
}

void handleShortcuts(ViewController& c, PanelState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  // In ImGui 1.86 the GLFW backend indexes io.KeysDown by GLFW key code.
  if (io.KeyCtrl) {
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false) && !state.savePath.empty()) c.save(state.savePath);
    if (ImGui::IsKeyPressed(GLFW_KEY_Q, false)) state.quit = true;
    return;
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false) || ImGui::IsKeyPressed(GLFW_KEY_F5, false)) c.reload();
  if (ImGui::IsKeyPressed(GLFW_KEY_O, false)) state.overlay = !state.overlay;
  if (ImGui::IsKeyPressed(GLFW_KEY_L, false)) state.markers = !state.markers;
  if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) c.resetCamera();
}

} // namespace prism
