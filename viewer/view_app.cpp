#include "view_app.h"

#include "gl.h" // before GLFW, which would otherwise include GL/gl.h itself

#include "camera_controls.h"
#include "display.h"
#include "frame_stats.h"
#include "image_view.h"
#include "input_latch.h"
#include "number_text.h"
#include "open_dialog.h"
#include "panels.h"
#include "scene_files.h"
#include "widgets.h"

#include "core/io/image_io.h"
#include "core/io/pending_file.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#ifdef __SANITIZE_ADDRESS__
#include <dlfcn.h>
#include <link.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <utility>

namespace prism {

namespace {

using Clock = std::chrono::steady_clock;

// Under Xvfb (and with many drivers) the swap interval does not throttle, so the
// loop waits for events until the next frame is due: 60 frames a second at most,
// and an idle window costs nothing.
constexpr double kFrameSeconds = 1.0 / 60.0;

std::string lastGlfwError;

void rememberGlfwError(int code, const char* description) {
  lastGlfwError = description ? description : "GLFW error " + std::to_string(code);
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

#ifdef __SANITIZE_ADDRESS__
// Sanitizer builds only: glfwTerminate unloads Mesa's DRI driver, and a leak
// LeakSanitizer then finds in it shows as "<unknown module>", which no
// suppression can name (tests/lsan-mesa.supp). Marking every loaded driver
// RTLD_NODELETE keeps it mapped until exit, so its leaks stay attributable.
void keepGlDriversLoaded() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const std::string name = info->dlpi_name ? info->dlpi_name : "";
        if (name.find("/dri/") != std::string::npos)
          dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE); // never closed on purpose
        return 0;
      },
      nullptr);
}
#else
void keepGlDriversLoaded() {}
#endif

// Files dropped on the window since the last frame (GLFW calls back on the
// window's thread).
std::vector<std::string> droppedFiles;

void rememberDroppedFiles(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i)
    droppedFiles.emplace_back(paths[i]);
}

std::vector<std::string> takeDroppedFiles() { return std::exchange(droppedFiles, {}); }

// The monitor's content scale: 2 on a screen set up for twice the usual
// pixels per inch. Fonts, the panel and the status line grow by it.
float contentScale(GLFWwindow* window) {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window, &x, &y);
  return std::clamp(std::max(x, y), 1.0f, 4.0f);
}

// The window's size for an image of `width` x `height` and the panel, within
// the screen.
void fitWindow(GLFWwindow* window, int width, int height) {
  const float scale = contentScale(window);
  int w = width + int(kPanelWidth * scale);
  int h = std::max(height + int(kStatusHeight * scale), int(760.0f * scale));
  if (const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor())) {
    w = std::min(w, mode->width);
    h = std::min(h, mode->height);
  }
  glfwSetWindowSize(window, w, h);
}

// A window for the scene, opened before it is read (its size is set again
// once the image size is known).
GLFWwindow* createWindow(const ViewAppOptions& options) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const std::string title = "Prism - " + options.scenePath;
  GLFWwindow* window = glfwCreateWindow(int(kPanelWidth) + std::max(options.width, 512),
                                        std::max(options.height, 736) + int(kStatusHeight),
                                        title.c_str(), nullptr, nullptr);
  if (window) {
    // Never so narrow that the panel leaves no room for the picture (and Tab
    // hides the panel altogether).
    const float scale = contentScale(window);
    glfwSetWindowSizeLimits(window, int((kPanelWidth + 160.0f) * scale), int(360.0f * scale),
                            GLFW_DONT_CARE, GLFW_DONT_CARE);
  }
  return window;
}

