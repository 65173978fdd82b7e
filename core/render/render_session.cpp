#include "core/render/render_session.h"

#include "core/render/parallel.h"

#include <condition_variable>
#include <optional>
#include <stdexcept>
#include <string>

namespace prism {

namespace {

constexpr std::uint8_t kNoSample = 255;

using Clock = std::chrono::steady_clock;

} // namespace

struct RenderSession::Work {
  Work(int w, int h)
      : film(w, h), display(film.pixelCount(), Rgb(0.0f)),
        displayLevel(film.pixelCount(), kNoSample), displaySupersampled(film.pixelCount(), 0) {}

  // The samples of the final picture, written by the schedule's workers
  // without the lock: read only once the render is done, or when the next
  // generation starts from its pass 1 (with the workers joined).
  Film film;
  std::vector<Rgb> display;                      // each pixel shows its nearest sample so far
  std::vector<std::uint8_t> displayLevel;        // block size of the sample shown; kNoSample: stale
  std::vector<std::uint8_t> displaySupersampled; // the film's mask as far as published
  SessionPhase phase = SessionPhase::Coarse;
  int level = kPreviewCoarsestLevel;
  double sumMax = 0.0;       // of max(r,g,b) over traced pixel centres
  double levelsAvgmax = 0.0; // sumMax / pass1Pixels when the last level completed
  long long pass1Pixels = 0;
  double avgmax = 0.0;
  long long supersampled = 0;
  long long pass2TilesDone = 0;
  long long tileCount = 1;
  RayCounts counts;
  RayCounts pass1Counts; // the counts when pass 1 completed, kept by a pass-2-only restart
  Clock::time_point start = Clock::now();
  Clock::time_point end;      // when the render finished: elapsed time stops there
  Clock::time_point pass1End; // when pass 1 was complete (or kept from before)
  bool done = false;
  std::condition_variable doneChanged;
  std::string failure; // why the render stopped early, if it failed
};

RenderSession::RenderSession(Scene scene, const RenderSettings& settings, AccelKind accel)
    : scene_(std::make_unique<Scene>(std::move(scene))),
      textureGroups_(prism::textureGroups(*scene_)), accelKind_(accel), settings_(settings) {
  accel_ = makeAccel(*scene_, accelKind_);
  startWorkers(false);
}

RenderSession::~RenderSession() { stopWorkers(); }

void RenderSession::stopWorkers() {
  cancel_.store(true, std::memory_order_relaxed);
  if (driver_.joinable()) driver_.join();
  cancel_.store(false, std::memory_order_relaxed);
}

void RenderSession::startWorkers(bool keepPass1) {
  auto work = std::make_unique<Work>(settings_.width, settings_.height);
  {
    std::lock_guard lock(mutex_);
    if (work_ && work_->film.width == settings_.width && work_->film.height == settings_.height) {
      // Until the new samples arrive the window keeps showing the old picture
      // (marked stale), rather than flashing black on every drag of a light.
      work->display = work_->display;
      if (keepPass1) {
        work->film.centre = work_->film.centre; // the schedule starts pass 2 over from it
        work->display = work_->film.centre;
        std::fill(work->displayLevel.begin(), work->displayLevel.end(), std::uint8_t(1));
        work->sumMax = work_->sumMax;
        work->levelsAvgmax = work_->levelsAvgmax;
        work->pass1Pixels = work_->pass1Pixels;
        work->counts = work_->pass1Counts;
        work->pass1Counts = work_->pass1Counts;
        work->level = 1;
      }
    }
    work_ = std::move(work);
    version_.fetch_add(1, std::memory_order_release);
  }
  Work* current = work_.get(); // replaced only after this thread is joined
  driver_ = std::jthread([this, current, keepPass1] {
    // A failure (memory exhausted in a tile, say) ends this render with its
    // reason instead of the whole program, and whoever waits is woken.
    std::string failure;
    try {
      run(*current, keepPass1);
      return;
    } catch (const std::bad_alloc&) {
      failure = "out of memory";
    } catch (const std::exception& error) {
      failure = error.what();
    }
    {
      std::lock_guard lock(mutex_);
      current->failure = failure;
      current->done = true;
    }
    current->doneChanged.notify_all();
    version_.fetch_add(1, std::memory_order_release);
  });
}

void RenderSession::apply(const SessionEdit& edit) {
  if (edit.empty()) return;
  for (const auto& [index, light] : edit.lights)
    if (index >= scene_->lights.size())
      throw std::out_of_range("light " + std::to_string(index + 1) +
                              " does not exist: the scene has " +
                              std::to_string(scene_->lights.size()));
  for (const auto& [index, values] : edit.textures)
    if (index >= textureGroups_.size())
      throw std::out_of_range("texture " + std::to_string(index + 1) +
                              " does not exist: the scene has " +
                              std::to_string(textureGroups_.size()));
  // thresh, jitter and no-AA only steer pass 2: a finished pass 1 stays valid when
  // nothing else changes.
  const RenderSettings& old = settings_;
  const bool onlyPass2 =
      !edit.camera && !edit.ambient && !edit.fog && edit.lights.empty() && edit.textures.empty() &&
      (!edit.settings ||
       (old.width == edit.settings->width && old.height == edit.settings->height &&
        old.maxDepth == edit.settings->maxDepth && old.tileSize == edit.settings->tileSize &&
        old.bailout == edit.settings->bailout));
  bool pass1Complete;
  {
    std::lock_guard lock(mutex_);
    pass1Complete = work_->phase != SessionPhase::Coarse;
  }
  stopWorkers(); // the workers read all of these: change them only while none runs
  if (edit.settings) settings_ = *edit.settings;
  if (edit.camera) scene_->camera = *edit.camera;
  if (edit.ambient) scene_->ambient = *edit.ambient;
  if (edit.fog) scene_->fog = *edit.fog;
  for (const auto& [index, light] : edit.lights)
    scene_->lights[index] = light;
  for (const auto& [index, values] : edit.textures)
    for (const std::uint32_t m : textureGroups_[index].materials)
      setTextureValues(scene_->materials[m], values, textureGroups_[index]);
  ++restarts_;
  startWorkers(onlyPass2 && pass1Complete);
}

void RenderSession::setScene(std::unique_ptr<Scene> scene, std::unique_ptr<Accel> accel) {
  stopWorkers();
  accel_ = std::move(accel); // refers to *scene, so both change together
  scene_ = std::move(scene);
  textureGroups_ = prism::textureGroups(*scene_);
  ++restarts_;
  startWorkers(false);
}

RenderSettings RenderSession::settings() const { return settings_; }

std::string RenderSession::failure() const {
  std::lock_guard lock(mutex_);
  return work_->failure;
}

Scene RenderSession::sceneCopy() const { return *scene_; }

// Publishes what the schedule produces into a Work, under the session's lock,
// bumping the version each time so the viewer copies it.
class RenderSession::Publisher final : public ScheduleSink {
public:
  Publisher(RenderSession& session, Work& work) : session_(session), work_(work) {}

