// What the previewer does, apart from drawing: it owns the render session,
// applies the user's edits to it (each one restarts refinement), reloads the
// scene when its files change, saves, and once a frame takes a consistent
// snapshot of the image and progress for the window. No GL, no ImGui: the
// panels, the mouse and scripts all go through these calls.
#pragma once

#include "file_watch.h"
#include "save_job.h"

#include "core/render_session.h"

#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <vector>

namespace prism {

struct ViewOptions {
  std::string scenePath;
  RenderSettings settings;   // size, depth, threshold, jitter, threads
  bool sizeFromScene = true; // follow the scene's `resolution` on reload (no --size)
  AccelKind accel = AccelKind::Groups;
  std::string savePath; // the Save field's initial text
};

class ViewController {
public:
  using Clock = std::chrono::steady_clock;

  // `warnings`: what loading `scene` reported (formatted), shown with the scene.
  ViewController(Scene scene, const ViewOptions& options, std::vector<std::string> warnings = {});
  ~ViewController(); // waits for a reload in progress

  // Edits: each cancels the work in flight and restarts refinement.
  void setSettings(const RenderSettings& settings);
  void setLight(std::size_t index, const Light& light); // 0-based
  void setAmbient(const Color& ambient);
  void setCamera(const CameraSpec& camera);
  void resetCamera(); // back to the scene file's camera
  // Re-reads the scene from disk and builds its hierarchy on another thread
  // (seconds for 10^6 primitives), while the window keeps showing and
  // refining the current scene; update() puts the new one in its place. On
  // errors the current scene stays and sceneErrors() lists the messages. A
  // reload asked for while one runs follows it (the files may have changed
  // again after they were read).
  void reload();
  bool reloading() const { return loading_.valid(); }
  void save(const std::string& path) { save_.start(path); }

  // Once a frame, before drawing: reloads when a scene file changed (checked
  // about twice a second), puts a reloaded scene in place, advances a save,
  // and copies the image if the render published anything. Returns true when
  // image() changed.
  bool update(Clock::time_point now = Clock::now());

  // The snapshot update() took: progress() was read before the image was
  // copied, so the image holds at least what progress() says.
  const SessionImage& image() const { return image_; }
  const SessionProgress& progress() const { return progress_; }
  bool snapshotCurrent() const { return !stale_; } // false between an edit and the next update()
  // The exposure the window applies now: 128 / avgmax of the samples so far.
  float exposure() const;

  RenderSettings settings() const { return session_->settings(); }
  const Scene& scene() const { return session_->scene(); }
  // Why the render stopped early (out of memory, say), or "".
  std::string renderFailure() const { return session_->failure(); }
  const std::string& scenePath() const { return options_.scenePath; }
  const std::vector<std::string>& sceneErrors() const { return sceneErrors_; }
  // What loading the current scene warned about (ignored OBJ/MTL fields, NFF
  // features without an equivalent).
  const std::vector<std::string>& sceneWarnings() const { return sceneWarnings_; }
  int successfulReloads() const { return successfulReloads_; }
  int failedReloads() const { return failedReloads_; }
  const SaveJob& saveJob() const { return save_; }

private:
  // A scene read and made ready to render on the loader thread.
  struct LoadedScene {
    std::unique_ptr<Scene> scene; // null when the files have errors
    std::unique_ptr<Accel> accel;
    std::vector<std::string> errors, warnings;
  };
  static LoadedScene load(const std::string& path, AccelKind accel);
  void apply(LoadedScene loaded);

  ViewOptions options_;
  CameraSpec fileCamera_;
  std::unique_ptr<RenderSession> session_;
  SaveJob save_;
  FileWatch watch_;
  Clock::time_point nextPoll_{};
  std::vector<std::string> sceneErrors_;
  std::vector<std::string> sceneWarnings_;
  std::future<LoadedScene> loading_; // valid while a reload runs
  bool reloadAgain_ = false;
  int successfulReloads_ = 0;
  int failedReloads_ = 0;
  SessionImage image_;
  SessionProgress progress_;
  bool stale_ = true;
};

} // namespace prism
