#include "panels.h"

#include "image_view.h"
#include "number_text.h"
#include "widgets.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

namespace prism {

namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kDimColour{0.62f, 0.64f, 0.68f, 1.0f};

// Drag speed for a value of about `magnitude`: ~200 pixels of mouse to double it.
float dragSpeed(double magnitude) { return float(std::max(1e-3, magnitude * 0.005)); }

void dimText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void errorText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// Applies an edit a widget made. While a widget is held (a slider or a
// number being dragged), its edits make one undo step, which ends when it is
// let go (see drawControlPanel).
template <class Apply> void edit(ViewController& c, WindowState& state, Apply&& apply) {
  if (ImGui::IsAnyItemActive() && !state.panelGesture) {
    c.beginGesture();
    state.panelGesture = true;
  }
  apply();
}

// What the last reload did with the user's edits, until the next edit.
void keptEditsText(const ViewController& c) {
  const auto list = [](const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items)
      text += (text.empty() ? "" : ", ") + item;
    return text;
  };
  const ViewController::ReloadEdits& kept = c.keptEdits();
  if (!kept.kept.empty()) dimText("Kept your edits over the reloaded file: " + list(kept.kept));
  if (!kept.dropped.empty())
    dimText("Dropped your edits of what the file no longer has: " + list(kept.dropped));
}

void sceneSection(ViewController& c, WindowState& state) {
  const std::string name = std::filesystem::path(c.scenePath()).filename().string();
  ImGui::TextWrapped("%s", name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.scenePath().c_str());
  const Scene& s = c.scene();
  dimText(withSeparators((long long)s.primitiveCount()) + " primitives, " +
          withSeparators((long long)s.lights.size()) + " lights");
  const ui::Scope scope("Scene");
  if (ui::button("Open... (Ctrl+O)")) state.open.visible = true;
  ImGui::SameLine();
  if (ui::button("Reload (R)")) c.reload();
  ImGui::BeginDisabled(!c.canUndo());
  if (ui::button("Undo (Ctrl+Z)")) c.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!c.canRedo());
  if (ui::button("Redo")) c.redo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Ctrl+Shift+Z or Ctrl+Y");
  if (ui::button("Back to the file's values")) c.apply(RevertToFile{});
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "the camera, the lights, ambient, fog and textures as the scene file says (undoable)");
  if (c.reloading()) dimText("Reading the scene files...");
  keptEditsText(c);
  for (const std::string& w : c.sceneWarnings())
    dimText(w);
  if (const std::string failure = c.renderFailure(); !failure.empty())
    errorText("The render failed: " + failure);
  if (!c.sceneErrors().empty()) {
    errorText("The scene has errors; showing the last good one:");
    for (const std::string& e : c.sceneErrors())
      errorText(e);
  }
}