void styleImGui(float scale) {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.WindowBorderSize = 0.0f;
  style.ItemSpacing = ImVec2(8.0f, 5.0f);
  style.WindowPadding = ImVec2(10.0f, 10.0f);
  style.Colors[ImGuiCol_WindowBg] = ImVec4(0.105f, 0.11f, 0.125f, 1.0f);
  style.Colors[ImGuiCol_PlotHistogram] = ImVec4(0.30f, 0.52f, 0.90f, 1.0f); // progress bars
  style.ScaleAllSizes(scale);
  // The default font drawn at the scaled size (crisp), not its 13-pixel
  // bitmap magnified.
  ImFontConfig font;
  font.SizePixels = 13.0f * scale;
  ImGui::GetIO().Fonts->AddFontDefault(&font);
}

// What the loading screen and stderr say about a stage that has lasted a while.
std::string loadingText(const ViewAppOptions& options, const LoadProgress& progress) {
  if (progress.stage.load() == 0) return "reading " + options.scenePath;
  return "building the hierarchy of " + withSeparators((long long)progress.primitives.load()) +
         " primitives";
}

// Shows, until the scene is read and its hierarchy built, what is being done
// and for how long, also on stderr once a stage has taken a second (a scene of
// a million primitives takes several). Closing the window meanwhile ends the
// program once the reading, which cannot be interrupted, is over.
PreparedView showLoading(GLFWwindow* window, const ViewAppOptions& options) {
  LoadProgress progress;
  std::future<PreparedView> loading =
      std::async(std::launch::async, options.prepare, std::ref(progress));
  const Clock::time_point start = Clock::now();
  Clock::time_point stageBegan = start;
  int stage = 0, announced = -1;
  while (loading.wait_for(std::chrono::milliseconds(0)) != std::future_status::ready) {
    if (progress.stage.load() != stage) {
      stage = progress.stage.load();
      stageBegan = Clock::now();
    }
    const double stageSeconds = seconds(Clock::now() - stageBegan);
    if (stageSeconds >= 1.0 && announced != stage) {
      std::cerr << "prism: " << loadingText(options, progress) << "...\n";
      announced = stage;
    }
    beginInputFrame();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    applyInputFrame();
    ImGui::NewFrame();
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * size.x, 0.5f * size.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::Begin("Loading", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoMove);
    ImGui::Text("Prism: %s", loadingText(options, progress).c_str());
    char elapsed[64];
    std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds(Clock::now() - start));
    // Nothing tells how much of a stage is done: the bar sweeps to show life.
    const float sweep = float(std::fmod(seconds(Clock::now() - start), 2.0) / 2.0);
    ImGui::ProgressBar(sweep, ImVec2(360.0f * contentScale(window), 0.0f), elapsed);
    ImGui::End();
    ImGui::Render();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    glViewport(0, 0, w, h);
    glClearColor(0.07f, 0.075f, 0.085f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
    glfwWaitEventsTimeout(1.0 / 30.0);
    if (glfwWindowShouldClose(window)) {
      glfwHideWindow(window);
      loading.wait();
      return {nullptr, 0};
    }
  }
  if (announced >= 0) {
    char ready[64];
    std::snprintf(ready, sizeof ready, "prism: ready in %.1f s\n", seconds(Clock::now() - start));
    std::cerr << ready;
  }
  return loading.get();
}

// The previewer while its window is open. Also the host of a scripted session:
// a script's actions go through the same controller calls as the panel's.
class ViewApp : public ScriptHost {
public:
  ViewApp(GLFWwindow* window, std::unique_ptr<ViewController> controller,
          const ViewAppOptions& options)
      : window_(window), controller_(std::move(controller)), dumpWidgets_(options.dumpWidgets) {
    state_.savePath = options.savePath;
    // Beside the scene file: a saved view belongs with the scene it shows.
    const std::filesystem::path scene(options.scenePath);
    state_.scenePath = (scene.parent_path() / (scene.stem().string() + "-view.sc")).string();
    state_.uiScale = contentScale(window);
    title_ = options.scenePath;
    state_.recent.add(options.scenePath);
    if (options.script) script_.emplace(*options.script);
  }

  int run();

