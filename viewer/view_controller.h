// What the previewer does, apart from drawing: it owns the render session,
// applies the user's edits to it (each one restarts refinement) and keeps
// their undo history, reloads the scene when its files change (keeping the
// user's edits), saves the picture or the edited scene, and once a frame takes
// a consistent snapshot of the image and progress for the window. No GL, no
// ImGui: the panels, the mouse and scripts all go through these calls.
#pragma once

#include "file_watch.h"
#include "save_job.h"
#include "scene_edit.h"
#include "sweep_view.h"

#include "core/render/render_session.h"

#include <chrono>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace prism {

struct ViewOptions {
  std::string scenePath;
  RenderSettings settings;   // size, depth, threshold, jitter, threads
  bool sizeFromScene = true; // follow the scene's `resolution` on reload (no --size)
  AccelKind accel = AccelKind::Groups;
  std::string savePath; // the Save field's initial text
  // --eye/--lookat/--fov: the view to start from, as a camera edit over the
  // file's camera from the start: reloads keep it, Reset camera goes to the
  // file's camera.
  std::optional<CameraSpec> camera;
  // --sweep: the sweep table of the scene (`prism sweep`); "" for the one
  // beside it, NAME.sweep.csv. Another scene opened uses the one beside it.
  std::string sweepPath;
};

class ViewController {
public:
  using Clock = std::chrono::steady_clock;

  // `scene` as the files say it; `warnings`: what loading it reported
  // (formatted), shown with the scene.
  ViewController(Scene scene, const ViewOptions& options, std::vector<std::string> warnings = {});
  ~ViewController(); // waits for a reload or a scene save in progress

  // Edits. Every change of a value goes through apply(), with one of the
  // SceneEdit alternatives (viewer/scene_edit.h: SettingsEdit, LightEdit,
  // AmbientEdit, FogEdit, TextureEdit, CameraEdit, and the resets ResetLight,
  // ResetTexture, ResetCamera, RevertToFile), whoever makes it: a panel, the
  // mouse, a script. It cancels the work in flight and restarts refinement
  // (an edit that changes nothing does neither), and becomes one undo step.
  // A LightEdit or TextureEdit of a light or texture the scene does not have
  // throws std::out_of_range.
  void apply(const SceneEdit& edit);

  // Undo and redo (Ctrl+Z, Ctrl+Shift+Z) step through the states the edits
  // made, restarting the render like any edit; a new edit drops what could be
  // redone. At most kMaxUndoSteps steps are kept (the oldest go first).
  //
  // A continuous interaction (a mouse drag of the camera, a slider or a
  // value being dragged) is one step: call beginGesture() when it starts and
  // endGesture() when it ends; every edit in between changes the same step.
  // A gesture that ends where it started leaves no step. Outside a gesture
  // every edit is its own step.
  static constexpr std::size_t kMaxUndoSteps = 1000;
  bool undo(); // false when there is nothing to undo
  bool redo();
  bool canUndo() const { return at_ > 0; }
  bool canRedo() const { return at_ + 1 < states_.size(); }
  void beginGesture();
  void endGesture();
  bool inGesture() const { return gesture_; }

  // What the user changed (the render settings and the edited scene values),
  // and the scene values as the files say them: what the resets go back to.
  // Both follow reloads.
  const UserEdits& edits() const { return states_[at_]; }
  const FileValues& fileValues() const { return file_; }

  // What the reloads did with the user's edits, for the panel, until the
  // user's next edit (or undo, redo): `kept` lists the edited values the last
  // reload put over the re-read files ("camera", "ambient", "fog", "light 2",
  // "texture 1", by the texture's new number); `dropped` the edits of lights
  // and textures that a file no longer has ("light 5", "texture 2"), which
  // are gone from the undo history too. The render settings always stay and
  // are not listed.
  struct ReloadEdits {
    std::vector<std::string> kept;
    std::vector<std::string> dropped;
  };
  const ReloadEdits& keptEdits() const { return keptEdits_; }

  // Re-reads the scene from disk and builds its hierarchy on another thread
  // (seconds for 10^6 primitives), while the window keeps showing and
  // refining the current scene; update() puts the new one in its place. On
  // errors the current scene stays and sceneErrors() lists the messages. A
  // reload asked for while one runs follows it (the files may have changed
  // again after they were read).
  void reload();
  bool reloading() const { return loading_.valid(); }
  // Reads another scene (in the background, like a reload) and shows it in
  // place of this one: a fresh start, without this scene's edits and history.
  // The render settings stay; the image size follows the new scene's
  // `resolution` unless --size set it. If it has errors, this scene stays and
  // sceneErrors() says why.
  void open(const std::string& path);
  // Saves the final picture, as `prism render` writes it (the automatic
  // exposure unless `exposure` asks for the window's).
  void save(const std::string& path, const PictureExposure& exposure = {}) {
    save_.start(path, exposure);
  }