void renderSection(ViewController& c, WindowState& state) {
  RenderSettings s = c.settings();
  bool changed = false;
  changed |= ui::sliderInt("max depth", &s.maxDepth, 1, std::max(16, s.maxDepth));
  float thresh = float(s.thresh);
  if (ui::sliderFloat("threshold", &thresh, 0.0f, 1.0f, "%.3f",
                      ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    s.thresh = double(thresh);
    changed = true;
  }
  changed |= ui::checkbox("jitter sub-samples", &s.jitter);
  changed |= ui::checkbox("no antialiasing", &s.noAa);
  dimText("image " + std::to_string(s.width) + " x " + std::to_string(s.height));
  if (changed) edit(c, state, [&] { c.apply(SettingsEdit{s}); });
}

// A colour (ambient, the fog's) dragged at a pace that suits its size. Never
// negative, as the scene language requires (docs/scene-language.md).
bool dragColour(const char* label, Color& colour) {
  const float speed = dragSpeed(std::max(0.05, maxComponent(colour)));
  if (!ui::dragDoubles(label, &colour[0], 3, speed, "%.3f")) return false;
  colour = glm::max(colour, Color(0.0));
  return true;
}

void lightsSection(ViewController& c, WindowState& state) {
  const Scene& scene = c.scene();
  if (Color ambient = scene.ambient; dragColour("ambient", ambient))
    edit(c, state, [&] { c.apply(AmbientEdit{ambient}); });
  const double extent = glm::length(scene.camera.eye - scene.camera.lookat);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Light light = scene.lights[i];
    const std::string label = "light " + std::to_string(i + 1);
    const ui::Scope scope(label);
    bool changed = ui::dragDoubles(label.c_str(), &light.position[0], 3, dragSpeed(extent), "%.2f");
    const double peak = std::max(1e-9, maxComponent(light.intensity));
    if (ui::dragDoubles("##intensity", &light.intensity[0], 3, dragSpeed(peak), "%.2f")) {
      light.intensity =
          glm::max(light.intensity, Color(0.0)); // never negative (docs/scene-language.md)
      changed = true;
    }
    // The intensity's hue, at full brightness, in place of a label.
    ImGui::SameLine();
    const ImVec4 swatch(float(light.intensity.r / peak), float(light.intensity.g / peak),
                        float(light.intensity.b / peak), 1.0f);
    ImGui::ColorButton("##colour", swatch, ImGuiColorEditFlags_NoTooltip, ImVec2(12.0f, 12.0f));
    ImGui::SameLine(0.0f, 4.0f);
    ImGui::TextUnformatted("intensity");
    if (changed) edit(c, state, [&] { c.apply(LightEdit{i, light}); });
    if (ui::button("reset")) c.apply(ResetLight{i});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the file's position and intensity");
  }
}

void fogTooltip() {
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Density 0 is no fog (the colour then does nothing).\n"
                      "Density is per unit of scene length: across a distance d\n"
                      "exp(-density d) of the light gets through and the rest is\n"
                      "the fog's colour; at 1 / density, 37%% gets through.");
}

// The fog as one edit of colour and density; density never negative (a
// typed NaN becomes 0 too: std::max keeps its first argument).
void fogSection(ViewController& c, WindowState& state) {
  Fog fog = c.scene().fog;
  bool changed = dragColour("fog colour", fog.color);
  fogTooltip();
  if (ui::dragDoubles("fog density", &fog.density, 1, dragSpeed(std::max(0.05, fog.density)),
                      "%.4f")) {
    fog.density = std::max(0.0, fog.density);
    changed = true;
  }
  fogTooltip();
  if (changed) edit(c, state, [&] { c.apply(FogEdit{fog}); });
}

// A value for a float widget: a double past the float range would be
// undefined behaviour to convert (a scene may hold 1e300).
float toFloat(double value) {
  const double limit = double(std::numeric_limits<float>::max());
  return float(std::clamp(value, -limit, limit));
}