  void levelStarted(int level) override {
    publish([&] {
      work_.level = level;
      // Levels run one after another: every centre traced so far belongs
      // to a completed level.
      if (work_.pass1Pixels > 0) work_.levelsAvgmax = work_.sumMax / double(work_.pass1Pixels);
    });
  }

  void tileDone(const TileSamples& tile) override {
    publish([&] {
      if (tile.pass == 1)
        showCentres(tile);
      else
        showSupersampled(tile);
      work_.counts += tile.counts;
    });
  }

  void pilotDone(const RayCounts& counts) override {
    publish([&] { work_.counts += counts; });
  }

  void pass1Complete(double avgmax) override {
    publish([&] {
      work_.avgmax = avgmax;
      work_.levelsAvgmax = avgmax;
      work_.pass1End = Clock::now();
      work_.phase = SessionPhase::Antialias;
      work_.pass1Counts = work_.counts;
    });
  }

  void done(const RayCounts&) override { // the same counts, summed tile by tile
    publish([&] {
      work_.phase = SessionPhase::Done;
      work_.done = true;
      work_.end = Clock::now();
    });
    work_.doneChanged.notify_all();
  }

private:
  template <class Change> void publish(Change&& change) {
    std::lock_guard lock(session_.mutex_);
    change();
    session_.version_.fetch_add(1, std::memory_order_release);
  }