  // Save scene as: writes the scene shown (the files with the user's edits
  // over them) as one .sc file, on a helper thread; the window goes on. The
  // file is flattened: every included file's contents are written into it,
  // because the .sc language has no way to override the camera or a light
  // that an included file sets, so a file that kept the includes could not
  // hold the edits. (The writer keeps the push/pop groups.) A path that does
  // not end in .sc or cannot be written fails at once; every failure is a
  // state and a message, as for Save, never an exception.
  enum class SceneSaveState { Idle, Writing, Saved, Failed };
  void saveSceneAs(const std::string& path);
  SceneSaveState sceneSaveState() const { return sceneSave_.state; }
  bool sceneSaveBusy() const { return sceneSave_.state == SceneSaveState::Writing; }
  // "saved scene view.sc", or why not.
  const std::string& sceneSaveMessage() const { return sceneSave_.message; }

  // Once a frame, before drawing: reloads when a scene file changed (checked
  // about twice a second), puts a reloaded scene in place, advances the
  // saves, and copies the image if the render published anything. Returns
  // true when image() changed.
  bool update(Clock::time_point now = Clock::now());

  // The snapshot update() took: progress() was read before the image was
  // copied, so the image holds at least what progress() says.
  const SessionImage& image() const { return image_; }
  const SessionProgress& progress() const { return progress_; }
  bool snapshotCurrent() const { return !stale_; } // false between an edit and the next update()
  // The exposure the window applies now: 128 / avgmax of the samples so far.
  float exposure() const;

  RenderSettings settings() const { return session_->settings(); }
  // The ray tree of pixel (x, y)'s centre ray in the scene shown, as
  // `prism render --pixel X Y` prints it.
  std::string pixelRayTree(int x, int y) const;
  const Scene& scene() const { return session_->scene(); }
  // Why the render stopped early (out of memory, say), or "".
  std::string renderFailure() const { return session_->failure(); }
  const std::string& scenePath() const { return options_.scenePath; }
  const std::vector<std::string>& sceneErrors() const { return sceneErrors_; }
  // What loading the current scene warned about (ignored OBJ/MTL fields, NFF
  // features without an equivalent).
  const std::vector<std::string>& sceneWarnings() const { return sceneWarnings_; }
  // The sweep table of the scene shown (viewer/sweep_view.h), read with the
  // scene on every load, reload and open: none when there is no file beside
  // the scene, or why it could not be read. sweepStatus() places the current
  // settings in it.
  const LoadedSweep& sweep() const { return sweep_; }
  SweepStatus sweepStatus() const { return prism::sweepStatus(sweep_, settings()); }
  int successfulReloads() const { return successfulReloads_; }
  int failedReloads() const { return failedReloads_; }
  const SaveJob& saveJob() const { return save_; }

private:
  // A scene read and made ready to render on the loader thread.
  struct LoadedScene {
    std::unique_ptr<Scene> scene; // null when the files have errors
    std::unique_ptr<Accel> accel;
    std::vector<std::string> errors, warnings;
    LoadedSweep sweep;
  };
  struct SceneSave {
    SceneSaveState state = SceneSaveState::Idle;
    std::string path;
    std::string message;
    std::future<std::string> writing; // the error message, empty on success
  };

  static LoadedScene load(const std::string& path, AccelKind accel, const std::string& sweepPath,
                          bool sweepNamed);
  // The sweep table of the scene at `path`, and whether the user named it.
  std::pair<std::string, bool> sweepPathFor(const std::string& path) const;
  void startLoading(const std::string& path);
  void install(LoadedScene loaded);
  UserEdits& current() { return states_[at_]; }
  void record(UserEdits next); // a new state, or the gesture's step changed
  void show();                 // puts the current state into the session
  void fitHistoryTo(const Scene& scene, const std::vector<std::optional<std::size_t>>& textures);
  void pollSceneSave();

  ViewOptions options_;
  FileValues file_;
  std::unique_ptr<RenderSession> session_;
  // The undo history: states_[at_] is shown; those before it can be undone
  // back to, those after it redone.
  std::deque<UserEdits> states_;
  std::size_t at_ = 0;
  bool gesture_ = false;     // between beginGesture() and endGesture()
  bool gestureStep_ = false; // the open gesture has made its step (states_[at_])
  ReloadEdits keptEdits_;
  SaveJob save_;
  SceneSave sceneSave_;
  FileWatch watch_;
  Clock::time_point nextPoll_{};
  std::vector<std::string> sceneErrors_;
  std::vector<std::string> sceneWarnings_;
  std::string namedSweepScene_; // the scene --sweep was given for
  LoadedSweep sweep_;
  std::future<LoadedScene> loading_; // valid while a reload runs
  bool reloadAgain_ = false;
  std::optional<std::string> opening_;  // the scene being opened in place of this one
  std::optional<std::string> openNext_; // asked for while another reading was in flight
  int successfulReloads_ = 0;
  int failedReloads_ = 0;
  SessionImage image_;
  SessionProgress progress_;
  bool stale_ = true;
};

} // namespace prism