  void start(const ScriptAction& action) override;
  bool finished(const ScriptAction& action) override;

private:
  void frame();
  void dumpWidgets();
  void drawPictures(const ImageLayout& layout, int fbHeight, float framebufferScale);
  void takeScreenshot(int width, int height);
  RenderSettings edited(const ScriptAction& a) const;
  std::size_t lightIndex(const ScriptAction& a) const;

  GLFWwindow* window_;
  std::unique_ptr<ViewController> controller_;
  ImageDisplay display_;
  ImageDisplay pinnedDisplay_;       // the render pinned for comparison
  std::uint64_t pinnedUploaded_ = 0; // the pin generation on the GPU
  std::string title_;                // the scene the window's title names
  WindowState state_;
  std::string dumpWidgets_; // --dump-widgets FILE
  ImageDrag drag_;
  FrameStats frames_;
  std::optional<ScriptRunner> script_;
  bool quit_ = false;
  std::uint64_t frameNumber_ = 0;
  std::uint64_t framesAtStart_ = 0; // for `frames N`
  std::string screenshotPath_;      // taken at the end of this frame
  bool screenshotTaken_ = false;
  int reloadsSeen_ = 0; // for `wait reload` / `wait error`
  int errorsSeen_ = 0;
};

int ViewApp::run() {
  Clock::time_point previous = Clock::now();
  while (!glfwWindowShouldClose(window_) && !quit_ && !state_.quit) {
    const Clock::time_point begin = Clock::now();
    const bool rendering = controller_->progress().phase != SessionPhase::Done;
    try {
      frame();
    } catch (const std::runtime_error& error) {
      std::cerr << "prism: error: " << error.what() << "\n";
      std::cout << frames_.summary() << std::endl;
      return 1;
    }
    const Clock::time_point end = Clock::now();
    if (frameNumber_ > 1) // the first frame has no interval yet
      frames_.record(seconds(begin - previous), seconds(end - begin), rendering);
    previous = begin;
    const Clock::time_point due = begin + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(kFrameSeconds));
    for (Clock::time_point now = end; now < due && !glfwWindowShouldClose(window_);
         now = Clock::now())
      glfwWaitEventsTimeout(seconds(due - now));
    glfwPollEvents();
  }
  if (script_) std::cout << frames_.summary() << std::endl;
  return 0;
}