  // A coarse sample covers its block on the display until a finer one comes.
  void showCentres(const TileSamples& tile) {
    const int width = work_.film.width, height = work_.film.height, level = tile.level;
    for (const Sample& sample : tile.samples) {
      const Rgb& c = sample.radiance;
      work_.sumMax += double(std::max({c.r, c.g, c.b}));
      for (int by = sample.y; by < std::min(sample.y + level, height); ++by) {
        for (int bx = sample.x; bx < std::min(sample.x + level, width); ++bx) {
          const std::size_t j = work_.film.index(bx, by);
          if (work_.displayLevel[j] <= level) continue; // a finer sample is shown
          work_.display[j] = c;
          work_.displayLevel[j] = std::uint8_t(level);
        }
      }
    }
    work_.pass1Pixels += (long long)tile.samples.size();
  }

  void showSupersampled(const TileSamples& tile) {
    for (const Sample& sample : tile.samples) {
      const std::size_t i = work_.film.index(sample.x, sample.y);
      work_.display[i] = sample.radiance;
      work_.displaySupersampled[i] = 1;
    }
    work_.supersampled += (long long)tile.samples.size();
    ++work_.pass2TilesDone;
  }

  RenderSession& session_;
  Work& work_;
};

void RenderSession::run(Work& work, bool keepPass1) {
  const PassSchedule schedule(*scene_, *accel_, settings_, kPreviewCoarsestLevel);
  ThreadPoolExecutor executor(resolveThreadCount(settings_.threads),
                              ThreadPoolExecutor::Priority::Background);
  {
    std::lock_guard lock(mutex_);
    work.tileCount = schedule.tileCount();
  }
  Publisher publisher(*this, work);
  schedule.run(
      work.film, executor, publisher, [this] { return cancel_.load(std::memory_order_relaxed); },
      keepPass1 ? Pass1::Keep : Pass1::Trace);
}

bool RenderSession::copyImage(SessionImage& image) const {
  std::lock_guard lock(mutex_);
  const std::uint64_t now = version_.load(std::memory_order_acquire);
  if (image.version == now && image.width == work_->film.width &&
      image.height == work_->film.height)
    return false;
  image.width = work_->film.width;
  image.height = work_->film.height;
  image.radiance = work_->display;
  image.supersampled = work_->displaySupersampled;
  image.version = now;
  return true;
}

SessionProgress RenderSession::progress() const {
  std::lock_guard lock(mutex_);
  const Work& w = *work_;
  SessionProgress p;
  p.phase = w.phase;
  p.level = w.level;
  const double pixels = double(w.film.pixelCount());
  const double pass1 = pixels > 0 ? double(w.pass1Pixels) / pixels : 1.0;
  const double pass2 = double(w.pass2TilesDone) / double(std::max(1LL, w.tileCount));
  p.fraction = w.done ? 1.0 : 0.5 * pass1 + 0.5 * pass2;
  p.pass1Fraction = pass1;
  p.pass2Fraction = w.done ? 1.0 : pass2;
  if (w.phase != SessionPhase::Coarse)
    p.pass1Seconds = std::chrono::duration<double>(w.pass1End - w.start).count();
  p.pass1Pixels = w.pass1Pixels;
  p.supersampledPixels = w.supersampled;
  p.liveAvgmax = w.pass1Pixels > 0 ? w.sumMax / double(w.pass1Pixels) : 0.0;
  p.levelsAvgmax = w.levelsAvgmax;
  p.avgmax = w.phase == SessionPhase::Coarse ? p.liveAvgmax : w.avgmax;
  p.counts = w.counts;
  p.elapsedSeconds =
      std::chrono::duration<double>((w.done ? w.end : Clock::now()) - w.start).count();
  p.restarts = restarts_.load(std::memory_order_relaxed);
  return p;
}

bool RenderSession::finished() const {
  std::lock_guard lock(mutex_);
  return work_->done;
}

RenderResult RenderSession::waitForResult() {
  std::unique_lock lock(mutex_);
  work_->doneChanged.wait(lock, [this] { return work_->done; });
  if (!work_->failure.empty()) throw std::runtime_error("the render failed: " + work_->failure);
  RenderResult result;
  result.film = work_->film;
  result.avgmax = work_->avgmax;
  result.counts = work_->counts;
  result.supersampledPixels = work_->supersampled;
  return result;
}

} // namespace prism