// A colour picked as floats: the channels the user did not change keep their
// exact value (a float would round them). Never negative (a typed NaN
// becomes 0 too: std::max keeps its first argument).
bool pickColour(const char* label, Color& colour) {
  float rgb[3] = {toFloat(colour.r), toFloat(colour.g), toFloat(colour.b)};
  if (!ui::colourEdit(label, rgb)) return false;
  bool changed = false;
  for (int i = 0; i < 3; ++i) {
    if (rgb[i] == toFloat(colour[i])) continue;
    colour[i] = std::max(0.0, double(rgb[i]));
    changed = true;
  }
  return changed;
}

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// Each texture of the scene (a `texture` or `image` line, on every primitive
// it covers): its scale and colours, as one edit. An image alone has no
// value-1 colour: its scale is its size and the surface colour its tint.
void texturesSection(ViewController& c, WindowState& state) {
  const FileValues& file = c.fileValues();
  for (std::size_t i = 0; i < file.textures.size(); ++i) {
    const FileTexture& texture = file.textures[i];
    const bool imageOnly = texture.group.imageOnly();
    const bool withImage = texture.group.image.active();
    const std::string name = "texture " + std::to_string(i + 1);
    const ui::Scope scope(name);
    dimText(name + ": " + texture.description() +
            (texture.place.empty() ? "" : ", on " + texture.place));
    TextureValues values = c.edits().textureOver(file, i);
    bool changed = false;
    // A slider a decade either side of the file's scale; Ctrl+click types any.
    const float fileScale = toFloat(texture.values().scale);
    float scale = toFloat(values.scale);
    if (ui::sliderFloat("scale", &scale, 0.1f * fileScale, 10.0f * fileScale, "%.4g",
                        ImGuiSliderFlags_Logarithmic) &&
        scale > 0.0f && std::isfinite(scale) && scale != toFloat(values.scale)) {
      values.scale = double(scale);
      changed = true;
    }
    if (imageOnly)
      tooltip("the size of one repeat of the image in the surface's coordinates\n"
              "(1 / SU of the uv line; SV follows, so the image keeps its aspect)");
    else if (withImage)
      tooltip("the pattern's size in the object's units (the texture line's SCALE);\n"
              "the image is sized with it (the uv line's SU and SV)");
    else
      tooltip("the pattern's size in the object's units (the texture line's SCALE)");
    if (!imageOnly) {
      changed |= pickColour("texture colour", values.color);
      tooltip("the colour where the pattern is 1 (the texture line's R G B)");
    }
    changed |= pickColour("surface colour", values.base);
    if (imageOnly)
      tooltip("the colour the image multiplies: the material's own\n"
              "(the surface line's R G B; white shows the image as it is)");
    else
      tooltip(withImage ? "the colour where the pattern is 0: the material's own\n"
                          "(the surface line's R G B); the image multiplies both ends"
                        : "the colour where the pattern is 0: the material's own\n"
                          "(the surface line's R G B)");
    if (changed) edit(c, state, [&] { c.apply(TextureEdit{i, values}); });
    if (ui::button("reset")) c.apply(ResetTexture{i});
    tooltip("back to the file's scale and colours for this texture");
  }
}

// Whether `camera` can be rendered (docs/image-formation.md): a view direction, `up` not
// along it, a field of view strictly between 0 and 180 degrees.
bool usable(const CameraSpec& camera) {
  const Vec3 forward = camera.lookat - camera.eye;
  if (!(camera.fov > 0.0 && camera.fov < 180.0) || forward == Vec3(0.0)) return false;
  const Vec3 side = glm::cross(glm::normalize(forward), glm::normalize(camera.up));
  return isFinite(side) && glm::length(side) > 1e-9;
}

void cameraSection(ViewController& c, WindowState& state) {
  CameraSpec cam = c.scene().camera;
  const double extent = std::max(1e-9, glm::length(cam.eye - cam.lookat));
  bool changed = ui::dragDoubles("eye", &cam.eye[0], 3, dragSpeed(extent), "%.3f");
  changed |= ui::dragDoubles("lookat", &cam.lookat[0], 3, dragSpeed(extent), "%.3f");
  float fov = float(cam.fov);
  if (ui::sliderFloat("fov", &fov, 1.0f, 179.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp)) {
    cam.fov = double(fov);
    changed = true;
  }
  // An edit that would leave no view (eye on lookat, up along the view) is
  // not applied.
  if (changed && usable(cam)) edit(c, state, [&] { c.apply(CameraEdit{cam}); });
  if (ui::button("Reset camera (Home)")) c.apply(ResetCamera{});
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the scene file's camera");
  dimText("On the picture: drag to orbit, right-drag or shift-drag to pan, wheel to zoom.");
}