void ViewApp::frame() {
  if (controller_->update()) {
    const SessionImage& image = controller_->image();
    display_.upload(image.width, image.height, image.radiance, image.supersampled);
  }
  state_.exposure.update(controller_->progress());
  state_.estimate.update(controller_->progress());
  // A scene file dropped on the window opens (the first one, if several).
  for (const std::string& path : takeDroppedFiles()) {
    if (!isSceneFile(path)) continue;
    openScene(*controller_, state_.recent, path);
    break;
  }
  if (controller_->scenePath() != title_) { // opened another scene
    title_ = controller_->scenePath();
    glfwSetWindowTitle(window_, ("Prism - " + title_).c_str());
    state_.inspected.reset();
  }
  // An inspected pixel's ray tree follows edits of the scene.
  if (state_.inspected && state_.rayTreeRestarts != controller_->progress().restarts)
    inspect(*controller_, state_, *state_.inspected);
  if (state_.pinned.valid && state_.pinned.generation != pinnedUploaded_) {
    const SessionImage& pinned = state_.pinned.image;
    pinnedDisplay_.upload(pinned.width, pinned.height, pinned.radiance, pinned.supersampled);
    pinnedUploaded_ = state_.pinned.generation;
  }
  if (script_) script_->step(*this); // may edit, save, request a screenshot or quit

  int fbWidth = 0, fbHeight = 0;
  glfwGetFramebufferSize(window_, &fbWidth, &fbHeight);
  beginInputFrame(); // this frame's share of the keys and clicks
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  applyInputFrame(); // the replayed buttons and pointer, not the live ones
  ImGui::NewFrame();
  widgetLog().beginFrame();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const ImageLayout layout =
      layoutImage(size.x, size.y, state_, display_.width(), display_.height());
  handleShortcuts(*controller_, state_);
  navigateWithMouse(*controller_, layout, state_, drag_);
  drawControlPanel(*controller_, state_, frames_, size.x, size.y - statusHeight(state_),
                   layout.zoom);
  if (state_.markers) drawLightMarkers(*controller_, layout);
  drawStatusLine(*controller_, state_, layout);
  if (state_.compare == CompareMode::Split && state_.pinned.valid) {
    // Where the pinned render begins, over the picture.
    const float x = layout.left + state_.split * float(display_.width()) * layout.zoom;
    ImGui::GetBackgroundDrawList()->AddLine(
        ImVec2(x, std::max(layout.top, 0.0f)),
        ImVec2(x, std::min(layout.top + float(display_.height()) * layout.zoom, layout.areaHeight)),
        IM_COL32(255, 255, 255, 200), 1.5f * state_.uiScale);
  }
  drawHelp(state_, size.x, size.y);
  drawOpenDialog(*controller_, state_.open, state_.recent, state_.uiScale, size.x, size.y);
  ImGui::Render();
  if (!dumpWidgets_.empty()) dumpWidgets();

  glViewport(0, 0, fbWidth, fbHeight);
  glClearColor(0.07f, 0.075f, 0.085f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  drawPictures(layout, fbHeight, size.x > 0.0f ? float(fbWidth) / size.x : 1.0f);
  glViewport(0, 0, fbWidth, fbHeight);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

  if (!screenshotPath_.empty()) takeScreenshot(fbWidth, fbHeight);
  glfwSwapBuffers(window_);
  ++frameNumber_;
}

// The live picture, and the pinned one where the comparison shows it: all of
// it (flip) or right of the split.
void ViewApp::drawPictures(const ImageLayout& layout, int fbHeight, float framebufferScale) {
  // Window coordinates run down from the top; GL's up from the bottom.
  DisplayView view;
  view.zoom = layout.zoom * framebufferScale;
  view.x = int(layout.left * framebufferScale);
  view.y = fbHeight - int((layout.top + float(display_.height()) * layout.zoom) * framebufferScale);
  view.clipX = 0;
  view.clipY = fbHeight - int(layout.areaHeight * framebufferScale);
  view.clipWidth = int(layout.areaWidth * framebufferScale);
  view.clipHeight = int(layout.areaHeight * framebufferScale);
  view.overlay = state_.overlay;
  const PinnedRender& pinned = state_.pinned;
  const bool comparable = pinned.valid && pinned.image.width == display_.width() &&
                          pinned.image.height == display_.height();
  const bool flipped = comparable && state_.compare == CompareMode::Flip && state_.showPinned;
  if (!flipped) {
    view.scale = state_.exposure.scale();
    display_.draw(view);
  }
  if (!comparable || state_.compare == CompareMode::Off ||
      (!flipped && state_.compare != CompareMode::Split))
    return;
  view.scale = pinned.scale;
  if (state_.compare == CompareMode::Split) {
    const int split = int((layout.left + state_.split * float(display_.width()) * layout.zoom) *
                          framebufferScale);
    view.clipWidth -= std::max(0, split - view.clipX);
    view.clipX = std::max(view.clipX, split);
  }
  pinnedDisplay_.draw(view);
}

// The widgets of this frame, for tests that click them (written whole or not
// at all, so a reader never sees half a list).
void ViewApp::dumpWidgets() {
  const std::vector<std::string> duplicates = widgetLog().duplicateIds();
  if (!duplicates.empty())
    throw std::runtime_error("two widgets share an ImGui id: " + duplicates.front());
  const std::string json = widgetLog().json();
  writeFileAtomically(dumpWidgets_, [&](std::ostream& out) { out << json; });
}

void ViewApp::takeScreenshot(int width, int height) {
  glReadBuffer(GL_BACK); // this frame, drawn but not yet swapped
  const std::string path = std::move(screenshotPath_);
  screenshotPath_.clear();
  writeImage8(path, width, height, readPixelsRgb(0, 0, width, height));
  screenshotTaken_ = true;
}

RenderSettings ViewApp::edited(const ScriptAction& a) const {
  RenderSettings s = controller_->settings();
  if (a.op == ScriptOp::Depth) s.maxDepth = a.index;
  if (a.op == ScriptOp::Thresh) s.thresh = a.values[0];
  if (a.op == ScriptOp::Jitter) s.jitter = a.values[0] != 0.0;
  if (a.op == ScriptOp::NoAa) s.noAa = a.values[0] != 0.0;
  return s;
}

std::size_t ViewApp::lightIndex(const ScriptAction& a) const {
  const std::size_t count = controller_->scene().lights.size();
  if (a.index < 1 || std::size_t(a.index) > count)
    throw std::runtime_error("there is no light " + std::to_string(a.index) + " (the scene has " +
                             std::to_string(count) + ")");
  return std::size_t(a.index - 1);
}

void ViewApp::start(const ScriptAction& a) {
  const auto vec = [&](std::size_t first) {
    return Vec3(a.values[first], a.values[first + 1], a.values[first + 2]);
  };
  const CameraSpec& camera = controller_->scene().camera;
  switch (a.op) {
  case ScriptOp::Wait:
  case ScriptOp::Timeout: break;
  case ScriptOp::Frames: framesAtStart_ = frameNumber_; break;
  case ScriptOp::Depth:
  case ScriptOp::Thresh:
  case ScriptOp::Jitter:
  case ScriptOp::NoAa: controller_->apply(SettingsEdit{edited(a)}); break;
  case ScriptOp::Ambient: controller_->apply(AmbientEdit{vec(0)}); break;
  case ScriptOp::Fog: controller_->apply(FogEdit{Fog{vec(0), a.values[3]}}); break;
  case ScriptOp::Light:
  case ScriptOp::Intensity: {
    const std::size_t i = lightIndex(a);
    Light light = controller_->scene().lights[i];
    (a.op == ScriptOp::Light ? light.position : light.intensity) = vec(0);
    controller_->apply(LightEdit{i, light});
    break;
  }
  case ScriptOp::Texture:
    controller_->apply(textureEditOf(a, controller_->fileValues(), controller_->edits()));
    break;
  case ScriptOp::Orbit:
    controller_->apply(CameraEdit{orbit(camera, a.values[0], a.values[1])});
    break;
  case ScriptOp::Pan:
    controller_->apply(
        CameraEdit{pan(camera, a.values[0], a.values[1], controller_->settings().height)});
    break;
  case ScriptOp::Zoom: controller_->apply(CameraEdit{zoom(camera, a.values[0])}); break;
  case ScriptOp::Reset: controller_->apply(ResetCamera{}); break;
  case ScriptOp::Overlay: state_.overlay = a.values[0] != 0.0; break;
  case ScriptOp::Markers: state_.markers = a.values[0] != 0.0; break;
  case ScriptOp::Exposure: state_.exposure.setLocked(a.values[0] != 0.0); break;
  case ScriptOp::Ev: state_.exposure.setEv(a.values[0]); break;
  case ScriptOp::Picture:
    state_.picture.fit = a.values[0] == 0.0;
    state_.picture.zoom = float(a.values[0] / 100.0);
    break;
  case ScriptOp::Inspect: {
    const RenderSettings s = controller_->settings();
    const glm::ivec2 pixel(int(a.values[0]), int(a.values[1]));
    if (pixel.x >= s.width || pixel.y >= s.height)
      throw std::runtime_error("there is no pixel (" + std::to_string(pixel.x) + ", " +
                               std::to_string(pixel.y) + ") in the image");
    inspect(*controller_, state_, pixel);
    break;
  }
  case ScriptOp::Pin: pinRender(*controller_, state_); break;
  case ScriptOp::Compare:
    state_.compare = CompareMode(a.index);
    state_.showPinned = a.index == 1;
    state_.split = float(a.values[0]);
    break;
  case ScriptOp::Reload: controller_->reload(); break;
  case ScriptOp::Save: controller_->save(a.path); break;
  case ScriptOp::Screenshot:
    screenshotPath_ = a.path;
    screenshotTaken_ = false;
    break;
  case ScriptOp::Echo: std::cout << a.path << std::endl; break;
  case ScriptOp::Print: { // the panel's Sweep section, as text
    const SweepStatus sweep = controller_->sweepStatus();
    if (!sweep.visible) std::cout << "sweep: none\n";
    for (const std::string& line : sweep.lines)
      std::cout << "sweep: " << line << "\n";
    std::cout << std::flush;
    break;
  }
  case ScriptOp::Quit: quit_ = true; break;
  }
}

bool ViewApp::finished(const ScriptAction& a) {
  // Between an edit and the next update() the snapshot still shows the old render.
  const bool current = controller_->snapshotCurrent();
  const SessionProgress& p = controller_->progress();
  switch (a.op) {
  case ScriptOp::Wait:
    switch (a.waitFor) {
    case WaitFor::Coarse: return current && p.pass1Pixels > 0;
    case WaitFor::Pass1: return current && p.phase != SessionPhase::Coarse;
    case WaitFor::Done: return current && p.phase == SessionPhase::Done;
    case WaitFor::Reload:
      if (controller_->successfulReloads() <= reloadsSeen_) return false;
      reloadsSeen_ = controller_->successfulReloads();
      return true;
    case WaitFor::Error:
      if (controller_->failedReloads() <= errorsSeen_) return false;
      errorsSeen_ = controller_->failedReloads();
      return true;
    }
    return false;
  case ScriptOp::Frames: return frameNumber_ - framesAtStart_ >= std::uint64_t(a.index);
  case ScriptOp::Save:
    if (controller_->saveJob().state() == SaveJob::State::Failed)
      throw std::runtime_error(controller_->saveJob().message());
    return controller_->saveJob().state() == SaveJob::State::Saved;
  case ScriptOp::Screenshot: return screenshotTaken_;
  default: return true;
  }
}

} // namespace

