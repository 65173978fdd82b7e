// A progressive render that can be changed while it runs: what the previewer
// shows and edits. It owns the scene, the settings, the film and the worker
// threads, and runs the pass schedule (core/render/pass_schedule.h) with the
// preview levels: one pixel-centre sample per 8x8 block, then 4x4, 2x2 and
// 1x1, which together are pass 1; avgmax; pass 2. Every sample taken is a
// sample of the final picture, so the finished film is bit-for-bit what
// render() produces with the same scene and settings.
//
// Every edit cancels the work in flight (workers check between blocks, so this
// takes milliseconds), applies the change and restarts from the first level;
// results of cancelled work are never published. Finished tiles are published
// under a short lock with a version bump; a viewer polls version() once per
// frame and copies the buffers only when it changed. No GL here.
#pragma once

#include "core/accel/accel.h"
#include "core/render/film.h"
#include "core/render/pass_schedule.h"
#include "core/render/ray_counts.h"
#include "core/render/renderer.h"
#include "core/scene/scene.h"
#include "core/scene/texture_groups.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace prism {

enum class SessionPhase {
  Coarse,    // pass 1 in coarse-to-fine order; `level` says which block size
  Antialias, // pass 2
  Done,
};

// A consistent view of how far the render got, for live statistics.
struct SessionProgress {
  SessionPhase phase = SessionPhase::Coarse;
  int level = 8;              // block size of the coarse level in progress (8, 4, 2, 1)
  double fraction = 0.0;      // of the whole render (pass 1 and pass 2), 0..1
  double pass1Fraction = 0.0; // of pass 1's pixel centres traced, 0..1
  double pass2Fraction = 0.0; // of pass 2's tiles done, 0..1
  double pass1Seconds = 0.0;  // how long pass 1 took, once it is complete
  long long pass1Pixels = 0;  // pixel centres traced so far
  long long supersampledPixels = 0;
  double liveAvgmax = 0.0; // mean of max(r,g,b) over the pixel centres traced so far
  // The same over the coarse levels completed so far (0 before the first): a
  // uniform subsample of the image, so it does not drift with the order in
  // which a level's tiles finish, as liveAvgmax does.
  double levelsAvgmax = 0.0;
  double avgmax = 0.0; // pass 1's avgmax once pass 1 is complete, else liveAvgmax
  RayCounts counts;    // rays traced since the last restart
  double elapsedSeconds = 0.0;
  std::uint64_t restarts = 0; // how many times an edit restarted the render
};

// What the viewer draws: radiance filled so that every pixel shows the nearest
// sample taken so far (a coarse sample covers its whole block), plus the mask
// of supersampled pixels.
struct SessionImage {
  int width = 0;
  int height = 0;
  std::vector<Rgb> radiance;
  std::vector<std::uint8_t> supersampled;
  std::uint64_t version = 0;
};

// The one way to change the session: one value (a dragged light) or several
// at once with one restart (an undo that puts back a camera and two lights, a
// reload re-applying the user's edits). Unset members stay as they are; the
// initialisers let a designated initialiser name only what changes:
// apply({.ambient = Color(0.1)}).
struct SessionEdit {
  std::optional<RenderSettings> settings{};
  std::optional<CameraSpec> camera{};
  std::optional<Color> ambient{};
  // Density 0 is no fog: the picture is then the fog-free one, bit for bit
  // (each render generation's tracers decide from the scene whether to fog).
  std::optional<Fog> fog{};
  std::vector<std::pair<std::size_t, Light>> lights{}; // 0-based index, new value
  // A texture's scale and colours (a procedural texture's, an image's size
  // and tint, or both), on every material of its group: the index is into
  // RenderSession::textureGroups(). The file's values put back give the
  // file's picture, bit for bit.
  std::vector<std::pair<std::size_t, TextureValues>> textures{};

  bool empty() const {
    return !settings && !camera && !ambient && !fog && lights.empty() && textures.empty();
  }
};

class RenderSession {
public:
  // Starts rendering at once.
  RenderSession(Scene scene, const RenderSettings& settings, AccelKind accel = AccelKind::Bvh);
  ~RenderSession(); // cancels and joins the workers

  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Edits. Each one cancels the work in flight and restarts refinement, except
  // that a change of only `thresh` or `jitter` keeps a completed pass 1 and
  // redoes pass 2. An empty edit does nothing. Light indices are 0-based here
  // (users see them from 1), as are texture groups; one past the scene's
  // lights or groups throws std::out_of_range before anything is stopped or
  // changed.
  void apply(const SessionEdit& edit);
  // A reloaded scene: new geometry with its hierarchy, built by
  // makeAccel(*scene, accelKind()) beforehand (on another thread: for 10^6
  // primitives that takes a second). Its textures are grouped as it comes,
  // so it must come with the textures its files give (edit them after).
  void setScene(std::unique_ptr<Scene> scene, std::unique_ptr<Accel> accel);
  AccelKind accelKind() const { return accelKind_; }

  // The current state (copies; safe from any thread).
  RenderSettings settings() const;
  Scene sceneCopy() const;
  const std::vector<Light>& lights() const { return scene_->lights; } // UI thread only
  const Scene& scene() const { return *scene_; }                      // UI thread only
  // The scene's textured materials grouped as the scene came (constructor,
  // setScene): what SessionEdit::textures indexes. UI thread only.
  const std::vector<TextureGroup>& textureGroups() const { return textureGroups_; }
  // The hierarchy the workers trace with (read-only, so any thread may trace
  // with it too; replaced only by setScene, on the UI thread).
  const Accel& accel() const { return *accel_; }

  // Bumps whenever workers publish new samples or the session restarts.
  std::uint64_t version() const { return version_.load(std::memory_order_acquire); }
  // Copies the display buffers (only when `image.version` differs from version()).
  // Returns true if it copied.
  bool copyImage(SessionImage& image) const;
  SessionProgress progress() const;
  bool finished() const;

  // Why the current render stopped early (out of memory, say), or "".
  std::string failure() const;

  // Blocks until the render is complete, then returns the finished film: the
  // picture `prism render` would write (same samples, same avgmax). Throws
  // std::runtime_error if the render failed.
  RenderResult waitForResult();

private:
  struct Work;     // one render generation: its film, counters and display
  class Publisher; // the schedule's sink: publishes into a Work

  void stopWorkers();
  void startWorkers(bool keepPass1);
  void run(Work& work, bool keepPass1);

  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Accel> accel_;
  std::vector<TextureGroup> textureGroups_; // of scene_ as it came
  AccelKind accelKind_;
  RenderSettings settings_;

  mutable std::mutex mutex_; // guards work_'s published state
  std::unique_ptr<Work> work_;
  std::atomic<std::uint64_t> version_{1};
  std::atomic<std::uint64_t> restarts_{0};
  std::atomic<bool> cancel_{false};
  std::jthread driver_;
};

} // namespace prism