// How the picture is exposed: the automatic 128 / avgmax, or locked at the
// current avgmax; either offset by EV stops. The text below always has the
// same number of lines, so the panel never jumps as the render refines.
void displaySection(ViewController& c, WindowState& state) {
  ui::checkbox("supersampled pixels (O)", &state.overlay);
  ui::checkbox("lights (L)", &state.markers);
  bool locked = state.exposure.locked();
  if (ui::checkbox("lock exposure (E)", &locked)) state.exposure.setLocked(locked);
  float ev = float(state.exposure.ev());
  if (ui::sliderFloat("EV offset", &ev, -5.0f, 5.0f, "%+.1f")) state.exposure.setEv(double(ev));
  ImGui::Text("avgmax %.5g   scale %.5g", state.exposure.avgmax(), double(state.exposure.scale()));
  const SessionProgress& p = c.progress();
  const char* source = state.exposure.locked()           ? "locked: the render does not change it"
                       : p.phase != SessionPhase::Coarse ? "pass 1's avgmax"
                       : state.exposure.holding()        ? "held from before the edit"
                                                         : "from the complete coarse levels";
  dimText(source);
}

// The picture's zoom (the camera stays), and the comparison with a pinned
// render.
void viewSection(ViewController& c, WindowState& state, float shownZoom) {
  float percent = 100.0f * shownZoom;
  if (ui::sliderFloat("zoom %", &percent, 100.0f * kMinZoom, 100.0f * kMaxZoom, "%.0f%%",
                      ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
    state.picture.fit = false;
    state.picture.zoom = percent / 100.0f;
  }
  if (ui::button("Fit (F)")) state.picture.fit = true;
  ImGui::SameLine();
  if (ui::button("1:1 (1)")) setPictureActualSize(state);
  ImGui::SameLine();
  dimText("Ctrl + wheel zooms, Ctrl + drag moves");
  if (ui::button("Pin this render (P)")) pinRender(c, state);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("keep the picture as it is now, to compare the next one with it");
  if (!state.pinned.valid) return;
  int mode = int(state.compare);
  bool changed = ui::radioButton("off", &mode, int(CompareMode::Off));
  ImGui::SameLine();
  changed |= ui::radioButton("flip (B)", &mode, int(CompareMode::Flip));
  ImGui::SameLine();
  changed |= ui::radioButton("split", &mode, int(CompareMode::Split));
  if (changed) state.compare = CompareMode(mode);
  if (state.compare == CompareMode::Split)
    ui::sliderFloat("split at", &state.split, 0.0f, 1.0f, "%.2f");
  if (state.compare == CompareMode::Flip)
    ui::checkbox("show the pinned render (B)", &state.showPinned);
  // The speed/accuracy trade made visible: what each render cost.
  const auto row = [](const char* what, const std::string& live, const std::string& pinned) {
    ImGui::TableNextColumn();
    ImGui::TextColored(kDimColour, "%s", what);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(live.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pinned.c_str());
  };
  const auto figures = [](const RenderSettings& s, const SessionProgress& p) {
    const double pixels = std::max(1.0, double(s.width) * double(s.height));
    char time[32], rays[32], share[32], settings[48];
    std::snprintf(time, sizeof time, "%.2f s", p.elapsedSeconds);
    std::snprintf(rays, sizeof rays, "%.2f", double(p.counts.total()) / pixels);
    std::snprintf(share, sizeof share, "%.1f%%", 100.0 * double(p.supersampledPixels) / pixels);
    std::snprintf(settings, sizeof settings, "depth %d, %.3g", s.maxDepth, s.thresh);
    return std::array<std::string, 4>{time, rays, share, settings};
  };
  const auto live = figures(c.settings(), c.progress());
  const auto pinned = figures(state.pinned.settings, state.pinned.progress);
  if (ImGui::BeginTable("compare", 3, ImGuiTableFlags_SizingStretchSame)) {
    row("", "live", "pinned");
    row("time", live[0], pinned[0]);
    row("rays / pixel", live[1], pinned[1]);
    row("supersampled", live[2], pinned[2]);
    row("depth, thresh", live[3], pinned[3]);
    ImGui::EndTable();
  }
}

// The ray tree of the pixel last clicked on the picture.
void pixelSection(WindowState& state) {
  if (!state.inspected) {
    dimText("Click the picture to see a pixel's ray tree; hover to read its value.");
    return;
  }
  if (ui::button("Close")) {
    state.inspected.reset();
    return;
  }
  ImGui::BeginChild("ray tree", ImVec2(0.0f, 260.0f * state.uiScale), true,
                    ImGuiWindowFlags_HorizontalScrollbar);
  ImGui::TextUnformatted(state.rayTree.c_str());
  ImGui::EndChild();
}

void saveSection(ViewController& c, WindowState& state) {
  ImGui::SetNextItemWidth(-1.0f);
  ui::inputText("##path", &state.savePath);
  const bool busy = c.saveJob().busy();
  ImGui::BeginDisabled(busy || state.savePath.empty());
  if (ui::button("Save picture (Ctrl+S)")) savePicture(c, state);
  ImGui::EndDisabled();
  ui::checkbox("with the window's exposure", &state.saveWindowExposure);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("otherwise the picture is exposed automatically, as prism render does "
                      "(the file's description says which)");
  const SaveJob& job = c.saveJob();
  if (job.state() == SaveJob::State::WaitingForRender) {
    ImGui::ProgressBar(float(state.estimate.timeFraction()), ImVec2(-1.0f, 0.0f),
                       "finishing the render...");
  } else if (job.state() == SaveJob::State::Failed) {
    errorText(job.message());
  } else if (job.state() != SaveJob::State::Idle) {
    ImGui::TextWrapped("%s", job.message().c_str());
  }
  // The camera and lights as edited here, as a scene file (includes are
  // written out: see ViewController::saveSceneAs).
  ImGui::SetNextItemWidth(-1.0f);
  ui::inputText("##scene path", &state.scenePath);
  ImGui::BeginDisabled(c.sceneSaveBusy() || state.scenePath.empty());
  if (ui::button("Save scene as .sc")) c.saveSceneAs(state.scenePath);
  ImGui::EndDisabled();
  if (c.sceneSaveState() == ViewController::SceneSaveState::Failed) {
    errorText(c.sceneSaveMessage());
  } else if (c.sceneSaveState() != ViewController::SceneSaveState::Idle) {
    ImGui::TextWrapped("%s", c.sceneSaveMessage().c_str());
  }
}

void statisticsSection(ViewController& c, WindowState& state, const FrameStats& frames) {
  const SessionProgress& p = c.progress();
  const RenderSettings s = c.settings();
  char progress[96];
  std::snprintf(progress, sizeof progress, "%s   %.0f%%", phaseText(p).c_str(),
                100.0 * state.estimate.timeFraction());
  ImGui::ProgressBar(float(state.estimate.timeFraction()), ImVec2(-1.0f, 0.0f), progress);
  ImGui::TextUnformatted(state.estimate.text().c_str());
  const double pixels = std::max(1.0, double(s.width) * double(s.height));
  const RayCounts& r = p.counts;
  const double seconds = std::max(p.elapsedSeconds, 1e-9);
  ImGui::Text("%.2f M rays/s", double(r.total()) / seconds * 1e-6);
  // Fixed column widths: stretched ones have no width in the first frame.
  const float column = 0.25f * ImGui::GetContentRegionAvail().x;
  if (ImGui::BeginTable("rays", 4, ImGuiTableFlags_SizingFixedFit)) {
    for (int i = 0; i < 4; ++i)
      ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthFixed,
                              i % 2 == 0 ? 1.4f * column : 0.6f * column);
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
    cell("all / pixel", double(r.total()));
    ImGui::EndTable();
  }
  ImGui::Text("supersampled %s pixels (%.1f%%)", withSeparators(p.supersampledPixels).c_str(),
              100.0 * double(p.supersampledPixels) / pixels);
  ImGui::TextColored(kDimColour, "restarts %s   window %.0f fps",
                     withSeparators((long long)p.restarts).c_str(), frames.recentFps());
}