bool openWindowSystem(std::string& why) {
  glfwSetErrorCallback(rememberGlfwError); // reported once, by the caller
  if (glfwInit()) return true;
  why = lastGlfwError.empty() ? "GLFW could not start" : lastGlfwError;
  return false;
}

void closeWindowSystem() { glfwTerminate(); }

std::optional<int> runViewApp(const ViewAppOptions& options, std::string& why) {
  GLFWwindow* window = createWindow(options);
  if (!window) {
    why = "cannot create an OpenGL 3.3 window: " + lastGlfwError;
    return std::nullopt;
  }
  glfwMakeContextCurrent(window);
  keepGlDriversLoaded();
  glfwSwapInterval(0); // the loop paces itself (see kFrameSeconds)

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr; // no imgui.ini beside the user's files
  styleImGui(contentScale(window));
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  installInputLatch(window);
  glfwSetDropCallback(window, rememberDroppedFiles);
  ImGui_ImplOpenGL3_Init("#version 330");

  int code = 0;
  try {
    // The window is open at once; the scene is read on a thread of its own.
    PreparedView prepared = showLoading(window, options);
    if (prepared.controller) {
      const RenderSettings s = prepared.controller->settings();
      fitWindow(window, s.width, s.height);
      ViewApp app(window, std::move(prepared.controller), options); // joins its threads on exit
      code = app.run();
    } else {
      code = prepared.exitCode;
    }
  } catch (const std::exception& error) { // the display shader, a screenshot's file
    std::cerr << "prism: error: " << error.what() << "\n";
    code = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return code;
}

} // namespace prism