// Where the current settings sit in the scene's sweep table (viewer/sweep_view.h):
// their expected error and the most accurate setting that costs no more.
void sweepSection(const SweepStatus& sweep) {
  if (!sweep.error.empty()) {
    for (const std::string& line : sweep.lines)
      errorText(line);
    return;
  }
  for (std::size_t i = 0; i < sweep.lines.size(); ++i) {
    if (i == 0)
      dimText(sweep.lines[i]); // the file
    else
      ImGui::TextWrapped("%s", sweep.lines[i].c_str());
  }
}

// Every key and mouse action of the window, for the F1 overlay.
struct KeyHelp {
  const char* keys;
  const char* action;
};
constexpr KeyHelp kKeys[] = {
    {"left drag on the picture", "orbit the camera around lookat"},
    {"right drag, middle drag, shift + left drag", "pan: the point under the mouse stays under it"},
    {"mouse wheel", "zoom: move the eye toward or away from lookat"},
    {"Home", "back to the scene file's camera"},
    {"click on the picture", "show that pixel's ray tree (hover: its value)"},
    {"Ctrl + wheel, Ctrl + drag", "zoom and move the picture (the camera stays)"},
    {"F, 1", "fit the picture to the window; show it at 1:1"},
    {"P", "pin this render for comparison"},
    {"B", "flip between the live and the pinned render"},
    {"Esc", "close the pixel's ray tree"},
    {"R, F5", "reload the scene files"},
    {"Ctrl+O, dropping a file on the window", "open another scene (recent ones are listed)"},
    {"O", "tint the supersampled pixels"},
    {"L", "show the lights"},
    {"E", "lock or unlock the exposure"},
    {"Tab", "hide or show the panel"},
    {"F1", "this help"},
    {"Ctrl+Z", "undo the last edit (a whole drag is one)"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"Ctrl+S", "save the final picture"},
    {"Ctrl+Q", "quit"},
};

} // namespace

float panelWidth(const WindowState& state) {
  return state.panelVisible ? kPanelWidth * state.uiScale : 0.0f;
}

std::string phaseText(const SessionProgress& p) {
  switch (p.phase) {
  case SessionPhase::Coarse:
    return "pass 1, " + std::to_string(p.level) + "x" + std::to_string(p.level) + " level";
  case SessionPhase::Antialias: return "pass 2, antialiasing";
  case SessionPhase::Done: break;
  }
  char text[48];
  std::snprintf(text, sizeof text, "done in %.2f s", p.elapsedSeconds);
  return text;
}

void drawControlPanel(ViewController& c, WindowState& state, const FrameStats& frames, float width,
                      float height, float shownZoom) {
  if (!state.panelVisible) return;
  const float panel = panelWidth(state);
  ImGui::SetNextWindowPos(ImVec2(width - panel, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(panel, height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoTitleBar;
  ImGui::Begin("Prism", nullptr, flags);
  // Tab belongs to the window (it hides the panel); ImGui would otherwise
  // move the keyboard into the next text field with it.
  ImGui::PushAllowKeyboardFocus(false);
  ImGui::PushItemWidth(-110.0f * state.uiScale); // room for the labels
  sceneSection(c, state);
  // Each section's widgets sit in a scope of its own, so that no widget shares
  // an ImGui id with its section's header (the Save button did, and was dead).
  const auto section = [](const char* title, auto&& draw) {
    if (!ui::collapsingHeader(title)) return;
    const ui::Scope scope(title);
    draw();
  };
  section("Render", [&] { renderSection(c, state); });
  section("Lights", [&] { lightsSection(c, state); });
  section("Fog", [&] { fogSection(c, state); });
  if (!c.fileValues().textures.empty()) section("Textures", [&] { texturesSection(c, state); });
  section("Camera", [&] { cameraSection(c, state); });
  section("Display", [&] { displaySection(c, state); });
  section("View", [&] { viewSection(c, state, shownZoom); });
  section("Pixel", [&] { pixelSection(state); });
  section("Save", [&] { saveSection(c, state); });
  section("Statistics", [&] { statisticsSection(c, state, frames); });
  if (const SweepStatus sweep = c.sweepStatus(); sweep.visible)
    section("Sweep", [&] { sweepSection(sweep); });
  ImGui::PopItemWidth();
  ImGui::PopAllowKeyboardFocus();
  if (state.panelGesture && !ImGui::IsAnyItemActive()) { // the widget was let go
    c.endGesture();
    state.panelGesture = false;
  }
  ImGui::End();
}

void drawHelp(WindowState& state, float width, float height) {
  if (!state.showHelp) return;
  // Within the window whatever its size: the list scrolls, the button stays.
  const float w = std::min(width - 40.0f, 560.0f * state.uiScale);
  ImGui::SetNextWindowPos(ImVec2(0.5f * width, 0.5f * height), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(w, std::min(height - 40.0f, 480.0f * state.uiScale)));
  ImGui::Begin("Keys and mouse (F1)", &state.showHelp,
               ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  {
    const ui::Scope scope("Help");
    if (ui::button("Close (F1)")) state.showHelp = false;
  }
  ImGui::BeginChild("keys");
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingStretchProp)) {
    for (const KeyHelp& k : kKeys) {
      ImGui::TableNextColumn();
      ImGui::TextColored(kDimColour, "%s", k.keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", k.action);
    }
    ImGui::EndTable();
  }
  ImGui::EndChild();
  ImGui::End();
}

void pinRender(const ViewController& c, WindowState& state) {
  PinnedRender& pinned = state.pinned;
  pinned.image = c.image();
  pinned.scale = state.exposure.scale();
  pinned.settings = c.settings();
  pinned.progress = c.progress();
  pinned.valid = true;
  ++pinned.generation;
  if (state.compare == CompareMode::Off) state.compare = CompareMode::Flip;
}

void setPictureActualSize(WindowState& state) {
  state.picture.fit = false;
  state.picture.zoom = 1.0f;
}

void savePicture(ViewController& c, WindowState& state) {
  if (state.savePath.empty()) return;
  PictureExposure exposure; // the automatic exposure, unless the user asks
  if (state.saveWindowExposure && !state.exposure.automatic()) {
    exposure.automatic = false;
    exposure.avgmax = state.exposure.avgmax();
    exposure.ev = state.exposure.ev();
  }
  c.save(state.savePath, exposure);
  state.note =
      c.sceneErrors().empty() ? "" : "the scene files have errors: saving the last good scene";
  if (!state.note.empty()) std::cerr << "prism: " << state.note << "\n"; // for a terminal too
}

void handleShortcuts(ViewController& c, WindowState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  // In ImGui 1.86 the GLFW backend indexes io.KeysDown by GLFW key code.
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_S)) savePicture(c, state);
    if (pressed(GLFW_KEY_O)) state.open.visible = true;
    if (pressed(GLFW_KEY_Q)) state.quit = true;
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) c.undo();
    if ((pressed(GLFW_KEY_Z) && io.KeyShift) || pressed(GLFW_KEY_Y)) c.redo();
    return;
  }
  if (pressed(GLFW_KEY_R) || pressed(GLFW_KEY_F5)) c.reload();
  if (pressed(GLFW_KEY_O)) state.overlay = !state.overlay;
  if (pressed(GLFW_KEY_L)) state.markers = !state.markers;
  if (pressed(GLFW_KEY_E)) state.exposure.setLocked(!state.exposure.locked());
  if (pressed(GLFW_KEY_TAB)) state.panelVisible = !state.panelVisible;
  if (pressed(GLFW_KEY_F1)) state.showHelp = !state.showHelp;
  if (pressed(GLFW_KEY_HOME)) c.apply(ResetCamera{});
  if (pressed(GLFW_KEY_F)) state.picture.fit = true;
  if (pressed(GLFW_KEY_1)) setPictureActualSize(state);
  if (pressed(GLFW_KEY_P)) pinRender(c, state);
  if (pressed(GLFW_KEY_B) && state.pinned.valid) {
    state.compare = CompareMode::Flip;
    state.showPinned = !state.showPinned;
  }
  if (pressed(GLFW_KEY_ESCAPE)) state.inspected.reset();
}

} // namespace prism
